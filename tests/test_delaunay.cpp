// t2::delaunay against CGAL's Delaunay_triangulation_2 (Epick) — the triangle sets must be
// equal — and against the exact certificates of delaunay_certificates.hpp, on uniform, normal,
// grid, circle, duplicate, collinear and "classroom" input; the result must not depend on the
// order of the input.
#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "cgal/cgal_delaunay.hpp"
#include "delaunay_certificates.hpp"
#include "delaunay_inputs.hpp"

namespace t2 {
namespace {

using testing::expect_delaunay;
using testing::scale;
using testing::Tri;
using testing::triangle_set;

void expect_cgal_equal(const std::vector<Point>& pts) {
  const Triangulation tr = delaunay(pts);
  expect_delaunay(tr, pts.size() <= 5000);
  testing::expect_cgal_triangles(tr, pts);
}

TEST(Delaunay, UniformEqualsCgal) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) expect_cgal_equal(testing::gen_points(gen::Kind::uniform, 3000 * scale(), seed));
}

TEST(Delaunay, NormalEqualsCgal) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) expect_cgal_equal(testing::gen_points(gen::Kind::normal, 3000 * scale(), seed, 1));
}

TEST(Delaunay, SmallSetsEqualCgal) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed)
    expect_cgal_equal(testing::gen_points(gen::Kind::uniform, 3 + seed % 20, seed));
}

// CGAL breaks cocircular ties with the same symbolic perturbation, so even the degenerate
// inputs must give the same triangle set.
TEST(Delaunay, GridEqualsCgal) {
  for (std::size_t n : {4, 9, 10, 100, 2500}) expect_cgal_equal(testing::grid_points(n * scale(), n));
}

TEST(Delaunay, CocircularLatticeEqualsCgal) {
  expect_cgal_equal(testing::lattice_circle_points(0, 1));
  expect_cgal_equal(testing::lattice_circle_points(200, 2));
}

TEST(Delaunay, RoundedCircleEqualsCgal) { expect_cgal_equal(testing::gen_points(gen::Kind::circle, 1000 * scale(), 3)); }

TEST(Delaunay, ClassroomExample) {
  const auto pts = testing::classroom_points(16);
  expect_cgal_equal(pts);
}

TEST(Delaunay, ClusteredEqualsCgal) { expect_cgal_equal(testing::gen_points(gen::Kind::normal, 3000 * scale(), 5, 32)); }

// The same point set in another order gives the same triangles (renamed).
void expect_order_independent(const std::vector<Point>& pts, std::uint64_t seed) {
  std::vector<Triangulation::Index> perm(pts.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(seed));
  std::vector<Point> shuffled;
  for (auto k : perm) shuffled.push_back(pts[k]);
  const auto a = triangle_set(delaunay(pts));
  std::vector<Tri> b;
  for (const Tri& t : delaunay(shuffled).finite_triangles()) b.push_back(testing::renamed(t, perm));
  std::sort(b.begin(), b.end());
  EXPECT_TRUE(a == b);
}

TEST(Delaunay, CocircularIndependentOfOrder) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    expect_order_independent(testing::grid_points(400, seed), seed);
    expect_order_independent(testing::lattice_circle_points(50, seed), seed);
  }
}

TEST(Delaunay, DuplicatesMergedAndReported) {
  auto pts = testing::gen_points(gen::Kind::uniform, 500, 7);
  const std::size_t n = pts.size();
  std::mt19937_64 rng(8);
  for (std::size_t k = 0; k < 300; ++k) pts.push_back(pts[rng() % pts.size()]);
  pts.push_back(Point(2, 2 * pts[0].x(), 2 * pts[0].y()));  // the same point, scaled
  const Triangulation tr = delaunay(pts);
  expect_delaunay(tr);
  EXPECT_EQ(tr.duplicates().size(), pts.size() - n);
  // Without the duplicates: the triangles of the first n points.
  const std::vector<Point> first(pts.begin(), pts.begin() + n);
  EXPECT_TRUE(triangle_set(tr) == triangle_set(delaunay(first)));
  pts.pop_back();  // CGAL gets the same points, all with w = 1
  expect_cgal_equal(pts);
}

TEST(Delaunay, DuplicatesOnGrid) {
  auto pts = testing::grid_points(100, 1);
  auto more = testing::grid_points(100, 2);
  pts.insert(pts.end(), more.begin(), more.end());
  const Triangulation tr = delaunay(pts);
  expect_delaunay(tr);
  EXPECT_EQ(tr.duplicates().size(), 100u);
  for (auto [d, k] : tr.duplicates()) EXPECT_GE(d, 100u);
}

