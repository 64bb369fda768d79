// t2 hull3d from the command line: the documented output, every algorithm the same bytes,
// standard input, comments, file:line errors (exit 2), undefined hulls (exit 3), the picture.
#include <set>
#include <sstream>

#include "cli_testing.hpp"

namespace t2::testing {
namespace {

class Hull3dCli : public CliTest {};

// A unit cube's corners, a point inside, one on a face, a duplicate corner (index 10 = 0).
const char* kCube =
    "# a cube\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
    "0.5 0.5 0.5\n0.5 0.5 1   # on the top face\n\n0 0 0\n";

TEST_F(Hull3dCli, TrianglesOutwardAndTheSameForEveryAlgorithm) {
  write("cube.xyz", kCube);
  const Result q = t2("hull3d cube.xyz");
  ASSERT_EQ(q.status, 0) << q.err;
  // 6 squares, each the fan from its smallest corner, outward, sorted
  EXPECT_EQ(q.out,
            "0 1 5\n0 2 3\n0 3 1\n0 4 6\n0 5 4\n0 6 2\n1 3 7\n1 7 5\n2 6 7\n2 7 3\n4 5 7\n4 7 6\n");
  for (const char* a : {"incremental", "gift-wrap", "quickhull"}) {
    const Result r = t2(std::string("hull3d cube.xyz --algorithm ") + a);
    EXPECT_EQ(r.status, 0) << a << r.err;
    EXPECT_EQ(r.out, q.out) << a;
  }
  const Result f = t2("hull3d cube.xyz --facets");
  EXPECT_EQ(f.out, "0 1 5 4\n0 2 3 1\n0 4 6 2\n1 3 7 5\n2 6 7 3\n4 5 7 6\n");
}

TEST_F(Hull3dCli, StandardInputGeneratedInputAndThePicture) {
  Result r = t2("hull3d -", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "0 1 3\n0 2 1\n0 3 2\n1 2 3\n");
  ASSERT_EQ(t2("gen sphere --n 200 --seed 4 -o s.xyz").status, 0);
  r = t2("hull3d s.xyz --svg s.svg");
  EXPECT_EQ(r.status, 0) << r.err;
  std::set<int> vertices;  // a triangulated sphere: 2V - 4 triangles
  std::istringstream words(r.out);
  for (int v; words >> v;) vertices.insert(v);
  EXPECT_GT(vertices.size(), 100u);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2 * static_cast<long>(vertices.size()) - 4);
  EXPECT_TRUE(has(slurp(dir_ / "s.svg"), "<svg"));
  EXPECT_EQ(t2("hull3d s.xyz --algorithm gift-wrap").out, r.out);
}

TEST_F(Hull3dCli, BadInputAndUndefinedHulls) {
  Result r = t2("hull3d -", "0 0 0\n1 2\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "<stdin>:2")) << r.err;
  write("bad.xyz", "0 0 0\n1 0 nan\n");
  r = t2("hull3d bad.xyz --svg x.svg");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "bad.xyz:2")) << r.err;
  r = t2("hull3d -", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "coplanar")) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(t2("hull3d -", "").status, 3);
  EXPECT_EQ(t2("hull3d - --algorithm fast", "0 0 0\n").status, 2);
  EXPECT_EQ(t2("hull3d missing.xyz").status, 2);
  EXPECT_FALSE(has(slurp(dir_ / "x.svg"), "svg"));  // nothing written on bad input
}

}  // namespace
}  // namespace t2::testing
