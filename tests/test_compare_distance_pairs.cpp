// compare_distance(a, b, c, d): the distance of one pair against another's, against an oracle
// written from the picture in exact rationals (testing.hpp's pos and sq), not from the
// predicate's polynomial: a pair on one side is at its Euclidean length, a pair with one point
// on Omega at +infinity, and a pair across sides beyond infinity, where the pair drawn farther
// apart is nearer to +infinity and hence nearer.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "t2/kernel/distance.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::make;
using testing::pos;
using testing::q;
using testing::scale;
using testing::sq;

template <class P>
std::pair<int, Rational> key(const P& a, const P& b) {
  const int sa = sgn(q(a.w())), sb = sgn(q(b.w()));
  if (sa == 0 || sb == 0) return {1, Rational(0)};
  const Rational e = sq(pos(a), pos(b));
  return sa == sb ? std::pair<int, Rational>{0, e} : std::pair<int, Rational>{2, -e};
}

template <class P>
Sign oracle(const P& a, const P& b, const P& c, const P& d) {
  const auto k1 = key(a, b), k2 = key(c, d);
  if (k1.first != k2.first) return k1.first < k2.first ? NEGATIVE : POSITIVE;
  return static_cast<Sign>(sgn(k1.second - k2.second));
}

template <class P>
void matches_oracle(std::uint64_t seed, long range) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-range, range), w(-3, 3);
  int ties = 0, classes[3] = {0, 0, 0};
  for (int i = 0; i < 4000 * scale(); ++i) {
    long c[4][3];
    for (auto& v : c) v[0] = w(rng), v[1] = u(rng), v[2] = u(rng);
    if (i % 7 == 0) c[3][0] = c[2][0], c[3][1] = c[2][1] + 1, c[3][2] = c[2][2];  // a unit edge, for ties
    if (i % 11 == 0) c[1][0] = c[0][0], c[1][1] = c[0][1], c[1][2] = c[0][2] + 1;
    std::vector<P> p;
    for (auto& v : c) {
      if (v[0] == 0 && v[1] == 0 && v[2] == 0) v[1] = 1;  // [0,0,0] is not a point
      p.push_back(make<P>(v[0], v[1], v[2]));
    }
    if ((p[0].w() == 0 && p[1].w() == 0) || (p[2].w() == 0 && p[3].w() == 0)) {
      EXPECT_THROW(compare_distance(p[0], p[1], p[2], p[3]), Undefined);
      continue;
    }
    const Sign want = oracle(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(compare_distance(p[0], p[1], p[2], p[3]), want) << i;
    ASSERT_EQ(compare_distance(p[2], p[3], p[0], p[1]), -want) << i;
    ASSERT_EQ(compare_distance(p[1], p[0], p[3], p[2]), want) << i;  // each pair is unordered
    ties += want == ZERO;
    ++classes[key(p[0], p[1]).first];
  }
  // The draw reaches every class and some exact ties, so each branch is checked.
  EXPECT_GT(ties, 0);
  for (int c : classes) EXPECT_GT(c, 0);
}

TEST(CompareDistancePairs, DoublesMatchTheOracle) { matches_oracle<Point>(1, 4); }
TEST(CompareDistancePairs, IntegersMatchTheOracle) { matches_oracle<ExactPoint>(2, 4); }
TEST(CompareDistancePairs, WideDoublesMatchTheOracle) { matches_oracle<Point>(3, 1000000); }

TEST(CompareDistancePairs, AgreesWithTheT1OrderOfSquaredDistance) {
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<long> u(-9, 9), w(-2, 2);
  for (int i = 0; i < 2000 * scale(); ++i) {
    std::vector<ExactPoint> p;
    for (int k = 0; k < 4; ++k) {
      const long vw = w(rng);
      p.emplace_back(Integer(vw == 0 ? 1 : vw), Integer(u(rng)), Integer(u(rng)));
    }
    if (p[0].w() == 0 || p[2].w() == 0) continue;
    ASSERT_EQ(compare_distance(p[0], p[1], p[2], p[3]),
              compare_distance_values(squared_distance(p[0], p[1]), squared_distance(p[2], p[3])));
  }
}

TEST(CompareDistancePairs, AntipodesAreTheFarthestAndOmegaIsPlusInfinity) {
  const Point a(1, 0, 0), b(1, 3, 4), far(-1, 1000, 0), omega(0, 1, 0);
  EXPECT_EQ(compare_distance(a, b, a, omega), NEGATIVE);      // finite < +inf
  EXPECT_EQ(compare_distance(a, omega, a, far), NEGATIVE);    // +inf < beyond
  EXPECT_EQ(compare_distance(a, far, a, antipode(a)), NEGATIVE);  // the antipode is farthest
  EXPECT_EQ(compare_distance(b, omega, a, Point(0, 0, 1)), ZERO);  // both at +inf
  EXPECT_THROW(compare_distance(omega, Point(0, 0, 1), a, b), Undefined);
}

}  // namespace
}  // namespace t2