TEST(Delaunay, CollinearGivesNoTriangle) {
  std::vector<Point> pts;
  for (int k = 0; k < 50; ++k) pts.push_back(Point::cartesian(k % 7 * 3.0 + 1, k % 7 * 6.0 - 2));
  const Triangulation tr = delaunay(pts);
  EXPECT_EQ(tr.dimension(), 1);
  EXPECT_TRUE(tr.finite_triangles().empty());
  EXPECT_TRUE(tr.hull_edges().empty());
  EXPECT_EQ(tr.duplicates().size(), 43u);
  expect_delaunay(tr);
  // One point off the line: a fan of 6 triangles.
  pts.push_back(Point::cartesian(0, 5));
  const Triangulation fan = delaunay(pts);
  expect_delaunay(fan);
  EXPECT_EQ(fan.finite_triangles().size(), 6u);
}

TEST(Delaunay, DegenerateSizes) {
  EXPECT_EQ(delaunay(std::vector<Point>{}).dimension(), -1);
  const Triangulation one = delaunay(std::vector<Point>{Point::cartesian(1, 2), Point::cartesian(1, 2)});
  EXPECT_EQ(one.dimension(), 0);
  EXPECT_EQ(one.duplicates().size(), 1u);
  const std::vector<Point> tri = {Point::cartesian(0, 0), Point::cartesian(0, 1), Point::cartesian(1, 0)};
  const Triangulation t = delaunay(std::span<const Point>(tri));
  expect_delaunay(t);
  EXPECT_EQ(triangle_set(t), (std::vector<Tri>{{0, 2, 1}}));
}

TEST(Delaunay, CollinearThenCocircular) {
  // Many points on the hull line y = 0 and the x axis, with a square around: hull with collinear
  // points, edges split on the hull.
  std::vector<Point> pts;
  for (int k = -20; k <= 20; ++k) pts.push_back(Point::cartesian(k, 0));
  for (int k = -20; k <= 20; ++k) pts.push_back(Point::cartesian(k, 20));
  for (int k = 1; k < 20; ++k) pts.push_back(Point::cartesian(-20, k));
  for (int k = 1; k < 20; ++k) pts.push_back(Point::cartesian(0, k));
  expect_cgal_equal(pts);
}

// gen's exact degeneracies: points exactly on the boundary of a square (collinear hull points),
// a grid drawn with repetition, duplicates written with scales 1, 2, 4 (w != 1), exactly
// collinear points, points exactly on the unit circle as [c, a, b].
TEST(Delaunay, GenDegenerateKinds) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    expect_cgal_equal(testing::gen_points(gen::Kind::boundary, 400, seed));
    expect_delaunay(delaunay(testing::gen_points(gen::Kind::grid, 2000, seed)));
    const Triangulation tr = delaunay(testing::gen_points(gen::Kind::duplicates, 800, seed));
    expect_delaunay(tr);
    EXPECT_GE(tr.duplicates().size(), 700u);
    const Triangulation line = delaunay(testing::gen_points(gen::Kind::segment, 100, seed));
    EXPECT_EQ(line.dimension(), 1);
    expect_delaunay(line);
    gen::Options o;
    o.n = 300;
    o.seed = seed;
    const auto circle = gen::points(gen::Kind::circle, o);  // exact [c, a, b]: cocircular
    expect_delaunay(delaunay(circle));
    expect_order_independent(circle, seed);
  }
}

// Input not all in front takes the T² construction (test_delaunay_t2.cpp, with points on Ω
// test_delaunay_omega.cpp).
TEST(Delaunay, PointsNotInFront) {
  const std::vector<Point> pts = {Point::cartesian(0, 0), Point(-1, 0, 1), Point::cartesian(1, 0)};
  EXPECT_EQ(delaunay(pts).validate(), "");
  const std::vector<Point> inf = {Point::cartesian(0, 0), Point::at_infinity(0, 1), Point::cartesian(1, 0)};
  EXPECT_EQ(delaunay(inf).validate(), "");
}

// The hook sees every insertion and every flip, and traits of one's own still apply.
struct CountingHook {
  std::size_t inserted_count = 0, flips = 0;
  void operator()(const trace::Report& r) {
    inserted_count += r.event == trace::Event::insert;
    flips += r.event == trace::Event::flip;
  }
};

