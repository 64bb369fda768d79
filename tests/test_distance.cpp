// Squared distances in T¹ and compare_distance, against independent oracles: Euclidean distances
// of the drawn positions in exact rationals, limits in which a point of Ω is replaced by a far
// proper point [±1, R u] (with the linear coefficient in R extracted exactly from two values of R),
// and angles between exact unit vectors of R³ (Pythagorean triples and quadruples).
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "t2/kernel/distance.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;

using testing::make;
using testing::pos;
using testing::q;
using testing::sq;

template <class P>
int side(const P& p) {
  return sgn(q(p.w()));
}

ExactPoint to_exact_any(const ExactPoint& p) { return p; }
ExactPoint to_exact_any(const Point& p) { return to_exact(p); }

/// Oracle for proper a, b, c, written from the picture: a point on c's side is at its Euclidean
/// distance; a point on the other side is beyond infinity, and among those the one drawn farther
/// is nearer to +∞, hence nearer.
template <class P>
Sign oracle_proper(const P& a, const P& b, const P& c) {
  auto key = [&](const P& v) {
    const Rational e = sq(pos(v), pos(c));
    return side(v) == side(c) ? std::pair<int, Rational>{0, e} : std::pair<int, Rational>{1, -e};
  };
  const auto ka = key(a), kb = key(b);
  if (ka.first != kb.first) return ka.first < kb.first ? NEGATIVE : POSITIVE;
  return static_cast<Sign>(sgn(ka.second - kb.second));
}

template <class P>
void squared_distance_matches_euclid(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-20, 20);
  for (int i = 0; i < 2000 * scale(); ++i) {
    long aw = u(rng), bw = u(rng);
    if (aw == 0) aw = 3;
    if (bw == 0) bw = -2;
    const P a = make<P>(aw, u(rng), u(rng)), b = make<P>(bw, u(rng), u(rng));
    const auto d = squared_distance(a, b);
    ASSERT_EQ(sgn(q(d.w())), side(a) * side(b));
    ASSERT_GE(sgn(q(d.x())), 0);
    // |x / w| is the Euclidean squared distance of the drawn positions.
    ASSERT_EQ(abs(q(d.x()) / q(d.w())), sq(pos(a), pos(b)));
    ASSERT_TRUE(squared_distance(b, a) == d);  // symmetric as points of T1
  }
}

TEST(SquaredDistance, IsEuclideanOnOneSideAndBeyondInfinityAcross) {
  squared_distance_matches_euclid<Point>(1);
  squared_distance_matches_euclid<ExactPoint>(2);
}

template <class P>
void squared_distance_special_cases() {
  using T = typename P::Coordinate;
  const P a = make<P>(2, 2, 4), inf = make<P>(0, 3, -1);
  EXPECT_TRUE(squared_distance(a, a) == BasicT1<T>(T(1), T(0)));
  EXPECT_TRUE(squared_distance(a, antipode(a)) == BasicT1<T>(T(-1), T(0)));  // the farthest value
  EXPECT_TRUE(squared_distance(a, inf) == BasicT1<T>::plus_infinity());
  EXPECT_TRUE(squared_distance(antipode(a), inf) == BasicT1<T>::plus_infinity());
  EXPECT_THROW(squared_distance(inf, make<P>(0, 1, 1)), Undefined);
  EXPECT_THROW(squared_distance(inf, inf), Undefined);
  // The T1 order of distances: 0 < finite < +inf < beyond < [-1, 0].
  const std::vector<BasicT1<T>> chain = {BasicT1<T>(T(1), T(0)), BasicT1<T>(T(4), T(1)), BasicT1<T>(T(1), T(7)),
                                         BasicT1<T>::plus_infinity(), BasicT1<T>(T(-1), T(7)),
                                         BasicT1<T>(T(-4), T(1)), BasicT1<T>(T(-1), T(0))};
  for (std::size_t i = 0; i < chain.size(); ++i)
    for (std::size_t j = 0; j < chain.size(); ++j)
      EXPECT_EQ(compare_distance_values(chain[i], chain[j]), i < j ? NEGATIVE : (i == j ? ZERO : POSITIVE)) << i << ' ' << j;
  EXPECT_EQ(compare_distance_values(BasicT1<T>(T(2), T(6)), BasicT1<T>(T(1), T(3))), ZERO);
  EXPECT_THROW(compare_distance_values(BasicT1<T>(T(1), T(-1)), chain[0]), Undefined);
}

