// in_circle against its definition: the circumcentre z of the drawn positions of a, b, c is
// computed exactly with rationals, the disk is the set of points on the side of a, b, c nearer to
// z than a, and the answer is orient(a, b, c) times (inside ? +1 : on ? 0 : −1). The same centre,
// made a point of T², must also satisfy the §4.3.1 distances of distance.hpp.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/incircle.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;

using testing::make;
using testing::orient_oracle;
using testing::q;

using testing::pos;
using testing::Pos;
using testing::sq;

/// The circumcentre of three non-collinear positions (intersection of perpendicular bisectors).
Pos circumcentre(const Pos& a, const Pos& b, const Pos& c) {
  const Rational den = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
  const Rational la = sq(a, Pos{0, 0}), lb = sq(b, Pos{0, 0}), lc = sq(c, Pos{0, 0});
  return {Rational((la * (b[1] - c[1]) + lb * (c[1] - a[1]) + lc * (a[1] - b[1])) / den),
          Rational((la * (c[0] - b[0]) + lb * (a[0] - c[0]) + lc * (b[0] - a[0])) / den)};
}

/// The definition, with rationals only.
template <class P>
Sign in_circle_oracle(const P& a, const P& b, const P& c, const P& d) {
  const int sigma = sgn(q(a.w()));
  const Pos z = circumcentre(pos(a), pos(b), pos(c));
  int inside = -1;
  if (sgn(q(d.w())) == sigma) inside = -sgn(sq(pos(d), z) - sq(pos(a), z));
  return orient_oracle(a, b, c) * static_cast<Sign>(inside);
}

/// The centre as a point of T² on the side sigma of a, b, c.
ExactPoint centre_point(const Pos& z, int sigma) {
  Integer l;
  mpz_lcm(l.get_mpz_t(), z[0].get_den_mpz_t(), z[1].get_den_mpz_t());
  const Rational zx = z[0] * l, zy = z[1] * l;  // integers now
  return ExactPoint(Integer(sigma * l), Integer(sigma * zx.get_num()), Integer(sigma * zy.get_num()));
}

ExactPoint to_exact_any(const ExactPoint& p) { return p; }
ExactPoint to_exact_any(const Point& p) { return to_exact(p); }

template <class P>
void matches_definition(std::uint64_t seed, long range) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-range, range), w(1, 3), sd(-1, 1);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 4000 * scale(); ++i) {
    const int sigma = sd(rng) >= 0 ? 1 : -1;
    const P a = make<P>(sigma * w(rng), u(rng), u(rng)), b = make<P>(sigma * w(rng), u(rng), u(rng)),
            c = make<P>(sigma * w(rng), u(rng), u(rng));
    const long dw = sd(rng) * w(rng), dx = u(rng), dy = u(rng);  // any side, Omega included
    const P d = make<P>(dw, dw == 0 && dx == 0 && dy == 0 ? 1 : dx, dy);
    if (orient_oracle(a, b, c) == ZERO) {
      ASSERT_THROW(in_circle(a, b, c, d), Undefined);
      continue;
    }
    const Sign want = in_circle_oracle(a, b, c, d);
    ++counts[want + 1];
    ASSERT_EQ(in_circle(a, b, c, d), want) << to_string(a) << to_string(b) << to_string(c) << to_string(d);
    ASSERT_EQ(in_circle(b, a, c, d), -want);  // reversing the turn swaps inside and outside
    ASSERT_EQ(in_circle(b, c, a, d), want);
    // The unoriented disk test: the inside of the finite disk, for every order of a, b, c.
    const Pos zc = circumcentre(pos(a), pos(b), pos(c));
    const int disk = sgn(q(d.w())) == sigma ? -sgn(sq(pos(d), zc) - sq(pos(a), zc)) : -1;
    ASSERT_EQ(in_disk(a, b, c, d), static_cast<Sign>(disk));
    ASSERT_EQ(in_disk(c, b, a, d), static_cast<Sign>(disk));
    // The same answer from the distances of §4.3.1 around the centre as a point of T².
    const ExactPoint z = centre_point(circumcentre(pos(a), pos(b), pos(c)), sigma);
    const ExactPoint ea = to_exact_any(a), eb = to_exact_any(b), ec = to_exact_any(c), ed = to_exact_any(d);
    ASSERT_TRUE(squared_distance(z, ea) == squared_distance(z, eb));
    ASSERT_TRUE(squared_distance(z, ea) == squared_distance(z, ec));
    ASSERT_EQ(in_circle(a, b, c, d), orient(a, b, c) * -compare_distance(ed, ea, z));
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[2], 0);
  if (range <= 3) {
    EXPECT_GT(counts[1], 0);  // small grids are full of cocircular points
  }
}

