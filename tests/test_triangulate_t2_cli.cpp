// t2 triangulate on input with points behind or on Ω (Algorithm 9 on T², triangulate_t2.hpp):
// the library's triangles on the example file and generated input, and exit status 3 naming
// the points in the two undefined cases.
#include <filesystem>
#include <set>
#include <sstream>

#include "cli_testing.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/triangulation/triangulate.hpp"

namespace t2::testing {
namespace {

class TriangulateT2Cli : public CliTest {};

using Tri = std::array<Triangulation::Index, 3>;

std::set<Tri> parse(const std::string& out) {
  std::set<Tri> tris;
  std::istringstream in(out);
  Tri t{};
  while (in >> t[0] >> t[1] >> t[2]) tris.insert(t);
  return tris;
}

std::set<Tri> library(const std::string& file) {
  std::vector<Point> P;
  for (const auto& p : read_scene(file).points) P.push_back(p.point);
  const auto t = triangulate(P).finite_triangles();
  return {t.begin(), t.end()};
}

TEST_F(TriangulateT2Cli, ExampleAndGeneratedFiles) {
  const std::string example = (fs::path(T2_SOURCE_DIR) / "data" / "examples" / "both-sides-14.t2").string();
  Result r = t2("triangulate " + example);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse(r.out), library(example));
  EXPECT_EQ(parse(r.out).size(), 20u);  // 14 points, a hull of 6 edges: 2·14 − 2 − 6
  for (const char* kind : {"antipodal", "infinity", "both-sides"}) {
    ASSERT_EQ(t2(std::string("gen ") + kind + " --n 50 --seed 3 -o pts.t2").status, 0);
    const bool draw = std::string(kind) == "antipodal";  // a picture takes a second
    r = t2(std::string("triangulate pts.t2") + (draw ? " --svg t.svg --model both" : ""));
    ASSERT_EQ(r.status, 0) << kind << r.err;
    EXPECT_EQ(parse(r.out), library((dir_ / "pts.t2").string())) << kind;
    if (draw) {
      EXPECT_TRUE(has(slurp(dir_ / "t.svg"), "<svg")) << kind;
    }
  }
}

TEST_F(TriangulateT2Cli, UndefinedNamesThePoints) {
  Result r = t2("triangulate - --svg out.svg", "0 0\n2 0\n1 2\n-1 -1 0\n");
  EXPECT_EQ(r.status, 3);
  // which point waits for ever depends on the insertion order: ¬p3 lies inside p0 -> p1 and
  // ¬p1 inside p3 -> p0; the message names one of them with its edge
  EXPECT_TRUE(has(r.err, "antipode of p3 = [-1, -1, 0] lies inside the hull edge from p0 = [1, 0, 0] to p1") ||
              has(r.err, "antipode of p1 = [1, 2, 0] lies inside the hull edge from p3 = [-1, -1, 0] to p0"))
      << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(files().empty());
  r = t2("triangulate -", "0 1 0\n0 -1 1\n0 -1 -1\n");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "one great circle")) << r.err;
  // the antipode of a hull vertex: four faces, two of them lunes
  r = t2("triangulate -", "0 0\n2 0\n3 4\n-1 0 0\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse(r.out), (std::set<Tri>{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}));  // (w, z, ¬z), (z, u, ¬z)
}

}  // namespace
}  // namespace t2::testing
