// The merge of the hemisphere hulls (merge.hpp, the bridge walk): its orientation tests grow
// linearly with the hull sizes on points of a circle on both sides of T² (the old insertion
// made h₁h₂ of them), and its answer agrees with an exact brute force on random small sets all
// over T², degenerate on purpose (collinear, repeated, on Ω, antipodal).
#include <gtest/gtest.h>

#include <random>

#include "hull_testing.hpp"
#include "t2/gen/generate.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::at;
using testing::same_cycle;

const int kScale = testing::scale();

// The hull traits with every orientation test counted (as chapter 16 counts them).
struct CountingOrient : HullTraits {
  static inline std::size_t calls = 0;
  static Sign orient(const Point& p, const Point& q, const Point& r) {
    ++calls;
    return HullTraits::orient(p, q, r);
  }
};

// n Pythagorean points [c, a, b] of the unit circle moved by [w, x, y] ↦ [x, −w, y]
// (determinant 1, so hulls and orientations are kept): the points with a > 0 stay in front,
// those with a < 0 go behind, those with a = 0 go to Ω. Every distinct point is a hull vertex.
std::vector<Point> circle_both_sides(std::size_t n) {
  gen::Options o;
  o.n = n;
  o.seed = 28;
  std::vector<Point> P;
  for (const Point& p : gen::points(gen::Kind::circle, o)) P.emplace_back(p.x(), -p.w(), p.y());
  return P;
}

// The hull of the points P[i] of one lexicographic half, in input indices (any algorithm will
// do: the count below is the merge's alone).
std::vector<std::size_t> half_hull(const std::vector<Point>& P, bool positive) {
  std::vector<Point> Q;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < P.size(); ++i)
    if ((detail::lex_sign(P[i]) > 0) == positive) Q.push_back(P[i]), index.push_back(i);
  std::vector<std::size_t> h;
  for (std::size_t k : convex_hull(Q)) h.push_back(index[k]);
  return h;
}

TEST(HullMerge, OrientationTestsGrowLinearlyOnACircleOnBothSides) {
  double before = 0;
  for (std::size_t n = 2000; n <= 32000; n *= 2) {
    const auto P = circle_both_sides(n);
    // The answer: the front hull of the circle, moved (an independent computation).
    gen::Options o;
    o.n = n;
    o.seed = 28;
    const auto front = gen::points(gen::Kind::circle, o);
    const auto want = at(P, convex_hull(front));
    std::vector<std::size_t> H = half_hull(P, true);
    const std::vector<std::size_t> H2 = half_hull(P, false);
    const std::size_t h1 = H.size(), h2 = H2.size();
    ASSERT_GT(h1, n / 3);  // both halves are large: the old insertion would cost h₁h₂ / 2 or more
    ASSERT_GT(h2, n / 3);
    CountingOrient::calls = 0;
    merge_halves<CountingOrient>(std::span<const Point>(P), H, H2);
    const auto calls = static_cast<double>(CountingOrient::calls);
    EXPECT_TRUE(same_cycle(at(P, H), want)) << "n = " << n;
    EXPECT_LE(calls, 2.0 * h1 + 7.0 * h2) << "n = " << n;  // the theorem's bound
    if (before > 0) {
      EXPECT_LE(calls, 2.2 * before) << "n = " << n;  // doubling n: about twice the tests
    }
    before = calls;
  }
}

// Random small sets with tiny integer coordinates: in an open hemisphere f·p > 0 for a random
// small f (so both halves are often large), sometimes with a point that breaks it.
std::vector<Point> random_set(std::mt19937_64& rng, std::size_t n, long r, bool spoil) {
  const auto pick = [&](long m) { return static_cast<long>(rng() % (2 * m + 1)) - m; };
  long f[3];
  do {
    for (long& c : f) c = pick(2);
  } while (f[0] == 0 && f[1] == 0 && f[2] == 0);
  std::vector<Point> P;
  while (P.size() < n) {
    const long w = pick(r), x = pick(r), y = pick(r);
    if (f[0] * w + f[1] * x + f[2] * y > 0) P.emplace_back(w, x, y);
  }
  if (spoil) {  // the antipode of a point, or a point near the antipode of f (not 0)
    Point p = antipode(P[rng() % P.size()]);
    long g[3] = {0, 0, 0};
    if (rng() % 2) {
      while (g[0] == 0 && g[1] == 0 && g[2] == 0)
        for (int k = 0; k < 3; ++k) g[k] = -f[k] + pick(1);
      p = Point(g[0], g[1], g[2]);
    }
    P.insert(P.begin() + static_cast<long>(rng() % P.size()), p);
  }
  return P;
}

TEST(HullMerge, AgreesWithBruteForceOnDegenerateSetsAllOverT2) {
  std::mt19937_64 rng(28);
  int with = 0, without = 0, walked = 0;
  for (int t = 0; t < 400 * kScale; ++t) {
    const std::size_t n = 8 + rng() % 22;
    const auto P = random_set(rng, n, t % 2 ? 2 : 3, t % 4 == 0);
    const bool none = testing::brute_no_hull(P);
    if (none) {
      ++without;
      try {
        merge_hull(std::span<const Point>(P));
        ADD_FAILURE() << "a hull of " << testing::text(P);
      } catch (const NoHull& e) {
        EXPECT_TRUE(testing::brute_no_hull(at(P, e.witnesses()))) << e.what() << " in " << testing::text(P);
      }
      continue;
    }
    ++with;
    const auto got = merge_hull(std::span<const Point>(P));
    EXPECT_TRUE(same_cycle(at(P, got), testing::brute_hull(P))) << testing::text(P);
    // The walk itself ran: the positive half's hull had three vertices and one more came.
    walked += half_hull(P, true).size() >= 3 && half_hull(P, false).size() >= 2;
  }
  EXPECT_GT(with, 150 * kScale);
  EXPECT_GT(without, 40 * kScale);
  EXPECT_GT(walked, 100 * kScale);
}

}  // namespace
}  // namespace t2
