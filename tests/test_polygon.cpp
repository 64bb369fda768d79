// Polygons: point on segment, segment intersection, signed area, point location (ray casting,
// winding number, Algorithm 2 of seed 000 §5.1), closest point on a segment, ear clipping.
// Oracles are independent: planar computations in exact rationals on Cartesian coordinates,
// barycentric signs for triangles of T², and invariance under projective maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "testing.hpp"

namespace t2 {
namespace {

using testing::scale;

// ---------------------------------------------------------------- rational planar oracles

struct Q2 {
  Rational x, y;
};

template <class T>
Rational rat(const T& v) {
  if constexpr (std::is_same_v<T, double>) {
    return to_rational(v);
  } else {
    return Rational(v);
  }
}

template <class T>
Q2 cart(const BasicPoint<T>& p) {
  Rational x = rat(p.x()) / rat(p.w()), y = rat(p.y()) / rat(p.w());
  return {x, y};
}

Rational cross(const Q2& o, const Q2& a, const Q2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool on_seg_q(const Q2& a, const Q2& b, const Q2& q) {
  if (cross(a, b, q) != 0) return false;
  return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
         q.y <= std::max(a.y, b.y);
}

// Closed segments ab, cd intersect: solve a + s(b-a) = c + t(d-c) in rationals.
bool seg_meet_q(const Q2& a, const Q2& b, const Q2& c, const Q2& d) {
  const Rational rx = b.x - a.x, ry = b.y - a.y, sx = d.x - c.x, sy = d.y - c.y;
  const Rational den = rx * sy - ry * sx;
  if (den == 0) {
    // parallel: intersect only if collinear and overlapping
    return on_seg_q(a, b, c) || on_seg_q(a, b, d) || on_seg_q(c, d, a) || on_seg_q(c, d, b);
  }
  const Rational s = ((c.x - a.x) * sy - (c.y - a.y) * sx) / den;
  const Rational t = ((c.x - a.x) * ry - (c.y - a.y) * rx) / den;
  return s >= 0 && s <= 1 && t >= 0 && t <= 1;
}

template <class T>
std::vector<Q2> cart_all(const BasicPolygon<T>& P) {
  std::vector<Q2> v;
  for (const auto& p : P) v.push_back(cart(p));
  return v;
}

bool simple_q(const std::vector<Q2>& v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (v[i].x == v[j].x && v[i].y == v[j].y) return false;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const Q2 &a = v[i], &b = v[(i + 1) % n], &c = v[j], &d = v[(j + 1) % n];
      if (j == i + 1) {
        if (on_seg_q(a, b, d) || on_seg_q(b, d, a)) return false;
      } else if (i == 0 && j == n - 1) {
        if (on_seg_q(a, b, c) || on_seg_q(c, a, b)) return false;
      } else if (seg_meet_q(a, b, c, d)) {
        return false;
      }
    }
  }
  return true;
}

Rational area2_q(const std::vector<Q2>& v) {  // shoelace, as a fan from v[0]
  Rational s = 0;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) s += cross(v[0], v[i], v[i + 1]);
  return s;
}

// The crossing of the edge ab with the horizontal line of q, right of q, for the half-open rule.
// Returns +1 upward crossing, -1 downward, 0 none.
int crossing_q(const Q2& a, const Q2& b, const Q2& q) {
  const bool ua = a.y > q.y, ub = b.y > q.y;
  if (ua == ub) return 0;
  const Rational x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
  if (x <= q.x) return 0;
  return ub ? 1 : -1;
}

struct Where {
  bool boundary = false;
  int winding = 0;
};

Where where_q(const std::vector<Q2>& v, const Q2& q) {
  Where w;
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (on_seg_q(v[i], v[(i + 1) % n], q)) w.boundary = true;
    w.winding += crossing_q(v[i], v[(i + 1) % n], q);
  }
  return w;
}

// ---------------------------------------------------------------- generators

template <class T>
BasicPoint<T> pt(long w, long x, long y) {
  return BasicPoint<T>(T(w), T(x), T(y));
}