TEST(InCircle, MatchesTheDefinitionOnBothSides) {
  matches_definition<Point>(1, 3);
  matches_definition<ExactPoint>(2, 3);
  matches_definition<ExactPoint>(3, 1000);
}

TEST(InCircle, CocircularPointsAreZero) {
  // Points of the circle x² + y² = 25 (Pythagorean) around a random centre, scaled by w.
  const std::vector<std::pair<long, long>> circle = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0},
                                                     {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<std::size_t> pick(0, circle.size() - 1);
  std::uniform_int_distribution<long> u(-50, 50), w(-4, 4);
  for (int i = 0; i < 2000 * scale(); ++i) {
    const long cx = u(rng), cy = u(rng);
    long ws[4];
    for (long& v : ws)
      do v = w(rng);
      while (v == 0);
    ws[1] = ws[2] = ws[0] > 0 ? std::labs(ws[1]) : -std::labs(ws[1]);
    auto pt = [&](long k) {
      const auto [x, y] = circle[pick(rng)];
      return ExactPoint(k, k * (cx + x), k * (cy + y));
    };
    const ExactPoint a = pt(ws[0]), b = pt(ws[1]), c = pt(ws[2]), d = pt(ws[3]);
    if (orient(a, b, c) == ZERO) continue;
    const Sign want = sign_of(ws[3]) == sign_of(ws[0]) ? ZERO : -orient(a, b, c);
    ASSERT_EQ(in_circle(a, b, c, d), want);
    ASSERT_EQ(in_circle(to_double(a), to_double(b), to_double(c), to_double(d)), want);
  }
}

TEST(InCircle, FrontPointsFollowCgalsConvention) {
  const Point a(1, 0, 0), b(1, 1, 0), c(1, 0, 1);  // counter-clockwise
  EXPECT_EQ(in_circle(a, b, c, Point(1, 0.25, 0.25)), POSITIVE);
  EXPECT_EQ(in_circle(a, b, c, Point(1, 5, 5)), NEGATIVE);
  EXPECT_EQ(in_circle(a, b, c, Point(2, 2, 2)), ZERO);  // (1, 1) is on the circle
  EXPECT_EQ(in_circle(a, c, b, Point(1, 0.25, 0.25)), NEGATIVE);
  // The back copy of an inside point is beyond infinity from the centre: outside.
  EXPECT_EQ(in_circle(a, b, c, Point(-1, -0.25, -0.25)), NEGATIVE);
  EXPECT_EQ(in_circle(a, b, c, Point(0, 1, 1)), NEGATIVE);
  // The circle through the antipodes turns the other way: the small disk is outside it.
  EXPECT_EQ(orient(antipode(a), antipode(b), antipode(c)), NEGATIVE);
  EXPECT_EQ(in_circle(antipode(a), antipode(b), antipode(c), Point(-1, -0.25, -0.25)), NEGATIVE);
  EXPECT_EQ(in_circle(antipode(a), antipode(b), antipode(c), Point(1, 0.25, 0.25)), POSITIVE);
}

TEST(InCircle, UndefinedWithoutACircle) {
  const ExactPoint a(1, 0, 0), b(1, 1, 0), d(1, 3, 3);
  EXPECT_THROW(in_circle(a, b, ExactPoint(1, 2, 0), d), Undefined);   // collinear
  EXPECT_THROW(in_circle(a, b, ExactPoint(-1, -2, 0), d), Undefined);  // collinear across sides
  EXPECT_THROW(in_circle(a, b, ExactPoint(0, 1, 0), d), Undefined);   // collinear through Omega
  // Two points of Omega and one proper: infinitely many lunes.
  EXPECT_THROW(in_circle(ExactPoint(0, 1, 0), a, ExactPoint(0, 0, 1), d), Undefined);
  EXPECT_THROW(in_circle(Point(0, 1, 0), Point(0, 1, 1), Point(1, 0, 1), Point(1, 3, 3)), Undefined);
}

