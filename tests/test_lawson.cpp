// t2::triangulate (the sweep) and Lawson's flip algorithm (t2/triangulation/lawson.hpp): the
// sweep gives a valid triangulation of every point (exact certificates: structure, every point a
// vertex or a duplicate, the triangles tile the hull exactly); Lawson's result passes every
// Delaunay certificate and is the same triangle set as t2::delaunay on uniform, clustered,
// cocircular, duplicate and "classroom" input; the legality test and the flip count on small
// cases worked by hand.
#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "delaunay_certificates.hpp"
#include "delaunay_inputs.hpp"
#include "t2/triangulation/lawson.hpp"

namespace t2 {
namespace {

using testing::area2;
using testing::expect_delaunay;
using testing::scale;
using testing::Tri;
using testing::triangle_set;

// A triangulation of the points, whatever it is: valid, every point a vertex or a duplicate of
// an equal point of smaller index, the hull edges convex with every point left of or on them,
// and the finite triangles' exact areas summing to the hull's.
void expect_triangulation(const Triangulation& tr) {
  ASSERT_EQ(tr.validate(), "");
  const auto& pts = tr.points();
  std::vector<char> vertex(pts.size(), 0), dropped(pts.size(), 0);
  for (const Tri& t : tr.finite_triangles())
    for (auto v : t) vertex[v] = 1;
  for (auto [d, k] : tr.duplicates()) {
    EXPECT_LT(k, d);
    EXPECT_TRUE(pts[d] == pts[k]);
    dropped[d] = 1;
  }
  if (tr.dimension() < 2) return;
  for (std::size_t v = 0; v < pts.size(); ++v) EXPECT_NE(vertex[v] != 0, dropped[v] != 0) << "point " << v;
  const auto hull = tr.hull_edges();
  Rational hull_area = 0, sum = 0;
  for (auto [a, b] : hull) {
    hull_area += area2(pts[hull.front().first], pts[a], pts[b]);
    for (const Point& p : pts) ASSERT_NE(orient(pts[a], pts[b], p), NEGATIVE);
  }
  for (const Tri& t : tr.finite_triangles()) sum += area2(pts[t[0]], pts[t[1]], pts[t[2]]);
  EXPECT_EQ(sum, hull_area);
}

// Lawson from the sweep is a Delaunay triangulation and the same one as t2::delaunay.
std::size_t expect_lawson_equals_incremental(const std::vector<Point>& pts) {
  Triangulation tr = triangulate(pts);
  expect_triangulation(tr);
  const std::size_t flips = flip_to_delaunay(tr);
  expect_delaunay(tr, pts.size() <= 3000);
  EXPECT_TRUE(triangle_set(tr) == triangle_set(delaunay(pts))) << "Lawson and the incremental algorithm differ";
  EXPECT_EQ(tr.duplicates(), delaunay(pts).duplicates());
  return flips;
}

TEST(Lawson, UniformEqualsIncremental) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed)
    EXPECT_GT(expect_lawson_equals_incremental(testing::gen_points(gen::Kind::uniform, 3000 * scale(), seed)), 0u);
}

TEST(Lawson, SmallSetsEqualIncremental) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed)
    expect_lawson_equals_incremental(testing::gen_points(gen::Kind::uniform, 3 + seed % 20, seed));
}

TEST(Lawson, ClusteredAndKuzminEqualIncremental) {
  expect_lawson_equals_incremental(testing::gen_points(gen::Kind::normal, 2000 * scale(), 5, 32));
  expect_lawson_equals_incremental(testing::gen_points(gen::Kind::kuzmin, 2000 * scale(), 6));
}

// The perturbation decides cocircular ties in both algorithms alike.
TEST(Lawson, CocircularAndGridEqualIncremental) {
  for (std::size_t n : {4, 9, 10, 100, 900}) expect_lawson_equals_incremental(testing::grid_points(n, n));
  expect_lawson_equals_incremental(testing::lattice_circle_points(0, 1));
  expect_lawson_equals_incremental(testing::lattice_circle_points(200, 2));
  gen::Options o;
  o.n = 300;
  o.seed = 3;
  expect_lawson_equals_incremental(gen::points(gen::Kind::circle, o));  // exact [c, a, b]
  expect_lawson_equals_incremental(testing::classroom_points(8));
}

TEST(Lawson, DegenerateKindsEqualIncremental) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed)
    for (gen::Kind k : {gen::Kind::boundary, gen::Kind::grid, gen::Kind::duplicates, gen::Kind::segment})
      expect_lawson_equals_incremental(testing::gen_points(k, 500, seed));
}

