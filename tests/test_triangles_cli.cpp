// t2 triangulate and t2 delaunay from the command line: the triangles of the library as index
// lines, both Delaunay algorithms, --infinite, stdin, duplicates and collinear input, the exit
// statuses of bad and undefined input, and the picture.
#include <set>
#include <sstream>

#include "cli_testing.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/triangulation/lawson.hpp"

namespace t2::testing {
namespace {

class TrianglesCli : public CliTest {};

using Tri = std::array<Triangulation::Index, 3>;

// The lines "i j k" of an output (finite triangles only).
std::vector<Tri> parse(const std::string& out) {
  std::vector<Tri> tris;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find("inf") != std::string::npos) continue;
    std::istringstream l(line);
    Tri t{};
    l >> t[0] >> t[1] >> t[2];
    tris.push_back(t);
  }
  return tris;
}

std::vector<Tri> sorted(std::vector<Tri> t) {
  std::sort(t.begin(), t.end());
  return t;
}

// A square with a point inside, a point inside an edge, a corner twice and a labelled corner.
const char* kSquare = "0 0\n2 0\n1 1\n1 0\n2 4 0\nlabel D 0 2\n2 2\n";

TEST_F(TrianglesCli, SquareByHand) {
  write("sq.t2", kSquare);
  // The Delaunay triangles: the centre p2 joined to the corners and to p3; p4 = p1 is merged.
  const std::string want = "0 2 5\n0 3 2\n1 2 3\n1 6 2\n2 6 5\n";
  for (const char* a : {"", " --algorithm incremental", " --algorithm divide", " --algorithm flip"}) {
    const Result r = t2(std::string("delaunay sq.t2") + a);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, want) << a;
    EXPECT_TRUE(has(r.err, "sq.t2:5: p4 equals p1 (line 2): merged")) << r.err;
  }
  const Result tri = t2("triangulate sq.t2");
  EXPECT_EQ(tri.status, 0) << tri.err;
  EXPECT_EQ(parse(tri.out).size(), 5u);  // 2n - h - 2 triangles: n = 6 vertices, h = 5 on the hull
  const Result inf = t2("delaunay sq.t2 --infinite");
  EXPECT_EQ(inf.out, want + "0 5 inf\n1 3 inf\n3 0 inf\n5 6 inf\n6 1 inf\n");  // hull edge a->b as "b a inf"
}

// The output is the library's answer on the scene's points, for generated files.
TEST_F(TrianglesCli, EqualsTheLibrary) {
  ASSERT_EQ(t2("gen normal --n 3000 --seed 5 -o pts.t2").status, 0);
  std::vector<Point> P;
  for (const auto& p : read_scene((dir_ / "pts.t2").string()).points) P.push_back(p.point);
  const auto inc = sorted(delaunay(P).finite_triangles());
  const Result a = t2("delaunay pts.t2"), b = t2("delaunay pts.t2 --algorithm flip"), c = t2("triangulate pts.t2");
  EXPECT_EQ(parse(a.out), inc);
  EXPECT_EQ(parse(b.out), inc);
  EXPECT_EQ(parse(t2("delaunay pts.t2 --algorithm divide").out), inc);
  EXPECT_EQ(parse(c.out), sorted(triangulate(P).finite_triangles()));
  EXPECT_NE(parse(c.out), inc);  // the sweep is not Delaunay
  // Every line counter-clockwise with its smallest index first.
  for (const Tri& t : parse(c.out)) {
    EXPECT_LT(t[0], t[1]);
    EXPECT_LT(t[0], t[2]);
    EXPECT_EQ(orient(P[t[0]], P[t[1]], P[t[2]]), POSITIVE);
  }
  // --infinite adds one line per hull edge.
  const Result i = t2("delaunay pts.t2 --infinite");
  EXPECT_EQ(std::count(i.out.begin(), i.out.end(), '\n') - std::count(a.out.begin(), a.out.end(), '\n'),
            std::ptrdiff_t(delaunay(P).hull_edges().size()));
}

TEST_F(TrianglesCli, StandardInputAndDegenerate) {
  Result r = t2("delaunay -", "0 0\n1 0\n0 1\n");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "0 1 2\n");
  r = t2("triangulate -", "0 1\n1 0\n0 0\n");
  EXPECT_EQ(r.out, "0 2 1\n");
  r = t2("delaunay -", "0 0\n1 1\n3 3\n");  // collinear: no triangle, said on stderr
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(has(r.err, "collinear")) << r.err;
  r = t2("triangulate - --infinite", "");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "");
}

TEST_F(TrianglesCli, BadAndUndefinedInput) {
  Result r = t2("delaunay -", "0 0\nsegment\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "<stdin>:2")) << r.err;
  r = t2("triangulate nope.t2");
  EXPECT_EQ(r.status, 2);
  r = t2("delaunay - --algorithm sweep", "0 0\n");
  EXPECT_EQ(r.status, 2);
  // A back point: Lawson and divide and conquer take front points only (t2 triangulate takes
  // T² input: test_triangulate_t2_cli.cpp).
  for (const char* c : {"delaunay --algorithm flip", "delaunay --algorithm divide"}) {
    r = t2(std::string(c) + " - --svg out.svg", "0 0\n1 0\n-1 -2 -3\n");
    EXPECT_EQ(r.status, 3) << c;
    EXPECT_TRUE(has(r.err, "undefined in T2: <stdin>: ")) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
  // Front points and points on Omega around it: the empty back side has no Delaunay
  // triangulation (delaunay_t2.hpp).
  r = t2("delaunay - --svg out.svg", "0 0\n1 0.25\n0 1 0\n0 -1 1\n0 -1 -1\n");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_TRUE(files().empty());  // no picture of an undefined answer
}

// Points on both sides, with and without a hull (antipodal pairs): the library's triangles,
// drawn without error (20 points: drawing both models costs more than the triangulation).
TEST_F(TrianglesCli, BothSidesOfT2) {
  for (const char* kind : {"both-sides", "antipodal"}) {
    ASSERT_EQ(t2(std::string("gen ") + kind + " --n 20 --seed 2 -o pts.t2").status, 0);
    std::vector<Point> P;
    for (const auto& p : read_scene((dir_ / "pts.t2").string()).points) P.push_back(p.point);
    const Result r = t2("delaunay pts.t2 --svg d.svg");
    ASSERT_EQ(r.status, 0) << kind << r.err;
    EXPECT_EQ(parse(r.out), sorted(delaunay(P).finite_triangles())) << kind;
    EXPECT_TRUE(has(slurp(dir_ / "d.svg"), "<svg"));
  }
}

TEST_F(TrianglesCli, Picture) {
  write("sq.t2", kSquare);
  std::set<std::string> pictures;
  for (const char* m : {"plane", "sphere", "both"}) {
    const Result r = t2(std::string("delaunay sq.t2 --svg d.svg --model ") + m);
    EXPECT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir_ / "d.svg");
    EXPECT_TRUE(has(svg, "<svg")) << m;
    pictures.insert(svg);
  }
  EXPECT_EQ(pictures.size(), 3u);  // three different pictures
  EXPECT_EQ(t2("delaunay sq.t2 --svg d.svg --model cube").status, 2);
}

}  // namespace
}  // namespace t2::testing