// A random star-shaped polygon on a small integer grid (many collinear triples), simple.
template <class T>
BasicPolygon<T> star_polygon(std::mt19937_64& rng, int n, int grid) {
  std::uniform_real_distribution<double> ang(0, 2 * std::numbers::pi), rad(0.2, 1.0);
  std::bernoulli_distribution cw(0.5);
  for (;;) {
    std::vector<double> a(n);
    for (auto& x : a) x = ang(rng);
    std::sort(a.begin(), a.end());
    if (cw(rng)) std::reverse(a.begin(), a.end());
    BasicPolygon<T> P;
    for (double t : a) {
      const double r = rad(rng) * grid;
      P.push_back(pt<T>(1, std::lround(r * std::cos(t)), std::lround(r * std::sin(t))));
    }
    if (simple_q(cart_all(P)) && area2_q(cart_all(P)) != 0) return P;
  }
}

// A random 3x3 integer matrix with positive determinant; when `force` is given, the image of
// that point lands on Ω (w = 0).
struct Mat {
  std::array<long, 9> m;
  Integer det() const {
    auto I = [&](int i) { return Integer(m[i]); };
    return I(0) * (I(4) * I(8) - I(5) * I(7)) - I(1) * (I(3) * I(8) - I(5) * I(6)) + I(2) * (I(3) * I(7) - I(4) * I(6));
  }
  template <class T>
  BasicPoint<T> operator()(const BasicPoint<T>& p) const {
    auto row = [&](int r) { return T(T(m[3 * r]) * p.w() + T(m[3 * r + 1]) * p.x() + T(m[3 * r + 2]) * p.y()); };
    return BasicPoint<T>(row(0), row(1), row(2));
  }
};

Mat random_map(std::mt19937_64& rng, const std::optional<std::array<long, 3>>& force) {
  std::uniform_int_distribution<long> c(-5, 5);
  for (;;) {
    Mat M;
    for (auto& x : M.m) x = c(rng);
    if (force) {  // first row orthogonal to the forced point: row = force × random
      const auto& f = *force;
      const long g0 = c(rng), g1 = c(rng), g2 = c(rng);
      M.m[0] = f[1] * g2 - f[2] * g1;
      M.m[1] = f[2] * g0 - f[0] * g2;
      M.m[2] = f[0] * g1 - f[1] * g0;
    }
    const Integer d = M.det();
    if (d == 0) continue;
    if (d < 0)
      for (int i = 3; i < 6; ++i) M.m[i] = -M.m[i];  // flip a row other than w
    return M;
  }
}

template <class T>
BasicPolygon<T> apply(const Mat& M, const BasicPolygon<T>& P) {
  BasicPolygon<T> out;
  for (const auto& p : P) out.push_back(M(p));
  return out;
}

template <class T>
BasicPolygon<T> antipodes(const BasicPolygon<T>& P) {
  BasicPolygon<T> out;
  for (const auto& p : P) out.push_back(antipode(p));
  return out;
}

template <class T>
class PolygonTyped : public ::testing::Test {};
using Coordinates = ::testing::Types<double, Integer>;
TYPED_TEST_SUITE(PolygonTyped, Coordinates);

// ---------------------------------------------------------------- on_segment, intersection

TYPED_TEST(PolygonTyped, OnSegmentMatchesRationalOracleAndWorksAcrossOmega) {
  using T = TypeParam;
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<long> c(-4, 4);
  for (int i = 0; i < 3000 * scale(); ++i) {
    const auto a = pt<T>(1, c(rng), c(rng)), b = pt<T>(1, c(rng), c(rng)), q = pt<T>(1, c(rng), c(rng));
    ASSERT_EQ(on_segment(a, b, q), on_seg_q(cart(a), cart(b), cart(q)));
    // Positions on a segment survive a projective map, also one that sends a point to Ω.
    const Mat M = random_map(rng, std::array<long, 3>{1, c(rng), c(rng)});
    ASSERT_EQ(on_segment(M(a), M(b), M(q)), on_seg_q(cart(a), cart(b), cart(q)));
    // ...and the antipode of q is never on a front segment.
    ASSERT_FALSE(on_segment(a, b, antipode(q)));
  }
  EXPECT_THROW(on_segment(pt<T>(1, 0, 0), pt<T>(-1, 0, 0), pt<T>(0, 1, 0)), Undefined);
  // The segment from the front origin to the back point [-1,-1,0] passes Ω at a + b = [0,-1,0].
  EXPECT_TRUE(on_segment(pt<T>(1, 0, 0), pt<T>(-1, -1, 0), pt<T>(0, -1, 0)));
  EXPECT_FALSE(on_segment(pt<T>(1, 0, 0), pt<T>(-1, -1, 0), pt<T>(0, 1, 0)));
}