TEST(SquaredDistance, DoublesDoNotUnderflowOrOverflow) {
  // (a_w b_w)^2 = 1e-800 underflows in double; the value is still the distance 1.
  EXPECT_TRUE(squared_distance(Point(1e-200, 0, 0), Point(1e-200, 1e-200, 0)) == T1(1, 1));
  EXPECT_TRUE(squared_distance(Point(0x1p700, 0, 0), Point(-0x1p700, 0x3p700, 0x4p700)) == T1(-1, 25));
  EXPECT_TRUE(squared_distance(Point(1e-300, 1e-300, 0), Point(0, 1e300, 0)) == T1::plus_infinity());
}

TEST(SquaredDistance, SpecialCasesAndTheOrderOfT1) {
  squared_distance_special_cases<Point>();
  squared_distance_special_cases<ExactPoint>();
}

template <class P>
void all_proper_matches_oracle(std::uint64_t seed, long range, bool expect_ties) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-range, range), w(1, 3), s(0, 1);
  int ties = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    auto pt = [&] { return make<P>(w(rng) * (s(rng) ? 1 : -1), u(rng), u(rng)); };
    const P a = pt(), b = pt(), c = pt();
    const Sign want = oracle_proper(a, b, c);
    ties += want == ZERO;
    ASSERT_EQ(compare_distance(a, b, c), want) << to_string(a) << to_string(b) << to_string(c);
    ASSERT_EQ(compare_distance(b, a, c), -want);
    // Seen from the antipode of c, the sides swap and so does the order.
    ASSERT_EQ(compare_distance(a, b, antipode(c)), -want);
  }
  if (expect_ties) {
    EXPECT_GT(ties, 0);  // small ranges do produce exact ties
  }
}

TEST(CompareDistance, AllProperMatchesEuclideanOracle) {
  all_proper_matches_oracle<Point>(3, 3, true);
  all_proper_matches_oracle<ExactPoint>(4, 3, true);
  all_proper_matches_oracle<ExactPoint>(5, 1000, false);
}

TEST(CompareDistance, RandomDoublesMatchOracle) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 3000 * scale(); ++i) {
    const Point a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    ASSERT_EQ(compare_distance(a, b, c), oracle_proper(a, b, c));
  }
  // Nearly equidistant: b is a reflection of a in a line through c, rounded.
  for (int i = 0; i < 3000 * scale(); ++i) {
    const double cx = u(rng), cy = u(rng), ax = u(rng), ay = u(rng);
    const Point a(1, ax, ay), c(1, cx, cy), b(1, 2 * cx - ax, 2 * cy - ay);
    ASSERT_EQ(compare_distance(a, b, c), oracle_proper(a, b, c));
  }
}

/// A far proper point near the direction [0, ux, uy] on side s: [s, R ux, R uy], drawn at s R u;
/// as R grows, [s/R, ux, uy] runs off to [0, u] from the front (s = 1) or from the back (s = -1).
ExactPoint far_point(const ExactPoint& dir, int side_sign, const Integer& R) {
  return ExactPoint(Integer(side_sign), R * dir.x(), R * dir.y());
}

template <class P>
void one_at_infinity_c_proper(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-9, 9), s(0, 1);
  const Integer R("1000000000000000000000000000000");
  for (int i = 0; i < 2000 * scale(); ++i) {
    const long dx = u(rng), dy = u(rng);
    if (dx == 0 && dy == 0) continue;
    const P inf = make<P>(0, dx, dy);
    const P b = make<P>(s(rng) ? 1 : -1, u(rng), u(rng)), c = make<P>(s(rng) ? 2 : -2, u(rng), u(rng));
    // Oracle: replace inf by a far proper point, from the front or from the back.
    for (int approach : {1, -1}) {
      const ExactPoint far = far_point(to_exact_any(inf), approach, R);
      const Sign want = oracle_proper(far, to_exact_any(b), to_exact_any(c));
      ASSERT_EQ(compare_distance(inf, b, c), want);
      ASSERT_EQ(compare_distance(b, inf, c), -want);
    }
  }
}