TEST(InCircle, LunesByHand) {
  // a, b on the front along the x axis, c on the back drawn at (0, 5): the lune is the front
  // half-plane y > 0 and the back half-plane drawn below Y = 5, centred at the direction +y.
  const Point a(1, 0, 0), b(1, 1, 0), c(-1, 0, -5);
  EXPECT_EQ(in_circle(a, b, c, Point(1, 0, 1)), POSITIVE);
  EXPECT_EQ(in_circle(a, b, c, Point(1, 0, -1)), NEGATIVE);
  EXPECT_EQ(in_circle(a, b, c, Point(1, 7, 0)), ZERO);
  EXPECT_EQ(in_circle(a, b, c, Point(-1, 0, 0)), POSITIVE);    // back, drawn at (0, 0)
  EXPECT_EQ(in_circle(a, b, c, Point(-1, -3, -10)), NEGATIVE);  // back, drawn at (3, 10)
  EXPECT_EQ(in_circle(a, b, c, Point(-2, 8, -10)), ZERO);       // back, drawn at (-4, 5)
  EXPECT_EQ(in_circle(a, b, c, Point(0, 0, 1)), POSITIVE);     // the direction +y, the centre
  EXPECT_EQ(in_circle(a, b, c, Point(0, 1, 0)), ZERO);         // the vertices of the lune
  EXPECT_EQ(in_circle(a, b, c, Point(0, 1, -1)), NEGATIVE);
  // The circle through two points and a point at infinity is their line: left of a -> b.
  const Point up(0, 1, 3), down(0, 1, -3);
  EXPECT_EQ(in_circle(a, b, up, Point(1, 5, 2)), POSITIVE);
  EXPECT_EQ(in_circle(a, b, down, Point(1, 5, 2)), POSITIVE);
  EXPECT_EQ(in_circle(a, b, up, Point(1, 5, -2)), NEGATIVE);
  EXPECT_EQ(in_circle(a, b, up, Point(-1, 5, 2)), NEGATIVE);  // the back: outside, c turns left
  EXPECT_EQ(in_circle(a, b, down, Point(-1, 5, 2)), POSITIVE);  // c turns right: inside
  EXPECT_EQ(in_circle(a, b, up, Point(0, -1, 1)), ZERO);      // the half of Omega through c
  EXPECT_EQ(in_circle(a, b, up, Point(0, -1, -1)), NEGATIVE);
  EXPECT_EQ(in_circle(a, b, down, Point(0, -1, 1)), POSITIVE);
  EXPECT_EQ(in_circle(a, b, down, Point(0, -1, -1)), ZERO);
}

template <class P>
void lunes_match_oracle(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-4, 4), w(-2, 2);
  auto any = [&] {
    for (;;) {
      const long pw = w(rng), px = u(rng), py = u(rng);
      if (pw != 0 || px != 0 || py != 0) return make<P>(pw, px, py);
    }
  };
  int counts[3] = {0, 0, 0}, undefined = 0;
  for (int i = 0; i < 20000 * scale(); ++i) {
    const P a = any(), b = any(), c = any(), d = any();
    const int sa = sgn(q(a.w())), sb = sgn(q(b.w())), sc = sgn(q(c.w()));
    if (sa != 0 && sa == sb && sb == sc) continue;  // a finite circle: the tests above
    Sign want;
    try {
      want = testing::in_lune_oracle(a, b, c, d);
    } catch (const Undefined&) {
      ++undefined;
      ASSERT_THROW(in_circle(a, b, c, d), Undefined) << to_string(a) << to_string(b) << to_string(c);
      continue;
    }
    ++counts[want + 1];
    ASSERT_EQ(in_circle(a, b, c, d), want) << to_string(a) << to_string(b) << to_string(c) << to_string(d);
    ASSERT_EQ(in_circle(b, c, a, d), want);
    ASSERT_EQ(in_circle(c, a, b, d), want);
    ASSERT_EQ(in_circle(b, a, c, d), -want);
    ASSERT_EQ(in_circle(antipode(a), antipode(b), antipode(c), antipode(d)), -want);
    ASSERT_EQ(in_disk(a, b, c, d), orient(a, b, c) * want);
  }
  EXPECT_GT(counts[0], 100);
  EXPECT_GT(counts[1], 100);
  EXPECT_GT(counts[2], 100);
  EXPECT_GT(undefined, 100);
}

TEST(InCircle, LunesMatchTheSweepRuleOracle) {
  lunes_match_oracle<Point>(31);
  lunes_match_oracle<ExactPoint>(32);
}