TYPED_TEST(PolygonTyped, SegmentIntersectionMatchesOracleAndNeedsTheFifthOrientation) {
  using T = TypeParam;
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<long> c(-3, 3);
  int yes = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    const auto a = pt<T>(1, c(rng), c(rng)), b = pt<T>(1, c(rng), c(rng));
    const auto d0 = pt<T>(1, c(rng), c(rng)), d1 = pt<T>(1, c(rng), c(rng));
    const bool want = seg_meet_q(cart(a), cart(b), cart(d0), cart(d1));
    yes += want;
    ASSERT_EQ(segments_intersect(a, b, d0, d1), want);
    const Mat M = random_map(rng, std::nullopt);
    ASSERT_EQ(segments_intersect(M(a), M(b), M(d0), M(d1)), want);
    // A front segment never meets a back one: the plain four-orientation test would say it does
    // whenever the front segments cross.
    ASSERT_FALSE(segments_intersect(a, b, antipode(d0), antipode(d1)));
  }
  EXPECT_GT(yes, 300);
}

// ---------------------------------------------------------------- area

TYPED_TEST(PolygonTyped, SignedAreaMatchesShoelaceInRationals) {
  using T = TypeParam;
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<int> nn(3, 12);
  std::uniform_int_distribution<long> wgt(1, 7);
  for (int i = 0; i < 500 * scale(); ++i) {
    auto P = star_polygon<T>(rng, nn(rng), 50);
    // Random positive weights: the same points, other coordinates.
    for (auto& p : P) {
      const long k = wgt(rng);
      p = BasicPoint<T>(T(T(k) * p.w()), T(T(k) * p.x()), T(T(k) * p.y()));
    }
    const Rational want = area2_q(cart_all(P));
    ASSERT_EQ(orientation(P), sign_of(want));
    ASSERT_EQ(orientation(antipodes(P)), -sign_of(want));
    if constexpr (std::is_same_v<T, Integer>) {
      ASSERT_EQ(signed_area(P), want);
      ASSERT_EQ(signed_area(antipodes(P)), Rational(-want));
    } else {
      // double: rounded; the error is a few ulps of the sum of |terms| (at most 4·50² each).
      const double got = signed_area(P);
      ASSERT_LE(std::fabs(got - want.get_d()), 1e-9 * 4 * 2500 * double(P.size()));
      ASSERT_EQ(signed_area(antipodes(P)), -got);
    }
  }
  // Integer input with w = 1: the exact integer area.
  const BasicPolygon<T> sq{pt<T>(1, 0, 0), pt<T>(1, 3, 0), pt<T>(1, 3, 2), pt<T>(1, 0, 2)};
  EXPECT_EQ(Rational(signed_area(sq)), Rational(12));
  const BasicPolygon<T> across{pt<T>(1, 0, 0), pt<T>(0, 1, 0), pt<T>(1, 0, 1)};
  EXPECT_THROW(signed_area(across), Undefined);
  const BasicPolygon<T> both{pt<T>(1, 0, 0), pt<T>(1, 1, 0), pt<T>(-1, 0, 1)};
  EXPECT_THROW(orientation(both), Undefined);
}

// ---------------------------------------------------------------- point in polygon

