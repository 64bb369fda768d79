// The locus method of counting (range/locus.hpp) against the definition: for every rectangle,
// the number of points that `contains` (bbox.hpp) puts in it, one point at a time, exactly.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "t2/kernel/bbox.hpp"
#include "range_testing.hpp"
#include "t2/range/locus.hpp"

namespace {

using t2::ExactIsoRect;
using t2::ExactT1;
using t2::Integer;
using t2::Point;

// The count by definition, on the inputs of the range-search tests (range_testing.hpp): points
// on a grid with weights ±1, ±2, ±3, duplicates and points of Ω in all eight directions, and
// rectangles on either side, finite or reaching Ω.
std::size_t brute(const std::vector<Point>& P, const ExactIsoRect& r) { return range_testing::brute(P, r).size(); }
using range_testing::rect;
std::vector<Point> points(std::mt19937_64& rng, int n) { return range_testing::mixed_points(rng, n); }

TEST(Locus, CountsWhatContainsSeesOnBothSidesAndOnOmega) {
  std::mt19937_64 rng(13);
  int rects = 0, omega_hits = 0;
  for (int round = 0; round < 60; ++round) {
    const std::vector<Point> P = points(rng, 5 + round * 3);
    const t2::LocusCounter L(P);
    for (int q = 0; q < 200; ++q) {
      const ExactIsoRect r = rect(rng);
      const std::size_t want = brute(P, r);
      ASSERT_EQ(L.count(r), want) << t2::to_string(r) << " over " << P.size() << " points, round " << round;
      ++rects;
      if (is_infinite(r.dx()) || is_infinite(r.dy())) {
        std::size_t on_omega = 0;
        for (const Point& p : P) on_omega += p.w() == 0 && t2::contains(r, t2::to_exact(p));
        omega_hits += on_omega > 0;
      }
    }
  }
  EXPECT_EQ(rects, 12000);
  EXPECT_GT(omega_hits, 100) << "the random rectangles must reach points of Ω";
}

TEST(Locus, TheOmegaPointsOfAClosedQuadrantCount) {
  // The quadrant x ≥ 0, y ≥ 0 of the front holds the origin, the two axis directions of Ω that
  // bound it and the directions between them; its antipode on the back holds the others.
  const std::vector<Point> P = {Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(0, 1, 1), Point(0, -1, 1),
                                Point(0, -1, -1), Point(-1, 0, 0)};
  const t2::LocusCounter L(P);
  const ExactIsoRect front(t2::ExactPoint(1, 0, 0), ExactT1(0, 1), ExactT1(0, 1));
  EXPECT_EQ(L.count(front), 4u);  // [1,0,0], [0,1,0], [0,0,1], [0,1,1]
  const ExactIsoRect back(t2::ExactPoint(-1, 0, 0), ExactT1(0, 1), ExactT1(0, 1));
  EXPECT_EQ(L.count(back), 2u);  // [-1,0,0] and [0,-1,-1]: the back quadrant reaches Ω at (−, −)
  const ExactIsoRect strip(t2::ExactPoint(1, 0, 0), ExactT1(0, 1), ExactT1(1, 0));
  EXPECT_EQ(L.count(strip), 2u);  // the ray y = 0, x ≥ 0 and its end [0,1,0]
}

TEST(Locus, DoubleRectanglesAreConvertedExactly) {
  const std::vector<Point> P = {Point::cartesian(0.1, 0.2), Point::cartesian(0.3, 0.2), Point(-1, 0.1, 0.2)};
  const t2::LocusCounter L(P);
  // [0.1, 0.3] × [0.2, 0.2] as doubles: the corner is the double 0.1 and the extent 0.2 (as
  // doubles), and 0.1 + 0.2 > 0.3 in exact arithmetic, so both front points are inside.
  const t2::IsoRect r(Point::cartesian(0.1, 0.2), t2::T1(1, 0.2), t2::T1(1, 0));
  const ExactIsoRect e(t2::to_exact(r.a()), t2::to_exact(r.dx()), ExactT1(1, 0));
  EXPECT_EQ(L.count(r), brute(P, e));
  EXPECT_EQ(L.count(r), 2u);
}

TEST(Locus, StoresOneCountPerGridCorner) {
  std::vector<Point> P;
  for (int k = 0; k < 30; ++k) P.push_back(Point::cartesian(k, (k * 7) % 30));  // 30 distinct x and y
  P.push_back(Point(-1, 3, 4));
  const t2::LocusCounter L(P);
  EXPECT_EQ(L.cells(), 31u * 31u + 2u * 2u);
}

}  // namespace