TEST(InCircle, APointAtInfinityIsTheLimitOfFarPoints) {
  // c on Omega against c_R = a + R·c (homogeneous sum) on the side of a, b, R = 2^100: for every d
  // off the line a ∨ b the finite circle through a, b, c_R already answers as the line does.
  std::mt19937_64 rng(33);
  std::uniform_int_distribution<long> u(-20, 20), w(1, 3);
  const Integer R = Integer(1) << 100;
  int checked = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    const long s = i % 2 ? 1 : -1;
    const ExactPoint a(s, u(rng), u(rng)), b(s, u(rng), u(rng)), c(0, u(rng), u(rng) + 21);
    const ExactPoint d(s * (i % 3 ? 1 : -1) * w(rng), u(rng), u(rng));
    if (a == b || orient(a, b, c) == ZERO || orient(a, b, d) == ZERO) continue;
    const ExactPoint far(a.w(), a.x() + R * c.x(), a.y() + R * c.y());  // tends to c
    ASSERT_EQ(in_circle(a, b, c, d), in_circle(a, b, far, d)) << to_string(a) << to_string(b) << to_string(c)
                                                             << to_string(d);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(InCircle, ADOnOmegaIsTheLimitOfFarDOnEitherSide) {
  // The lune through x, y (front) and z (back): its rule for d on Omega is the limit of its rules
  // for d on either side, as d = [±ε, dx, dy] runs off towards [0, dx, dy]; and a rotation of
  // x, y, z does not change it.
  const Point x = Point::cartesian(1, 0), y = Point::cartesian(0, 1), z(-1, -0.2, -0.1);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 200; ++k) {
    const double dx = u(rng), dy = u(rng);
    const Sign at_inf = in_circle(x, y, z, Point::at_infinity(dx, dy));
    ASSERT_NE(at_inf, ZERO);
    EXPECT_EQ(in_circle(x, y, z, Point(1e-9, dx, dy)), at_inf);   // front, far in (dx, dy)
    EXPECT_EQ(in_circle(x, y, z, Point(-1e-9, dx, dy)), at_inf);  // back, drawn far in -(dx, dy)
    EXPECT_EQ(in_circle(z, x, y, Point::at_infinity(dx, dy)), at_inf);
  }
}

TEST(InCircle, RandomDoublesMatchOracle) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 3000 * scale(); ++i) {
    const double s = u(rng) < 0 ? -1 : 1;
    const Point a(s * (1.5 + u(rng)), u(rng), u(rng)), b(s * (1.5 + u(rng)), u(rng), u(rng)),
        c(s * (1.5 + u(rng)), u(rng), u(rng)), d(u(rng), u(rng), u(rng));
    ASSERT_EQ(in_circle(a, b, c, d), in_circle_oracle(a, b, c, d));
  }
  // Nearly cocircular: d is a rounded point of the circle through a, b, c = (1,0), (0,1), (-1,0).
  for (int i = 0; i < 3000 * scale(); ++i) {
    const double t = 3 * u(rng), x = std::cos(t), y = std::sin(t);
    const Point a(1, 1, 0), b(1, 0, 1), c(1, -1, 0), d(1, x, y);
    ASSERT_EQ(in_circle(a, b, c, d), in_circle_oracle(a, b, c, d));
  }
}

/// Four points rounded onto one circle (centre and radius random), d nudged by up to `ulps`
/// units in the last place, all scaled exactly by 2^e; with weight w (an exact power of two).
std::array<Point, 4> near_circle(std::mt19937_64& rng, int e, int ulps, double w = 1) {
  std::uniform_real_distribution<double> u(-1, 1), t(0, 6.283185307179586);
  std::uniform_int_distribution<int> k(-ulps, ulps);
  const double cx = u(rng), cy = u(rng), rad = 0.1 + std::fabs(u(rng));
  std::array<Point, 4> p{Point(1, 0, 0), Point(1, 0, 0), Point(1, 0, 0), Point(1, 0, 0)};
  for (int i = 0; i < 4; ++i) {
    const double a = t(rng);
    double x = cx + rad * std::cos(a), y = cy + rad * std::sin(a);
    if (i == 3)
      for (int j = k(rng); j != 0; j += (j > 0 ? -1 : 1)) y = std::nextafter(y, j > 0 ? 9.0 : -9.0);
    p[i] = Point(w, w * std::ldexp(x, e), w * std::ldexp(y, e));
  }
  return p;
}