TEST(Delaunay, TraitsAndTraceHook) {
  CountingHook k;
  const auto pts = testing::gen_points(gen::Kind::uniform, 1000, 11);
  struct Ref {
    static Sign orient(const Point& p, const Point& q, const Point& r) { return t2::orient(p, q, r); }
    static Sign in_circle(const Point& a, const Point& b, const Point& c, const Point& d) {
      return t2::in_circle(a, b, c, d);
    }
    static Sign compare_xy(const Point& p, const Point& q) { return t2::compare_xy(p, q); }
  };
  const Triangulation tr = delaunay_with(pts, Ref{}, k);
  EXPECT_EQ(k.inserted_count, pts.size() - 3);  // the first triangle is not an insertion
  EXPECT_GT(k.flips, pts.size());               // about 3 flips per point on random input
  EXPECT_TRUE(triangle_set(tr) == triangle_set(delaunay(pts)));
}

// delaunay(std::vector<Point>&&) takes the vector over and moves its copy back in place: the same
// result as from a caller's points, on general, duplicated, collinear and T² input.
TEST(Delaunay, TakenVectorGivesTheSameResult) {
  auto dup = testing::grid_points(300, 4);
  for (std::size_t k = 0; k < 100; ++k) dup.push_back(dup[(k * 37) % dup.size()]);
  std::vector<Point> line;
  for (int k = 0; k < 20; ++k) line.push_back(Point::cartesian((k * 7) % 20, (k * 7) % 20));
  line.push_back(line[3]);
  auto sides = testing::gen_points(gen::Kind::uniform, 200, 9);
  for (std::size_t k = 0; k < sides.size(); k += 3) sides[k] = antipode(sides[k]);
  for (const auto& pts : {testing::gen_points(gen::Kind::uniform, 2000, 11), dup, line, sides}) {
    const Triangulation kept = delaunay(pts);
    const Triangulation taken = delaunay(std::vector<Point>(pts));
    EXPECT_EQ(taken.dimension(), kept.dimension());
    EXPECT_TRUE(taken.points() == pts);
    EXPECT_TRUE(triangle_set(taken) == triangle_set(kept));
    EXPECT_EQ(taken.duplicates(), kept.duplicates());
    EXPECT_TRUE(taken.valid()) << taken.validate();
  }
}

// unpermute (spatial_sort.hpp) against its definition, points[order[m]] = old points[m], on
// random and BRIO orders of every size around its eight ranges (n < 8, n = 8k ± 1, large).
TEST(Delaunay, UnpermuteRestoresTheInputOrder) {
  std::mt19937 rng(5);
  for (std::size_t n : {0, 1, 2, 3, 7, 8, 9, 15, 16, 17, 63, 100, 1001, 40000}) {
    std::vector<Point> pts;
    for (std::size_t k = 0; k < n; ++k) pts.push_back(Point::cartesian(double(k), double((k * 7919) % 101)));
    std::vector<std::uint32_t> shuffled(n);
    std::iota(shuffled.begin(), shuffled.end(), 0u);
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    for (const auto& order : {shuffled, spatial_order(pts)}) {
      std::vector<Point> moved;
      for (std::uint32_t k : order) moved.push_back(pts[k]);
      std::vector<std::uint32_t> scratch = order;
      unpermute(moved, scratch);
      EXPECT_TRUE(moved == pts) << "n = " << n;
    }
  }
}

// The Hilbert index of spatial_sort.hpp against the curve's defining property: on the 2^b × 2^b
// grid it numbers every cell once, and cells with consecutive numbers share a side. And
// spatial_order is a permutation.
TEST(Delaunay, HilbertIndexWalksTheGridCellToCell) {
  for (int b = 1; b <= 6; ++b) {
    const std::uint32_t side = 1u << b;
    std::vector<std::pair<int, int>> cell(std::size_t(side) * side, {-1, -1});
    for (std::uint32_t x = 0; x < side; ++x)
      for (std::uint32_t y = 0; y < side; ++y) {
        const std::uint64_t d = detail::hilbert_index(x, y, b);
        ASSERT_LT(d, cell.size());
        EXPECT_EQ(cell[d].first, -1) << "two cells numbered " << d;
        cell[d] = {int(x), int(y)};
      }
    for (std::size_t d = 1; d < cell.size(); ++d)
      EXPECT_EQ(std::abs(cell[d].first - cell[d - 1].first) + std::abs(cell[d].second - cell[d - 1].second), 1)
          << "b = " << b << ", d = " << d;
  }
  for (std::size_t n : {0, 1, 17, 5000}) {
    auto order = spatial_order(testing::gen_points(gen::Kind::normal, n, 3, 4));
    std::sort(order.begin(), order.end());
    for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(order[k], k);
  }
}

}  // namespace
}  // namespace t2