TEST(CompareDistance, OnePointOfOmegaIsAtPlusInfinityFromAProperCentre) {
  one_at_infinity_c_proper<Point>(7);
  one_at_infinity_c_proper<ExactPoint>(8);
}

/// lim (d(a, c') - d(b, c')) as c' runs off to the direction u on side `approach`, by sign only:
/// E(R) = |A - C'|^2 - |B - C'|^2 is linear in R, and its coefficient alpha (extracted exactly
/// from two values of R) has the sign of the limit, which is alpha / (2|u|); alpha = 0 is a tie.
/// Across sides (c' on the other side of a and b) distances are beyond infinity: reversed.
Sign sweep_oracle(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c, int approach) {
  const Integer R1("1000000000000000000000"), R2("7000000000000000000000000");
  auto e = [&](const Integer& R) -> Rational {
    const auto cp = pos(far_point(c, approach, R));
    return sq(pos(a), cp) - sq(pos(b), cp);
  };
  const Rational alpha = (e(R2) - e(R1)) / Rational(R2 - R1);
  const Sign s = static_cast<Sign>(sgn(alpha));
  return side(a) == approach ? s : -s;
}

template <class P>
void sweep_rule(std::uint64_t seed, long range) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-range, range), w(1, 4), s(0, 1);
  int ties = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    const long dx = u(rng), dy = u(rng);
    if (dx == 0 && dy == 0) continue;
    const P c = make<P>(0, dx, dy);
    const int sd = s(rng) ? 1 : -1;
    // Drawn in a fixed order, y, x, w (a call's arguments have none: GCC drew them so, clang
    // the other way, and its points had no tie).
    const std::array<long, 6> d{u(rng), u(rng), sd * w(rng), u(rng), u(rng), sd * w(rng)};
    const P a = make<P>(d[2], d[1], d[0]), b = make<P>(d[5], d[4], d[3]);
    const Sign front = sweep_oracle(to_exact_any(a), to_exact_any(b), to_exact_any(c), 1);
    const Sign back = sweep_oracle(to_exact_any(a), to_exact_any(b), to_exact_any(c), -1);
    ASSERT_EQ(front, back);  // on one side, the two ways of reaching c agree
    ties += front == ZERO;
    ASSERT_EQ(compare_distance(a, b, c), front);
    // The seed's formulation: r = a v c, r_perp = a v norm(r); r_perp <> b > 0 iff a is nearer.
    if (!(a == b) && !(a == antipode(b))) {
      const auto r = join(a, c);
      using T = typename P::Coordinate;
      const P n(T(0), r.X(), r.Y());
      const auto rp = join(a, n);
      ASSERT_EQ(t2::side(rp, b), -compare_distance(a, b, c)) << "seed sweep rule, same side";
    }
    // Opposite sides: no answer.
    ASSERT_THROW(compare_distance(a, antipode(b), c), Undefined);
  }
  EXPECT_GT(ties, 0);
}

TEST(CompareDistance, SweepRuleIsTheLimitFromEitherSide) {
  sweep_rule<Point>(9, 4);
  sweep_rule<ExactPoint>(10, 4);
  sweep_rule<ExactPoint>(11, 300);
}

// Integer vectors of R^3 with integer length: exact unit vectors for the angle oracle.
struct Unit {
  long w, x, y, len;
};
std::vector<Unit> units(bool on_omega) {
  std::vector<Unit> out;
  for (long w = on_omega ? 0 : -9; w <= (on_omega ? 0 : 9); ++w)
    for (long x = -13; x <= 13; ++x)
      for (long y = -13; y <= 13; ++y) {
        const long n2 = w * w + x * x + y * y;
        long r = 0;
        while (r * r < n2) ++r;
        if (n2 > 0 && r * r == n2 && (on_omega || w != 0)) out.push_back({w, x, y, r});
      }
  return out;
}