// Every point of a small grid (and half-grid), many of them on edges, on vertices, on lines
// through vertices: ray casting, winding number and Algorithm 2 against the rational oracle.
TYPED_TEST(PolygonTyped, PlanarLocationAgreesWithOracleOnDegenerateGrids) {
  using T = TypeParam;
  std::mt19937_64 rng(14);
  std::uniform_int_distribution<int> nn(3, 10);
  std::uniform_int_distribution<long> c(-13, 13);
  int inside = 0, boundary = 0, outside = 0;
  for (int i = 0; i < 150 * scale(); ++i) {
    const auto P = star_polygon<T>(rng, nn(rng), 6);
    const auto v = cart_all(P);
    const Sign o = sign_of(area2_q(v));
    for (int k = 0; k < 40; ++k) {
      const auto q = pt<T>(2, c(rng), c(rng));  // half-integer grid
      const Where w = where_q(v, cart(q));
      if (w.boundary) {
        ++boundary;
        ASSERT_EQ(locate_by_ray_casting(P, q), ZERO);
        ASSERT_EQ(locate(P, q), ZERO);
        ASSERT_THROW(winding_number(P, q), Undefined);
        continue;
      }
      ASSERT_TRUE(w.winding == 0 || w.winding == o) << w.winding;  // simple: 0 or ±1
      const Sign in = w.winding != 0 ? POSITIVE : NEGATIVE;
      (in == POSITIVE ? inside : outside)++;
      ASSERT_EQ(locate_by_ray_casting(P, q), in);
      ASSERT_EQ(winding_number(P, q), w.winding);
      ASSERT_EQ(locate(P, q), in * o);  // positive side = inside iff counter-clockwise
      ASSERT_EQ(locate(P, antipode(q)), -o);  // back points are outside a front polygon
    }
    // The vertices themselves, and their antipodes (q = ¬p0 is the seed's undefined walk).
    for (const auto& p : P) {
      ASSERT_EQ(locate(P, p), ZERO);
      ASSERT_EQ(locate(P, antipode(p)), -o);
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(boundary, 100);
  EXPECT_GT(outside, 100);
}

// Orientation-preserving projective maps send the polygon across Ω and onto the back side (one
// vertex is forced onto Ω); the side of P and the winding number must not change.
TYPED_TEST(PolygonTyped, LocationInT2IsInvariantUnderProjectiveMaps) {
  using T = TypeParam;
  std::mt19937_64 rng(15);
  std::uniform_int_distribution<int> nn(3, 9);
  std::uniform_int_distribution<long> c(-13, 13);
  int crossing_omega = 0;
  for (int i = 0; i < 150 * scale(); ++i) {
    const auto P = star_polygon<T>(rng, nn(rng), 6);
    const auto v = cart_all(P);
    const Sign o = sign_of(area2_q(v));
    std::uniform_int_distribution<std::size_t> pick(0, P.size() - 1);
    const auto& f = P[pick(rng)];
    const long fx = std::lround(rat(f.x()).get_d()), fy = std::lround(rat(f.y()).get_d());
    const Mat M = random_map(rng, std::array<long, 3>{1, fx, fy});
    const auto MP = apply(M, P);
    bool front = false, back = false;
    for (const auto& p : MP) (side_of(p) == Side::front ? front : back) |= side_of(p) != Side::infinity;
    crossing_omega += front && back;
    for (int k = 0; k < 30; ++k) {
      const auto q = pt<T>(2, c(rng), c(rng));
      const Where w = where_q(v, cart(q));
      const Sign want = w.boundary ? ZERO : (w.winding != 0 ? o : -o);
      ASSERT_EQ(locate(MP, M(q)), want);
      ASSERT_EQ(locate(MP, antipode(M(q))), -o);
      ASSERT_EQ(locate(antipodes(MP), antipode(M(q))), -want);  // the antipodal map reverses sides
      if (!w.boundary) {
        ASSERT_EQ(winding_number(MP, M(q)), w.winding);
      }
    }
    for (const auto& p : MP) ASSERT_EQ(locate(MP, antipode(p)), -o);
  }
  EXPECT_GT(crossing_omega, 20);
}

// Random triangles of T² (any signs, any sides): the positive combinations of the vertices
// are the small triangle; barycentric signs are the oracle.
TYPED_TEST(PolygonTyped, TrianglesOfT2AgreeWithBarycentricSigns) {
  using T = TypeParam;
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<long> c(-3, 3);
  for (int i = 0; i < 5000 * scale(); ++i) {
    const auto a = pt<T>(c(rng), c(rng), c(rng) | 1), b = pt<T>(c(rng), c(rng) | 1, c(rng)),
               d = pt<T>(c(rng) | 1, c(rng), c(rng));
    const Sign D = orient(a, b, d);
    if (D == ZERO) continue;
    const BasicPolygon<T> P{a, b, d};
    const auto q = pt<T>(c(rng), c(rng), c(rng) | 1);
    const Sign sa = orient(q, b, d) * D, sb = orient(a, q, d) * D, sc = orient(a, b, q) * D;
    Sign want;
    if (sa > 0 && sb > 0 && sc > 0) want = D;
    else if (sa >= 0 && sb >= 0 && sc >= 0) want = ZERO;
    else want = -D;
    ASSERT_EQ(locate(P, q), want);
  }
  // The triangle e0 e1 e2 reaches Ω; [1,1,1] is inside, its antipode is not.
  const BasicPolygon<T> E{pt<T>(1, 0, 0), pt<T>(0, 1, 0), pt<T>(0, 0, 1)};
  EXPECT_EQ(locate(E, pt<T>(1, 1, 1)), POSITIVE);
  EXPECT_EQ(locate(E, pt<T>(-1, -1, -1)), NEGATIVE);
  EXPECT_EQ(locate(E, pt<T>(0, 1, 1)), ZERO);  // on the edge e1e2, which lies on Ω
  EXPECT_EQ(winding_number(E, pt<T>(1, 1, 1)), 1);
  EXPECT_EQ(winding_number(E, pt<T>(-1, -1, -1)), -1);  // seen from ¬q the turn is clockwise
}

TYPED_TEST(PolygonTyped, SeedSpecialCases) {
  using T = TypeParam;
  // p0 is a straight vertex and q lies on the line of its two edges, beyond p1: the seed's
  // s ← (on_segment − 1)·t gives 0 ("on the boundary"), but q is outside.
  const BasicPolygon<T> P{pt<T>(1, 1, 0), pt<T>(1, 2, 0), pt<T>(1, 2, 2), pt<T>(1, 0, 2), pt<T>(1, 0, 0)};
  EXPECT_EQ(locate(P, pt<T>(1, 3, 0)), NEGATIVE);
  EXPECT_EQ(locate(P, pt<T>(1, -1, 0)), NEGATIVE);
  EXPECT_EQ(locate(P, pt<T>(2, 3, 0)), ZERO);
  // q = ¬p0: the walk p0→q is undefined; another vertex is used.
  EXPECT_EQ(locate(P, pt<T>(-1, -1, 0)), NEGATIVE);
  // The walk from p0 runs along the edge p4p0 and through vertex p3's line.
  EXPECT_EQ(locate(P, pt<T>(1, 1, 1)), POSITIVE);
  EXPECT_EQ(locate(P, pt<T>(1, 1, 3)), NEGATIVE);
  // A reflex p0: the L-shape.
  const BasicPolygon<T> L{pt<T>(1, 1, 1), pt<T>(1, 1, 2), pt<T>(1, 0, 2), pt<T>(1, 0, 0), pt<T>(1, 2, 0), pt<T>(1, 2, 1)};
  EXPECT_EQ(orient(L[5], L[0], L[1]), NEGATIVE);
  EXPECT_EQ(locate(L, pt<T>(2, 1, 1)), POSITIVE);
  EXPECT_EQ(locate(L, pt<T>(2, 3, 3)), NEGATIVE);
  EXPECT_EQ(locate(L, pt<T>(1, 0, 1)), ZERO);
  EXPECT_THROW(locate(BasicPolygon<T>{pt<T>(1, 0, 0), pt<T>(1, 1, 0)}, pt<T>(1, 0, 1)), Undefined);
  EXPECT_THROW(locate_by_ray_casting(P, pt<T>(-1, 0, 0)), Undefined);
}

// ---------------------------------------------------------------- closest point

TYPED_TEST(PolygonTyped, ClosestPointMatchesRationalProjection) {
  using T = TypeParam;
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<long> c(-20, 20), w(1, 5);
  int interior = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    const auto a = pt<T>(w(rng), c(rng), c(rng)), b = pt<T>(w(rng), c(rng), c(rng)), q = pt<T>(w(rng), c(rng), c(rng));
    const Q2 A = cart(a), B = cart(b), Qp = cart(q);
    Q2 want = A;
    const Rational len = (B.x - A.x) * (B.x - A.x) + (B.y - A.y) * (B.y - A.y);
    if (len != 0) {
      Rational t = ((Qp.x - A.x) * (B.x - A.x) + (Qp.y - A.y) * (B.y - A.y)) / len;
      if (t < 0) t = 0;
      if (t > 1) t = 1;
      interior += (t > 0 && t < 1);
      want = {A.x + t * (B.x - A.x), A.y + t * (B.y - A.y)};
    }
    const auto got = closest_point_on_segment(a, b, q);
    ASSERT_EQ(side_of(got), Side::front);
    const Q2 g = cart(got);
    if constexpr (std::is_same_v<T, Integer>) {
      ASSERT_TRUE(g.x == want.x && g.y == want.y);
    } else {
      ASSERT_NEAR(g.x.get_d(), want.x.get_d(), 1e-12);
      ASSERT_NEAR(g.y.get_d(), want.y.get_d(), 1e-12);
    }
    // On the back side: the antipode of the answer.
    const auto back = closest_point_on_segment(antipode(a), antipode(b), antipode(q));
    ASSERT_EQ(side_of(back), Side::back);
    ASSERT_TRUE(cart(back).x == g.x && cart(back).y == g.y);
  }
  EXPECT_GT(interior, 500);
  EXPECT_THROW(closest_point_on_segment(pt<T>(1, 0, 0), pt<T>(0, 1, 0), pt<T>(1, 1, 1)), Undefined);
  EXPECT_THROW(closest_point_on_segment(pt<T>(1, 0, 0), pt<T>(1, 1, 0), pt<T>(-1, 1, 1)), Undefined);
}

// ---------------------------------------------------------------- ear clipping

TYPED_TEST(PolygonTyped, EarClippingGivesNMinus2TrianglesCoveringThePolygon) {
  using T = TypeParam;
  std::mt19937_64 rng(18);
  std::uniform_int_distribution<int> nn(3, 16);
  std::bernoulli_distribution flip(0.3);
  for (int i = 0; i < 300 * scale(); ++i) {
    auto P = star_polygon<T>(rng, nn(rng), 8);
    if (flip(rng)) P = antipodes(P);  // a back-side polygon
    const auto v = cart_all(P);
    const std::size_t n = P.size();
    const Sign o = orientation(P);
    const auto tris = ear_clipping(P);
    ASSERT_EQ(tris.size(), n - 2);
    Rational sum = 0;
    std::vector<std::array<std::size_t, 2>> diagonals;
    for (const auto& t : tris) {
      ASSERT_TRUE(t[0] < n && t[1] < n && t[2] < n && t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
      const Sign to = orient(P[t[0]], P[t[1]], P[t[2]]);
      ASSERT_NE(to, -o);
      sum += cross(v[t[0]], v[t[1]], v[t[2]]);
      if (to == ZERO) continue;
      // inside P: its centroid is inside (rational ray casting) and no side properly crosses an edge
      const Q2 g{(v[t[0]].x + v[t[1]].x + v[t[2]].x) / 3, (v[t[0]].y + v[t[1]].y + v[t[2]].y) / 3};
      const Where w = where_q(v, g);
      ASSERT_FALSE(w.boundary);
      ASSERT_NE(w.winding, 0);
      for (int e = 0; e < 3; ++e) {
        const Q2 &a = v[t[e]], &b = v[t[(e + 1) % 3]];
        for (std::size_t j = 0; j < n; ++j) {
          const Q2 &c = v[j], &d = v[(j + 1) % n];
          if (sign_of(cross(a, b, c)) * sign_of(cross(a, b, d)) < 0 && sign_of(cross(c, d, a)) * sign_of(cross(c, d, b)) < 0)
            FAIL() << "a triangle side crosses an edge";
        }
      }
    }
    // Planar areas (the back side mirrors the orientation, not the Cartesian area).
    ASSERT_EQ(sum, area2_q(v));
  }
  EXPECT_THROW(ear_clipping(BasicPolygon<T>{pt<T>(1, 0, 0), pt<T>(1, 1, 0), pt<T>(0, 1, 1)}), Undefined);
}

}  // namespace
}  // namespace t2