TEST(InCircle, NearlyCocircularMatchesOracleAtEveryScale) {
  // Every stage of incircle_double.hpp: fast path, unrounded differences, full expansions, and
  // the dyadic fallback; Cartesian (w = 1) and homogeneous (w = 2^k) input.
  std::mt19937_64 rng(21);
  for (double w : {1.0, 0.25, 8.0}) {
    for (int e : {0, 60, -60, 200, -200, 215, -209, 249, 260, -260, 500, -500, 950, -1000}) {
      for (int i = 0; i < 40 * scale(); ++i) {
        const auto [a, b, c, d] = near_circle(rng, e, 2, w);
        if (orient_oracle(a, b, c) == ZERO) {
          ASSERT_THROW(in_circle(a, b, c, d), Undefined);
          continue;
        }
        const Sign want = in_circle_oracle(a, b, c, d);
        ASSERT_EQ(in_circle(a, b, c, d), want) << w << " " << e;
        ASSERT_EQ(in_circle(b, a, c, d), -want);
        if (w == 1 && std::abs(e) <= 200) {
          ASSERT_EQ(in_circle(to_exact(a), to_exact(b), to_exact(c), to_exact(d)), want);
        }
      }
    }
  }
}

TEST(InCircle, GridsMatchOracleAtEveryScale) {
  // Cartesian points k·2^s on integer grids: the coarse-grid stage of incircle_double.hpp
  // (|k| < 2^11 relative to the largest coordinate, 2^s in range) and its edges: |k| up to 4095
  // and 65535 (past the grid, the expansions decide; a grid of 2^17 would round here), scales
  // past 2^±200, and points of one circle (x² + y² = (5m)², from (3, 4, 5)) with d exactly on it
  // or one grid step off, where H is zero or small against terms near 2^50 and beyond.
  std::mt19937_64 rng(23);
  const long pyth[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5},
                            {3, -4}, {4, -3}};
  std::uniform_int_distribution<int> pick(0, 11), nudge(-1, 1);
  int zeros = 0;
  for (int s : {0, -60, 60, -190, 190, -205, 205, -1000}) {
    for (long range : {15L, 2047L, 4095L, 65535L}) {
      std::uniform_int_distribution<long> u(-range, range), m(1, range / 5);
      for (int i = 0; i < 300 * scale(); ++i) {
        double xy[4][2];
        if (i % 2 == 0) {
          for (auto& p : xy) p[0] = double(u(rng)), p[1] = double(u(rng));
        } else {  // one circle around (cx, cy), radius 5 m; d perhaps one step off it
          const long r = m(rng), cx = u(rng) / 2, cy = u(rng) / 2;
          for (auto& p : xy) {
            const auto& v = pyth[pick(rng)];
            p[0] = double(cx + r * v[0]), p[1] = double(cy + r * v[1]);
          }
          xy[3][0] += nudge(rng);
        }
        Point p[4] = {Point(1, 0, 0), Point(1, 0, 0), Point(1, 0, 0), Point(1, 0, 0)};
        for (int k = 0; k < 4; ++k) p[k] = Point::cartesian(std::ldexp(xy[k][0], s), std::ldexp(xy[k][1], s));
        if (orient_oracle(p[0], p[1], p[2]) == ZERO) {
          ASSERT_THROW(in_circle(p[0], p[1], p[2], p[3]), Undefined);
          continue;
        }
        const Sign want = in_circle_oracle(p[0], p[1], p[2], p[3]);
        zeros += want == ZERO;
        ASSERT_EQ(in_circle(p[0], p[1], p[2], p[3]), want) << s << " " << range << " " << i;
        ASSERT_EQ(in_circle(p[1], p[0], p[2], p[3]), -want);
        if (s == 0) {
          ASSERT_EQ(in_circle(to_exact(p[0]), to_exact(p[1]), to_exact(p[2]), to_exact(p[3])), want);
        }
      }
    }
  }
  EXPECT_GT(zeros, 100);
}

TEST(InCircle, NearlyCollinearTrianglesThrowExactlyWhenCollinear) {
  // a, b, c rounded onto a line: the fast path cannot certify their orientation, the exact
  // orient decides whether there is a circle.
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1, 1), t(0, 1);
  int thrown = 0;
  for (int i = 0; i < 2000 * scale(); ++i) {
    const double px = u(rng), py = u(rng), qx = i % 3 ? u(rng) : px + 0.5, qy = i % 3 ? u(rng) : py + 0.25;
    const double s = i % 3 ? t(rng) : 2.0;
    const Point a(1, px, py), b(1, qx, qy), c(1, px + s * (qx - px), py + s * (qy - py)), d(1, u(rng), u(rng));
    if (orient_oracle(a, b, c) == ZERO) {
      ++thrown;
      ASSERT_THROW(in_circle(a, b, c, d), Undefined);
    } else {
      ASSERT_EQ(in_circle(a, b, c, d), in_circle_oracle(a, b, c, d));
    }
  }
  EXPECT_GT(thrown, 0);
}

}  // namespace
}  // namespace t2
