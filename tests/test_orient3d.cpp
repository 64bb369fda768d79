// orient3d (Volume6 of seed 004) against the exact rational oracle: the 4×4 determinant with
// rows [x, y, z, 1] by Gaussian elimination, whose sign is the opposite of orient3d's (see
// orient3d.hpp). Random, nearly coplanar, exactly coplanar and extreme-exponent input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "t2/kernel/orient3d.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;
using testing::sign_oracle;

Sign oracle(const Point3& p, const Point3& q, const Point3& r, const Point3& s) {
  return -sign_oracle(testing::det4_points({{{p.x, p.y, p.z}, {q.x, q.y, q.z}, {r.x, r.y, r.z}, {s.x, s.y, s.z}}}));
}

void check(const Point3& p, const Point3& q, const Point3& r, const Point3& s) {
  const Sign want = oracle(p, q, r, s);
  ASSERT_EQ(orient3d(p, q, r, s), want) << p.x << " " << s.x;
  ASSERT_EQ(orient3d(q, p, r, s), -want);  // swapping two rows flips the sign
  ASSERT_EQ(orient3d(q, r, p, s), want);
}

TEST(Orient3d, UnitTetrahedronAndTheSeedsSign) {
  const Point3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(orient3d(o, x, y, z), POSITIVE);  // z is where x × y points
  EXPECT_EQ(orient3d(o, y, x, z), NEGATIVE);
  EXPECT_EQ(orient3d(o, x, y, Point3{5, -7, 0}), ZERO);
  EXPECT_EQ(volume6(o, x, y, z), 1.0);
  // The seed's 4×4 determinant has the opposite sign.
  EXPECT_LT(testing::det4_points({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}), 0);
}

/// Four points: p, q, r random in [-1, 1]³ at scale 2^e, s a rounded point of their plane nudged
/// by up to `ulps` units in the last place.
std::array<Point3, 4> near_plane(std::mt19937_64& rng, int e, int ulps) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> k(-ulps, ulps);
  Point3 p{u(rng), u(rng), u(rng)}, q{u(rng), u(rng), u(rng)}, r{u(rng), u(rng), u(rng)};
  const double s = u(rng), t = u(rng);
  Point3 w{p.x + s * (q.x - p.x) + t * (r.x - p.x), p.y + s * (q.y - p.y) + t * (r.y - p.y),
           p.z + s * (q.z - p.z) + t * (r.z - p.z)};
  for (int i = k(rng); i != 0; i += (i > 0 ? -1 : 1)) w.z = std::nextafter(w.z, i > 0 ? 9.0 : -9.0);
  auto sc = [e](Point3 v) { return Point3{std::ldexp(v.x, e), std::ldexp(v.y, e), std::ldexp(v.z, e)}; };
  return {sc(p), sc(q), sc(r), sc(w)};
}

TEST(Orient3d, RandomAndNearlyCoplanarMatchOracleAtEveryScale) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 2000 * scale(); ++i) check({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
  for (int e : {0, 60, -60, 290, -290, 301, -310, 700, -700, 1000, -1020}) {
    for (int i = 0; i < 200 * scale(); ++i) {
      const auto [p, q, r, s] = near_plane(rng, e, 2);
      check(p, q, r, s);
    }
  }
}

TEST(Orient3d, ExactlyCoplanarDyadicPointsAreZero) {
  std::mt19937_64 rng(32);
  std::uniform_int_distribution<int> m(-(1 << 20), 1 << 20), k(-8, 8);
  for (int e : {0, -40, 40, -290, 290, -900, 900}) {
    for (int i = 0; i < 300 * scale(); ++i) {
      auto c = [&](int sh) { return std::ldexp(m(rng), e - sh); };
      const Point3 p{c(20), c(20), c(20)}, v{c(24), c(24), c(24)}, w{c(24), c(24), c(24)};
      const double a = k(rng), b = k(rng);
      const Point3 q{p.x + v.x, p.y + v.y, p.z + v.z}, r{p.x + w.x, p.y + w.y, p.z + w.z};
      const Point3 s{p.x + a * v.x + b * w.x, p.y + a * v.y + b * w.y, p.z + a * v.z + b * w.z};
      ASSERT_EQ(oracle(p, q, r, s), ZERO);  // the construction is exact at these sizes
      ASSERT_EQ(orient3d(p, q, r, s), ZERO) << e;
      check(p, q, r, Point3{s.x, s.y, std::nextafter(s.z, 1e300)});
    }
  }
}

TEST(Orient3d, LimitsOfTheDoubleRange) {
  const double big = 0x1.fffffffffffffp1023, tiny = 0x1p-1074;
  const Point3 pts[] = {{big, 0, 0}, {0, big, 0}, {0, 0, big}, {-big, -big, -big}, {0, 0, 0}, {tiny, 0, 0},
                        {0, tiny, tiny}, {3 * tiny, -tiny, 5 * tiny}, {1, 1, 1}, {0x1p-1000, 1, 0x1p1000}};
  for (const Point3& p : pts)
    for (const Point3& q : pts)
      for (const Point3& r : pts)
        for (const Point3& s : {pts[0], pts[4], pts[5], pts[7], pts[8], pts[9]}) ASSERT_EQ(orient3d(p, q, r, s), oracle(p, q, r, s));
}

}  // namespace
}  // namespace t2
