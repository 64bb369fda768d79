// t2 locate from the command line: a map with a face on Ω and one that crosses Ω, queries in
// faces, on edges, on vertices, on Ω and on the back, the three algorithms, and bad maps.
#include "cli_testing.hpp"

namespace t2::testing {
namespace {

class LocateCli : public CliTest {};

// Face 0: a front triangle. Face 1: beyond its long edge, between the ray +x from (4, 0) and
// the ray from (0, 4) towards Ω in direction (1, 1) (two vertices on Ω). Face 2:
// the triangle [1,−1,−1], [−1,1,2], [−1,−1,1], from the front through Ω (directions (−2β, γ))
// to the back. Edge (4,0) → (0,4) is shared by faces 0 and 1.
constexpr const char* kMap =
    "polygon\n 0 0\n 4 0\n 0 4\nend\n"
    "polygon\n 0 4\n 4 0\n 0 1 0\n 0 1 1\nend\n"
    "polygon\n 1 -1 -1\n -1 1 2\n -1 -1 1\nend\n";

TEST_F(LocateCli, FacesEdgesVerticesOmegaAndTheBack) {
  write("map.t2", kMap);
  write("q.t2",
        "1 1\n"        // face 0
        "3 3\n"        // face 1
        "2 0\n"        // on edge 0 of face 0
        "4 0\n"        // vertex 1 of faces 0 and 1: the least face
        "2 2\n"        // the shared edge: face 0's edge 1
        "0 2 1\n"      // Ω, inside face 1's edge along Ω
        "0 -1 1\n"     // Ω, inside face 2
        "1 -1 -1\n"    // vertex 0 of face 2
        "-1 0 0\n"     // the back origin: outside
        "0 1 -1\n"     // Ω, outside
        "0 -1 0\n");   // Ω: u + v, inside face 2's edge v → u
  const std::string want =
      "face 0\nface 1\nedge 0 0\nvertex 0 1\nedge 0 1\nedge 1 2\nface 2\nvertex 2 0\noutside\noutside\nedge 2 2\n";
  for (const char* a : {"walk", "trapezoid", "brute"}) {
    const Result r = t2(std::string("locate map.t2 q.t2 --algorithm ") + a);
    EXPECT_EQ(r.status, 0) << a << r.err;
    EXPECT_EQ(r.out, want) << a;
  }
  const Result r = t2("locate map.t2 q.t2 --svg out.svg");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(slurp(dir_ / "out.svg"), "<svg"));
}

// Two front squares (a vertical edge shared, a column of vertices at x = 2) and a back
// triangle: both charts are closed, so the trapezoidal maps answer all but the Ω query.
TEST_F(LocateCli, TrapezoidAnswersAsTheWalkOnBothSides) {
  write("map.t2",
        "polygon\n 0 0\n 2 0\n 2 2\n 0 2\nend\n"
        "polygon\n 2 0\n 4 0\n 4 2\n 2 2\nend\n"
        "polygon\n -1 0 0\n -1 0 -1\n -1 -1 0\nend\n");  // drawn at (0, 0), (0, 1), (1, 0)
  write("q.t2", "1 1\n2 1\n2 2\n2 3\n3 1\n4 1\n5 1\n2 -1\n-2 -1 0\n-4 -1 -1\n-1 0 0\n-1 -1 -1\n0 1 0\n");
  const std::string want =
      "face 0\nedge 0 1\nvertex 0 2\noutside\nface 1\nedge 1 1\noutside\noutside\n"
      "edge 2 2\nface 2\nvertex 2 0\noutside\noutside\n";
  for (const char* a : {"walk", "trapezoid", "brute"}) {
    const Result r = t2(std::string("locate map.t2 q.t2 --algorithm ") + a);
    EXPECT_EQ(r.status, 0) << a << r.err;
    EXPECT_EQ(r.out, want) << a;
  }
  // Two faces whose edges cross with no vertex in common: the walk takes the map (the
  // subdivision does not test it), the trapezoidal map refuses it.
  write("cross.t2", "polygon\n 0 0\n 4 0\n 0 4\nend\npolygon\n 2 -1\n 5 -2\n 6 3\nend\n");
  const Result r = t2("locate cross.t2 q.t2 --algorithm trapezoid");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "cross.t2:")) << r.err;
}

TEST_F(LocateCli, BadMapsExitTwoWithTheLineOfTheFace) {
  write("q.t2", "1 1\n");
  write("map.t2", kMap);
  // Each case: a file, its text, the command's arguments, and the file:line the error names.
  const struct {
    const char *name, *text, *args, *where;
  } cases[] = {
      // face 1 written clockwise: its edges repeat face 0's in the same direction
      {"cw.t2", "polygon\n 0 0\n 4 0\n 0 4\nend\n\npolygon\n 0 4\n 0 0\n 4 0\nend\n", "cw.t2 q.t2", "cw.t2:7:"},
      {"bow.t2", "polygon\n 0 0\n 4 4\n 4 0\n 0 4\nend\n", "bow.t2 q.t2", "bow.t2:1:"},  // not simple
      // two faces whose corners overlap at (0, 0)
      {"over.t2", "polygon\n 0 0\n 4 0\n 0 4\nend\npolygon\n 0 0\n 4 1\n 1 4\nend\n", "over.t2 q.t2", "over.t2:6:"},
      {"none.t2", "1 1\n", "none.t2 q.t2", "none.t2:1:"},             // no face
      {"badq.t2", "1 1 1 1\n", "map.t2 badq.t2", "badq.t2:1:"}};   // a bad query
  for (const auto& c : cases) {
    write(c.name, c.text);
    const Result r = t2(std::string("locate ") + c.args);
    EXPECT_EQ(r.status, 2) << c.name;
    EXPECT_TRUE(has(r.err, c.where)) << c.name << ": " << r.err;
  }
}

}  // namespace
}  // namespace t2::testing
