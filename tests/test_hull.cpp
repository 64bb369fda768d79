// t2::convex_hull on front-only input against CGAL::convex_hull_2 (exact kernel), every
// algorithm, as cyclic sequences of points. CGAL is the oracle here only.
#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "cgal/cgal_oracle.hpp"
#include "hull_testing.hpp"
#include "t2/gen/generate.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using gen::Kind;
using testing::all_algorithms;
using testing::at;
using testing::same_cycle;

// CGAL's hull, as points of P (each CGAL vertex the first input point it equals).
std::vector<Point> cgal_hull(const std::vector<Point>& P) { return at(P, testing::cgal::hull_2(P)); }

void expect_like_cgal(const std::vector<Point>& P, const std::string& what) {
  const auto want = cgal_hull(P);
  for (HullAlgorithm a : all_algorithms()) {
    const auto got = at(P, convex_hull(P, a));
    EXPECT_TRUE(same_cycle(got, want)) << what << ", " << name(a) << ": got " << got.size() << " vertices "
                                       << testing::text(got) << "\nCGAL: " << testing::text(want);
  }
}

void check_kind(Kind k, std::size_t n, int seeds, bool cartesian = false) {
  for (int s = 1; s <= seeds; ++s) {
    gen::Options o;
    o.n = n;
    o.seed = static_cast<std::uint64_t>(s);
    o.cartesian = cartesian;
    expect_like_cgal(gen::points(k, o), std::string(gen::name(k)) + " seed " + std::to_string(s));
  }
}

const int kScale = testing::scale();

TEST(HullCgal, Uniform) { check_kind(Kind::uniform, 2000, 5 * kScale); }
TEST(HullCgal, DiskKuzminNormal) {
  check_kind(Kind::disk, 2000, 3 * kScale);
  check_kind(Kind::kuzmin, 2000, 3 * kScale);
  check_kind(Kind::normal, 2000, 3 * kScale);
}
TEST(HullCgal, OnCircleExactAndRounded) {
  check_kind(Kind::circle, 1000, 2 * kScale);        // every point a vertex (all exactly cocircular)
  check_kind(Kind::circle, 1000, 2 * kScale, true);  // rounded: nearly cocircular, a few inside
}
TEST(HullCgal, CollinearHeavy) {
  check_kind(Kind::segment, 500, 3 * kScale);
  check_kind(Kind::boundary, 1000, 3 * kScale);
  // Many points on a few lines, with random points between.
  for (int s = 1; s <= 3 * kScale; ++s) {
    gen::Options o;
    o.n = 300;
    o.seed = static_cast<std::uint64_t>(s);
    auto P = gen::points(Kind::boundary, o);
    auto Q = gen::points(Kind::segment, o);
    auto R = gen::points(Kind::uniform, o);
    P.insert(P.end(), Q.begin(), Q.end());
    P.insert(P.end(), R.begin(), R.begin() + 20);
    expect_like_cgal(P, "mixed collinear seed " + std::to_string(s));
  }
}
TEST(HullCgal, DuplicateHeavyAndGrid) {
  check_kind(Kind::duplicates, 2000, 3 * kScale);
  check_kind(Kind::grid, 2000, 3 * kScale);
  check_kind(Kind::grid, 30, 10 * kScale);  // 6×6 grids: most points collinear or repeated
}
// The bucket sort of plain points (chart_sort.hpp) against one std::sort in the chart's
// order: ranges that overflow, tiny ranges, many equal x, repeats; then the hulls against CGAL.
TEST(HullCgal, BucketSortOfPlainPoints) {
  std::mt19937_64 rng(7);
  const auto pick = [&](std::initializer_list<double> v) {
    return *(v.begin() + static_cast<std::ptrdiff_t>(rng() % v.size()));
  };
  std::uniform_real_distribution<double> u(-1, 1);
  for (double range : {1.0, 1.5e308, 1e-300, 4.9e-324}) {
    std::vector<Point> P;
    for (int i = 0; i < 3000; ++i) {
      const double x = i % 3 == 0 ? range * pick({-1, -0.5, 0, 0.25, 1}) : range * u(rng);
      P.push_back(Point::cartesian(x, i % 5 == 0 ? pick({-2, 0, 3}) : u(rng)));
    }
    for (int i = 0; i < 300; ++i) P.push_back(P[rng() % P.size()]);  // repeats
    const Chart chart = front_chart();
    const ChartOrder<HullTraits> order{chart};
    std::vector<std::size_t> idx(P.size());
    std::iota(idx.begin(), idx.end(), std::size_t{0});
    std::vector<Point> want = P;
    std::sort(want.begin(), want.end(), [&](const Point& a, const Point& b) { return order.less(a, b); });
    want.erase(std::unique(want.begin(), want.end()), want.end());
    const auto got = detail::sorted_in_chart<HullTraits>(P, idx, order);
    ASSERT_EQ(got.size(), want.size()) << "range " << range;
    for (std::size_t k = 0; k < got.size(); ++k) {
      ASSERT_TRUE(got[k].p == want[k]) << "range " << range << " at " << k;
      ASSERT_TRUE(P[got[k].i] == got[k].p);
    }
    expect_like_cgal(P, "bucket sort, range " + std::to_string(range));
  }
}
TEST(HullCgal, TinyInputs) {
  const Point a = Point::cartesian(1, 2), b = Point::cartesian(3, -1);
  EXPECT_TRUE(convex_hull(std::vector<Point>{}).empty());
  for (HullAlgorithm alg : all_algorithms()) {
    EXPECT_EQ(convex_hull(std::vector<Point>{a}, alg), (std::vector<std::size_t>{0}));
    EXPECT_EQ(convex_hull(std::vector<Point>{a, Point(2, 2, 4), a}, alg).size(), 1u);
    const auto two = at({a, b, a}, convex_hull(std::vector<Point>{a, b, a}, alg));
    EXPECT_TRUE(same_cycle(two, {a, b})) << name(alg);
  }
}

