// Affine and projective maps of T² (seed 000 §4.2) applied to every primitive, for double
// and Integer coordinates: orientation and sides under negative determinants and negative
// w-scales, lines by the adjugate, composition, inverse, and the images of segments, rays,
// vectors, directions, triangles, iso-rectangles and circles against independent oracles.
#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "t2/kernel/affine.hpp"
#include "test_prim.hpp"

namespace t2 {
namespace {

using testing::combo;
using testing::coords;
using testing::det_oracle;
using testing::pt;
using testing::same_point;
using testing::scale;
using testing::Small;

template <class T>
class AffineT : public ::testing::Test {};
TYPED_TEST_SUITE(AffineT, testing::CoordinateTypes);

template <class T>
using Mat = typename BasicAffine<T>::Matrix;

// A random invertible map; affine ones have first row [m, 0, 0].
template <class T>
BasicAffine<T> random_map(Small& g, bool affine) {
  for (;;) {
    Mat<T> m;
    std::array<std::array<Integer, 3>, 3> im;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const long v = (affine && i == 0 && j > 0) ? 0 : g();
        m[i][j] = T(v);
        im[i][j] = v;
      }
    if (det_oracle(im[0], im[1], im[2]) == 0) continue;
    return BasicAffine<T>(m);
  }
}
template <class T>
Integer det_of(const BasicAffine<T>& a) {
  std::array<Integer, 3> r[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = Integer(a.m(i, j));
  return det_oracle(r[0], r[1], r[2]);
}
template <class T>
BasicPoint<T> random_point(Small& g) {
  return pt<T>(g.triple());
}

TYPED_TEST(AffineT, OrientationAndSides) {
  using T = TypeParam;
  Small g(51, 5);
  for (int i = 0; i < 1500 * scale(); ++i) {
    const auto M = random_map<T>(g, i % 2 == 0);
    const Sign sd = sign_of(det_of(M));
    ASSERT_EQ(M.determinant_sign(), sd);
    const auto p = random_point<T>(g), q = random_point<T>(g), r = random_point<T>(g);
    const auto P = coords(p), Q = coords(q), R = coords(r);
    ASSERT_EQ(orient(transform(M, p), transform(M, q), transform(M, r)), sd * sign_of(det_oracle(P, Q, R)));
    if (M.is_affine()) {
      // A negative w-scale swaps front and back; Ω stays Ω.
      const Sign m = sign_of(Integer(M.m(0, 0)));
      ASSERT_EQ(static_cast<int>(side_of(transform(M, p))), m * static_cast<int>(side_of(p)));
    }
  }
  // −I is the antipodal map: determinant −1.
  const auto minus = BasicAffine<T>::scaling(T(-1), T(-1));
  EXPECT_EQ(minus.determinant_sign(), NEGATIVE);
  EXPECT_EQ(transform(minus, pt<T>(1, 2, 3)), pt<T>(-1, -2, -3));
  EXPECT_THROW(BasicAffine<T>::scaling(T(0)), Undefined);
}

TYPED_TEST(AffineT, LinesKeepTheirSidesThroughTheAdjugate) {
  using T = TypeParam;
  Small g(52, 5);
  for (int i = 0; i < 1500 * scale(); ++i) {
    const auto M = random_map<T>(g, i % 3 == 0);
    const auto p = random_point<T>(g), q = random_point<T>(g);
    if (same_point(coords(p), coords(q)) || same_point(coords(p), coords(antipode(q)))) continue;
    const auto l = join(p, q);
    const auto l2 = transform(M, l);
    for (int k = 0; k < 5; ++k) {
      const auto r = random_point<T>(g);
      ASSERT_EQ(side(l2, transform(M, r)), side(l, r));
    }
    const auto j = join(transform(M, p), transform(M, q));
    ASSERT_EQ(l2, M.determinant_sign() == POSITIVE ? j : opposite(j));
  }
}

TYPED_TEST(AffineT, CompositionAndInverse) {
  using T = TypeParam;
  Small g(53, 4);
  for (int i = 0; i < 1000 * scale(); ++i) {
    const auto A = random_map<T>(g, i % 2 == 0), B = random_map<T>(g, false);
    const auto p = random_point<T>(g);
    ASSERT_EQ(transform(A * B, p), transform(A, transform(B, p)));
    ASSERT_EQ(transform(inverse(A), transform(A, p)), p);  // p itself, not ¬p
    ASSERT_EQ(transform(A, transform(inverse(A), p)), p);
  }
  const auto I = BasicAffine<T>::identity();
  EXPECT_EQ(transform(I, pt<T>(2, 3, 4)), pt<T>(2, 3, 4));
  EXPECT_EQ(to_string(BasicAffine<T>::translation(T(2), T(3))), "affine[[1, 0, 0], [2, 1, 0], [3, 0, 1]]");
}

TYPED_TEST(AffineT, TranslationsRotationsScalings) {
  using T = TypeParam;
  using A = BasicAffine<T>;
  EXPECT_EQ(transform(A::translation(T(2), T(3)), pt<T>(1, 1, 1)), pt<T>(1, 3, 4));
  EXPECT_EQ(transform(A::scaling(T(3), T(2)), pt<T>(1, 2, 4)), pt<T>(2, 6, 12));
  EXPECT_EQ(transform(A::rotation(T(4), T(3), T(5)), pt<T>(1, 1, 0)), pt<T>(5, 3, 4));
  EXPECT_EQ(transform(A::rotation(T(1), T(0), T(1)), pt<T>(1, 1, 0)), pt<T>(1, 0, 1));
  EXPECT_THROW(A::rotation(T(1), T(1), T(1)), BadInput);
  EXPECT_THROW(A::rotation(T(4), T(3), T(-5)), BadInput);
  if constexpr (std::is_same_v<T, Integer>) {
    EXPECT_EQ(transform(A::rotation(BasicDirection<T>(T(3), T(4))), pt<T>(1, 1, 0)), pt<T>(5, 3, 4));
    EXPECT_THROW(A::rotation(BasicDirection<T>(T(1), T(1))), BadInput);
  } else {
    // Rounded cosine and sine: 3/5 and 4/5 are not doubles.
    const auto r34 = transform(A::rotation(Direction(3, 4)), Point(1, 1, 0));
    EXPECT_NEAR(r34.x() / r34.w(), 0.6, 1e-15);
    EXPECT_NEAR(r34.y() / r34.w(), 0.8, 1e-15);
    const auto img = transform(A::rotation(Direction(1, 1)), Point(1, 1, 0));
    EXPECT_NEAR(img.x(), img.y(), 1e-15);
  }
  // Translation by vector(p, q) maps p to q, whatever the sides.
  Small g(54, 9);
  for (int i = 0; i < 1000 * scale(); ++i) {
    const auto p = random_point<T>(g), q = random_point<T>(g);
    if (p.w() == 0 || q.w() == 0 || p == antipode(q)) continue;
    ASSERT_EQ(transform(A::translation(vector(p, q)), p), q);
  }
  EXPECT_THROW(A::translation(BasicVector<T>(T(0), T(1), T(0))), Undefined);
}

TYPED_TEST(AffineT, SegmentsRaysVectorsDirectionsTriangles) {
  using T = TypeParam;
  Small g(55, 5);
  std::uniform_int_distribution<long> co(0, 4);
  for (int i = 0; i < 1000 * scale(); ++i) {
    const bool affine = i % 2 == 0;
    const auto M = random_map<T>(g, affine);
    const auto p = random_point<T>(g), q = random_point<T>(g);
    const auto P = coords(p), Q = coords(q);
    if (same_point(P, Q) || same_point(P, coords(antipode(q)))) continue;
    // Points on the segment stay on the image segment.
    const auto r = pt<T>(combo(co(g.rng), P, co(g.rng) + 1, Q));
    const auto s2 = transform(M, BasicSegment<T>(p, q));
    ASSERT_TRUE(contains(s2, transform(M, r)));
    ASSERT_FALSE(contains(s2, transform(M, antipode(r))));
    // Triangles: orientation times sign(det), containment kept.
    const auto c = random_point<T>(g);
    if (det_oracle(P, Q, coords(c)) != 0) {
      const BasicTriangle<T> t(p, q, c);
      const auto t2 = transform(M, t);
      ASSERT_EQ(orientation(t2), M.determinant_sign() * orientation(t));
      const auto inside = pt<T>(combo(1, combo(co(g.rng) + 1, P, co(g.rng) + 1, Q), co(g.rng) + 1, coords(c)));
      ASSERT_TRUE(contains(t2, transform(M, inside)));
    }
    if (!M.is_affine()) {
      if (p.w() != 0 || q.w() != 0) {
        EXPECT_THROW(transform(M, direction(p, q)), Undefined);
      }
      continue;
    }
    // Directions and vectors commute with the constructions from two points.
    if (p.w() != 0 || q.w() != 0) {
      ASSERT_EQ(transform(M, direction(p, q)), direction(transform(M, p), transform(M, q)));
    }
    if (p.w() != 0) {
      ASSERT_EQ(transform(M, vector(p, q)), vector(transform(M, p), transform(M, q)));
      const auto ray = BasicRay<T>::through(p, q);
      const auto ray2 = transform(M, ray);
      ASSERT_EQ(ray2, BasicRay<T>::through(transform(M, p), transform(M, q)));
      ASSERT_EQ(contains(ray2, transform(M, q)), contains(ray, q));
    }
  }
}

TYPED_TEST(AffineT, IsoRectanglesUnderAxisKeepingMaps) {
  using T = TypeParam;
  Small g(56, 5);
  int n = 0;
  for (int i = 0; i < 1000 * scale(); ++i) {
    // m, translation, and a diagonal or anti-diagonal linear part (all non-zero).
    long v[5];
    for (auto& x : v)
      do x = g();
      while (x == 0);
    const bool swap = i % 2;
    Mat<T> m = {{{T(v[0]), T(0), T(0)},
                 {T(g()), swap ? T(0) : T(v[1]), swap ? T(v[2]) : T(0)},
                 {T(g()), swap ? T(v[3]) : T(0), swap ? T(0) : T(v[4])}}};
    const BasicAffine<T> M(m);
    auto at = g.triple();
    if (at[0] == 0) continue;
    auto ext = [&](int k) {
      if (k % 5 == 3) return BasicT1<T>::plus_infinity();
      if (k % 5 == 4) return BasicT1<T>::minus_infinity();
      long w;
      do w = g();
      while (w <= 0);
      return BasicT1<T>(T(w), T(g()));
    };
    const BasicIsoRect<T> r(pt<T>(at), ext(i / 2), ext(i / 10), (i / 3) % 2 ? POSITIVE : NEGATIVE);
    const auto r2 = transform(M, r);
    ASSERT_EQ(r2.orientation(), M.determinant_sign() * r.orientation());
    // The corners of the image are the images of the corners (as a set).
    for (int k = 0; k < 4; ++k) {
      const auto img = transform(M, r.corner(k));
      bool found = false;
      for (int j = 0; j < 4; ++j) found = found || r2.corner(j) == img;
      ASSERT_TRUE(found) << to_string(r) << " -> " << to_string(r2);
    }
    // Boxes map like rectangles.
    const auto b2 = transform(M, bbox(r));
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(contains(b2, transform(M, r.corner(k))));
    // The traversal of the image turns as its orientation says (non-flat rectangles).
    if (r.natural() != ZERO) {
      ASSERT_EQ(orient(r2.vertex(0), r2.vertex(1), r2.vertex(3)), r2.orientation());
    }
    ++n;
  }
  EXPECT_GT(n, 500);
  const BasicIsoRect<T> r(pt<T>(1, 0, 0), BasicT1<T>(T(1), T(1)), BasicT1<T>(T(1), T(1)));
  EXPECT_THROW(transform(BasicAffine<T>::rotation(T(4), T(3), T(5)), r), Undefined);
  EXPECT_NO_THROW(transform(BasicAffine<T>::rotation(T(1), T(0), T(1)), r));
}

TYPED_TEST(AffineT, CirclesUnderSimilarities) {
  using T = TypeParam;
  using A = BasicAffine<T>;
  Small g(57, 9);
  const A sims[] = {A::rotation(T(4), T(3), T(5)) * A::translation(T(2), T(-1)),
                    A::scaling(T(-3), T(2)) * A::rotation(T(-12), T(5), T(13)),
                    A(Mat<T>{{{T(1), T(0), T(0)}, {T(0), T(0), T(1)}, {T(0), T(1), T(0)}}}),  // reflection
                    A::scaling(T(2), T(-1)) * A::translation(T(1), T(1))};  // swaps the sides
  int n = 0;
  for (int i = 0; i < 1000 * scale(); ++i) {
    const auto& M = sims[i % 4];
    auto a = g.triple(), b = g.triple(), c = g.triple();
    if (a[0] == 0 || b[0] == 0 || c[0] == 0) continue;
    if ((b[0] > 0) != (a[0] > 0)) b = {-b[0], -b[1], -b[2]};
    if ((c[0] > 0) != (a[0] > 0)) c = {-c[0], -c[1], -c[2]};
    if (det_oracle(coords(pt<T>(a)), coords(pt<T>(b)), coords(pt<T>(c))) == 0) continue;
    const auto circ = circle_through(pt<T>(a), pt<T>(b), pt<T>(c));
    const auto img = transform(M, circ);
    const auto want = circle_through(transform(M, pt<T>(a)), transform(M, pt<T>(b)), transform(M, pt<T>(c)));
    ASSERT_EQ(img.center(), want.center());
    ASSERT_EQ(img.orientation(), want.orientation());
    ASSERT_EQ(img.orientation(), M.determinant_sign() * circ.orientation());
    ASSERT_EQ(radius_kind(img), RadiusKind::finite);
    ++n;
  }
  EXPECT_GT(n, 300);
  const BasicCircle<T> c(pt<T>(1, 0, 0), pt<T>(1, 1, 0));
  EXPECT_THROW(transform(A::scaling(T(2)) * A(Mat<T>{{{T(1), T(0), T(0)}, {T(0), T(2), T(0)}, {T(0), T(0), T(1)}}}), c),
               Undefined);
  EXPECT_THROW(transform(A(Mat<T>{{{T(1), T(1), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}}), c), Undefined);
}

}  // namespace
}  // namespace t2