/// Oracle of the angle rule: the larger cosine (dot product of exact unit vectors) is nearer.
Sign angle_oracle(const Unit& a, const Unit& b, const Unit& c) {
  auto cosine = [&](const Unit& v) -> Rational { return Rational(v.w * c.w + v.x * c.x + v.y * c.y) / Rational(v.len * c.len); };
  return static_cast<Sign>(sgn(cosine(b) - cosine(a)));
}

template <class P>
void angle_rule(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto omega = units(true), proper = units(false);
  std::uniform_int_distribution<std::size_t> io(0, omega.size() - 1), ip(0, proper.size() - 1);
  std::uniform_int_distribution<long> k(1, 5);
  auto as_point = [&](const Unit& v) { const long m = k(rng); return make<P>(m * v.w, m * v.x, m * v.y); };
  int ties = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    // Cases: (a, b on Omega, c proper), (all on Omega), (c and a on Omega, b proper), (c and b on
    // Omega, a proper). The last two are the 90-degree convention of chapter 03, section 5: the
    // proper point counts as 90 degrees from c, where the origin is.
    const int kase = i % 4;
    const Unit a = kase == 3 ? proper[ip(rng)] : omega[io(rng)];
    const Unit b = kase == 2 ? proper[ip(rng)] : omega[io(rng)];
    const Unit c = kase == 0 ? proper[ip(rng)] : omega[io(rng)];
    const Unit at_90{0, -c.y, c.x, c.len};  // a point of Omega 90 degrees from c
    const Sign want = angle_oracle(kase == 3 ? at_90 : a, kase == 2 ? at_90 : b, c);
    ties += want == ZERO;
    ASSERT_EQ(compare_distance(as_point(a), as_point(b), as_point(c)), want) << kase;
  }
  EXPECT_GT(ties, 0);
}

TEST(CompareDistance, TwoOrThreeOnOmegaFollowTheAngleRuleAndTheNinetyDegreeConvention) {
  angle_rule<Point>(12);
  angle_rule<ExactPoint>(13);
}

TEST(CompareDistance, AProperPointIsNinetyDegreesFromADirectionWhereverItIs) {
  // c = [0,1,0] and a proper b = (3, -2): the seed's angle at the origin puts b about 36.7
  // degrees from c, so it made b nearer than a = [0,1,1] (45 degrees). The convention of
  // chapter 03 puts every proper point, on either side, at 90 degrees: a is nearer, [0,0,1] ties
  // with b, [0,-1,1] (135 degrees) is farther.
  const Point c(0, 1, 0);
  for (const Point& b : {Point::cartesian(3, -2), Point(-1, 3, -2), Point(1, 0, 0), Point(-2, 1e300, 1e-300)}) {
    EXPECT_EQ(compare_distance(Point(0, 1, 1), b, c), NEGATIVE) << to_string(b);
    EXPECT_EQ(compare_distance(b, Point(0, 1, 1), c), POSITIVE) << to_string(b);
    EXPECT_EQ(compare_distance(Point(0, 0, 1), b, c), ZERO) << to_string(b);
    EXPECT_EQ(compare_distance(b, Point(0, 0, -7), c), ZERO) << to_string(b);
    EXPECT_EQ(compare_distance(Point(0, -1, 1), b, c), POSITIVE) << to_string(b);
    EXPECT_EQ(compare_distance(to_exact(Point(0, -1, 1)), to_exact(b), to_exact(c)), POSITIVE) << to_string(b);
    EXPECT_EQ(compare_distance(c, b, c), NEGATIVE);     // c itself: distance zero
    EXPECT_EQ(compare_distance(b, antipode(c), c), NEGATIVE);  // ¬c: 180 degrees
  }
}