// The sweep depends on the point set only: a permutation of the input renames the triangles.
TEST(Triangulate, IndependentOfOrder) {
  auto pts = testing::gen_points(gen::Kind::uniform, 1000, 9);
  std::vector<Triangulation::Index> perm(pts.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(3));
  std::vector<Triangulation::Index> back(pts.size());  // shuffled index -> original index
  for (std::size_t k = 0; k < pts.size(); ++k) back[perm[k]] = static_cast<Triangulation::Index>(k);
  std::vector<Point> shuffled;
  for (std::size_t j = 0; j < pts.size(); ++j) shuffled.push_back(pts[back[j]]);
  std::vector<Tri> b;
  for (const Tri& t : triangulate(shuffled).finite_triangles()) b.push_back(testing::renamed(t, back));
  std::sort(b.begin(), b.end());
  EXPECT_TRUE(triangle_set(triangulate(pts)) == b);
}

// Collinear points first (they go into the first edge), on both orientations of the first
// triangle; collinear hull points; fewer than three distinct points.
TEST(Triangulate, CollinearStartsAndSmallSets) {
  for (double y : {1.0, -1.0}) {
    std::vector<Point> pts;
    for (int k = 0; k < 9; ++k) pts.push_back(Point::cartesian(0, k));  // sorted first, on x = 0
    pts.push_back(Point::cartesian(3, y));
    pts.push_back(Point::cartesian(4, 2 * y));
    pts.push_back(Point::cartesian(5, 3 * y));  // on the line of the last two: a collinear hull edge
    const Triangulation tr = triangulate(pts);
    expect_triangulation(tr);
    EXPECT_EQ(tr.finite_triangles().size(), 2 * pts.size() - tr.hull_edges().size() - 2);
  }
  EXPECT_EQ(triangulate(std::vector<Point>{}).dimension(), -1);
  EXPECT_EQ(triangulate(std::vector<Point>{Point::cartesian(1, 1), Point(2, 2, 2)}).dimension(), 0);
  const Triangulation line = triangulate(testing::gen_points(gen::Kind::segment, 50, 1));
  EXPECT_EQ(line.dimension(), 1);
  EXPECT_TRUE(line.finite_triangles().empty());
  // a back point goes to Algorithm 9 on T² (test_triangulate_t2.cpp): here one triangle
  const Triangulation t2 =
      triangulate(std::vector<Point>{Point::cartesian(0, 0), Point(-1, 0, 1), Point::cartesian(1, 0)});
  EXPECT_EQ(t2.finite_triangles().size(), 1u);
}

// A convex quadrilateral worked by hand: A(0,0), B(1,-1), C(1,1), D(1.5,0). The sweep takes
// them in this order and joins B C; D lies inside the circle of A, B, C (centre (1, 0), radius
// 1), so B C is illegal and one flip makes A D.
TEST(Lawson, OneFlipByHand) {
  const std::vector<Point> pts = {Point::cartesian(0, 0), Point::cartesian(1, -1), Point::cartesian(1, 1),
                                  Point::cartesian(1.5, 0)};
  Triangulation tr = triangulate(pts);
  EXPECT_EQ(triangle_set(tr), (std::vector<Tri>{{0, 1, 2}, {1, 3, 2}}));
  int illegal = 0;
  for (Triangulation::Index t = 0; t < tr.size(); ++t)
    for (int i = 0; i < 3; ++i) illegal += !is_legal(tr, t, i);
  EXPECT_EQ(illegal, 2);  // the edge B C, seen from both of its triangles
  EXPECT_EQ(flip_to_delaunay(tr), 1u);
  EXPECT_EQ(triangle_set(tr), (std::vector<Tri>{{0, 1, 3}, {0, 3, 2}}));
  for (Triangulation::Index t = 0; t < tr.size(); ++t)
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(is_legal(tr, t, i));
  EXPECT_EQ(flip_to_delaunay(tr), 0u);  // nothing left to do
  // With D at (3, 0), outside the circle, B C is legal and the sweep is already Delaunay.
  Triangulation far = triangulate(std::vector<Point>{pts[0], pts[1], pts[2], Point::cartesian(3, 0)});
  EXPECT_EQ(flip_to_delaunay(far), 0u);
}

// Two rows, y = 0 and far above (slightly tilted), n points each: the sweep joins neighbours
// across the rows in a zigzag that Delaunay replaces almost entirely — Θ(n²) flips, the worst
// case of the file comment — and never more than the C(N, 2) of its proof (N = 2n points).
TEST(Lawson, TwoRowsNeedQuadraticFlips) {
  for (int n : {20, 40, 80}) {
    std::vector<Point> pts;
    for (int k = 0; k < n; ++k) {
      pts.push_back(Point::cartesian(k, 0));
      pts.push_back(Point::cartesian(k + 0.5, 1000.0 * n - k));
    }
    const std::size_t flips = expect_lawson_equals_incremental(pts), N = pts.size();
    EXPECT_GE(flips, std::size_t(n) * n / 4) << n;
    EXPECT_LE(flips, N * (N - 1) / 2) << n;
  }
}

}  // namespace
}  // namespace t2