// A kernel that counts its orientation tests, and a trace that records the steps: the
// algorithms are templates on both, and give the same answer through them.
using testing::CountingTraits;

struct Recorder {
  std::vector<trace::Event> steps;
  std::vector<std::size_t> last;
  void operator()(const trace::Report& r) {
    steps.push_back(r.event);
    last.assign(r.chain.begin(), r.chain.end());
  }
};

TEST(HullCgal, KernelAndTraceParameters) {
  gen::Options o;
  o.n = 500;
  const auto P = gen::points(Kind::both_sides, o);
  const auto ref = convex_hull(P, HullAlgorithm::merge);
  for (HullAlgorithm a : all_algorithms()) {
    CountingTraits::calls = 0;
    Recorder rec;
    const auto h = convex_hull<CountingTraits>(P, a, rec);
    EXPECT_TRUE(same_cycle(at(P, h), at(P, ref))) << name(a);
    EXPECT_GT(CountingTraits::calls, 500) << name(a);
    EXPECT_FALSE(rec.steps.empty()) << name(a);
  }
  Recorder rec;  // Graham's last step leaves the hull on its stack
  const auto F = gen::points(Kind::uniform, o);
  const auto h = convex_hull(F, HullAlgorithm::graham, rec);
  EXPECT_EQ(rec.last, h);
}

// Quickhull divides at the point farthest from the chord, so on a circle (every point a
// vertex) both halves shrink and it makes O(n log n) orientation tests. Dividing at the nearest
// instead (the sign of the direction reversed, a bug chapter 16's counts found) still gives the
// right hull, through the fallbacks, but with about n² tests: 16 million here.
TEST(Hull, QuickhullDividesAtTheFarthestPoint) {
  gen::Options o;
  o.n = 4096;
  o.seed = 16;
  const auto P = gen::points(Kind::circle, o);
  CountingTraits::calls = 0;
  const auto h = convex_hull<CountingTraits>(P, HullAlgorithm::quickhull);
  const long calls = CountingTraits::calls;
  EXPECT_TRUE(same_cycle(at(P, h), at(P, convex_hull(P, HullAlgorithm::monotone))));
  EXPECT_GT(h.size(), 4000u);       // nearly every point is a vertex (a few are repeated)
  EXPECT_LT(calls, 8 * 4096 * 12);  // 8 n log2 n
}

}  // namespace
}  // namespace t2