TEST(CompareDistance, AngleRuleWithProperCentreIsTheLimit) {
  // a, b on Omega and c proper: replace a and b by far points at the same distance R|u| = R
  // (unit directions from Pythagorean triples), from the front or the back; E(R) is linear in R.
  std::mt19937_64 rng(14);
  const auto omega = units(true);
  std::uniform_int_distribution<std::size_t> io(0, omega.size() - 1);
  std::uniform_int_distribution<long> u(-20, 20), s(0, 1);
  const Integer R1("1000000000000000000000"), R2("9000000000000000000000000");
  for (int i = 0; i < 2000 * scale(); ++i) {
    const Unit ua = omega[io(rng)], ub = omega[io(rng)];
    long cw = u(rng);
    if (cw == 0) cw = 1;
    const ExactPoint c(cw, u(rng), u(rng));
    const int approach = s(rng) ? 1 : -1;
    auto far = [&](const Unit& v, const Integer& R) {  // drawn at approach * R * v / |v|
      return testing::Pos{Rational(approach * R * v.x) / v.len, Rational(approach * R * v.y) / v.len};
    };
    auto e = [&](const Integer& R) -> Rational { return sq(far(ua, R), pos(c)) - sq(far(ub, R), pos(c)); };
    const Rational alpha = (e(R2) - e(R1)) / Rational(R2 - R1);
    Sign want = static_cast<Sign>(sgn(alpha));
    if (approach != side(c)) want = -want;  // both beyond infinity: reversed
    const ExactPoint a(0, ua.x, ua.y), b(0, ub.x, ub.y);
    ASSERT_EQ(compare_distance(a, b, c), want);
    ASSERT_EQ(compare_distance(to_double(a), to_double(b), to_double(c)), want);
  }
}

TEST(CompareDistance, NearlyEquidistantCartesianAtEveryScale) {
  // Every stage of distance_double.hpp: a and b rounded onto one circle around c (so the
  // filter cannot decide), b nudged by a few ulps, all scaled exactly by 2^e; the fast path,
  // the unrounded differences, the two-component expansions and the dyadic fallback.
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(-1, 1), t(0, 6.283185307179586);
  std::uniform_int_distribution<int> k(-2, 2);
  int ties = 0;
  for (int e : {0, 60, -60, 300, -300, 484, -484, 490, -490, 501, -540, 900, -1000}) {
    for (int i = 0; i < 300 * scale(); ++i) {
      const double cx = u(rng), cy = u(rng), r = 0.1 + std::fabs(u(rng)), s = t(rng), v = t(rng);
      double bx = cx + r * std::cos(v), by = cy + r * std::sin(v);
      for (int j = k(rng); j != 0; j += j > 0 ? -1 : 1) by = std::nextafter(by, j > 0 ? 9.0 : -9.0);
      const double ax = i % 4 ? cx + r * std::cos(s) : 2 * cx - bx, ay = i % 4 ? cy + r * std::sin(s) : 2 * cy - by;
      const Point a = Point::cartesian(std::ldexp(ax, e), std::ldexp(ay, e)),
                  b = Point::cartesian(std::ldexp(bx, e), std::ldexp(by, e)),
                  c = Point::cartesian(std::ldexp(cx, e), std::ldexp(cy, e));
      const Sign want = oracle_proper(a, b, c);
      ties += want == ZERO;
      ASSERT_EQ(compare_distance(a, b, c), want) << e;
      ASSERT_EQ(compare_distance(b, a, c), -want) << e;
    }
  }
  EXPECT_GT(ties, 0);  // the reflections through c are exact ties
}

TEST(CompareDistance, DoublesAtExtremeExponentsMatchIntegers) {
  // The filter must defer to the exact stage; compare with the same points as integers.
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> m(-1, 1);
  std::uniform_int_distribution<int> e(-300, 300), z(0, 5);
  auto coord = [&](bool zero_ok) { return zero_ok && z(rng) == 0 ? 0.0 : std::ldexp(m(rng), e(rng)); };
  for (int i = 0; i < 1000 * scale(); ++i) {
    const Point a(coord(true), coord(false), coord(false)), b(coord(true), coord(false), coord(false)),
        c(coord(true), coord(false), coord(false));
    Sign got, want;
    try {
      want = compare_distance(to_exact(a), to_exact(b), to_exact(c));
    } catch (const Undefined&) {
      EXPECT_THROW(compare_distance(a, b, c), Undefined);
      continue;
    }
    got = compare_distance(a, b, c);
    ASSERT_EQ(got, want);
  }
}

}  // namespace
}  // namespace t2
