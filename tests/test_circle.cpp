// Circles of T² (seed 000 §4.1.9): constructors and their definedness rules, radius kinds,
// for double and Integer coordinates, against rational Cartesian oracles.
#include <gtest/gtest.h>

#include "t2/kernel/circle.hpp"
#include "test_prim.hpp"

namespace t2 {
namespace {

using testing::combo;
using testing::coords;
using testing::det_oracle;
using testing::pos;
using testing::pt;
using testing::scale;
using testing::Small;
using testing::sq;

template <class T>
class CircleT : public ::testing::Test {};
TYPED_TEST_SUITE(CircleT, testing::CoordinateTypes);


TYPED_TEST(CircleT, RadiusKinds) {
  using T = TypeParam;
  using C = BasicCircle<T>;
  EXPECT_EQ(radius_kind(C(pt<T>(1, 0, 0), pt<T>(1, 1, 0))), RadiusKind::finite);
  EXPECT_EQ(radius_kind(C(pt<T>(-1, 0, 0), pt<T>(-1, 1, 0))), RadiusKind::finite);
  EXPECT_EQ(radius_kind(C(pt<T>(1, 0, 0), pt<T>(-1, 1, 0))), RadiusKind::beyond_infinity);
  EXPECT_EQ(radius_kind(C(pt<T>(-1, 0, 0), pt<T>(1, 1, 0))), RadiusKind::beyond_infinity);
  EXPECT_EQ(radius_kind(C(pt<T>(0, 1, 0), pt<T>(1, 1, 0))), RadiusKind::infinite);
  EXPECT_EQ(radius_kind(C(pt<T>(1, 0, 0), pt<T>(0, 1, 0))), RadiusKind::infinite);
  EXPECT_EQ(radius_kind(C(pt<T>(-1, 0, 0), pt<T>(0, 1, 0))), RadiusKind::infinite);
  EXPECT_THROW(C(pt<T>(0, 1, 0), pt<T>(0, 0, 1)), Undefined);
  EXPECT_STREQ(to_string(RadiusKind::beyond_infinity), "beyond_infinity");
  EXPECT_THROW(C(pt<T>(1, 1, 0), pt<T>(1, 0, 1), ZERO), BadInput);
  EXPECT_EQ(opposite(C(pt<T>(1, 0, 0), pt<T>(1, 1, 0))).orientation(), NEGATIVE);
  EXPECT_NO_THROW(C(pt<T>(1, 2, 3), pt<T>(1, 2, 3)));    // radius zero
  EXPECT_NO_THROW(C(pt<T>(1, 2, 3), pt<T>(-1, -2, -3)));  // beyond infinity, "radius zero"
}

TYPED_TEST(CircleT, DiameterOnOneSideHasTheMidpointAsCentre) {
  using T = TypeParam;
  Small g(41, 30);
  for (int i = 0; i < 2000 * scale(); ++i) {
    auto pa = g.triple(), qa = g.triple();
    if (pa[0] == 0 || qa[0] == 0) continue;
    if ((pa[0] > 0) != (qa[0] > 0)) qa = {-qa[0], -qa[1], -qa[2]};
    const auto c = circle_from_diameter(pt<T>(pa), pt<T>(qa));
    const auto C = coords(c.center()), P = coords(pt<T>(pa)), Q = coords(pt<T>(qa));
    ASSERT_EQ(sgn(C[0]), sgn(P[0]));
    const auto cc = pos(C), cp = pos(P), cq = pos(Q);
    ASSERT_EQ(cc[0] * 2, cp[0] + cq[0]);
    ASSERT_EQ(cc[1] * 2, cp[1] + cq[1]);
    ASSERT_EQ(radius_kind(c), RadiusKind::finite);
    ASSERT_EQ(c.boundary_point(), pt<T>(pa));
  }
}

TYPED_TEST(CircleT, DiameterAcrossInfinityIsNeverDefined) {
  using T = TypeParam;
  // The seed allows it when p and q are equally far from pq ∩ Ω; that never happens (see
  // circle.hpp). Check the exact test on many pairs, including far and near ones.
  Small g(42, 50);
  int tried = 0;
  for (int i = 0; i < 2000 * scale(); ++i) {
    auto pa = g.triple(), qa = g.triple();
    if (pa[0] == 0 || qa[0] == 0) continue;
    if ((pa[0] > 0) == (qa[0] > 0)) qa = {-qa[0], -qa[1], -qa[2]};
    const auto P = coords(pt<T>(pa)), Q = coords(pt<T>(qa));
    if (P[0] * Q[1] == P[1] * Q[0] && P[0] * Q[2] == P[2] * Q[0] && P[1] * Q[2] == P[2] * Q[1]) continue;
    ++tried;
    ASSERT_THROW(circle_from_diameter(pt<T>(pa), pt<T>(qa)), Undefined);
  }
  EXPECT_GT(tried, 1000);
  EXPECT_THROW(circle_from_diameter(pt<T>(1, 0, 0), pt<T>(0, 1, 0)), Undefined);
  EXPECT_THROW(circle_from_diameter(pt<T>(1, 1, 0), pt<T>(-1, -1, 0)), Undefined);
}

TYPED_TEST(CircleT, CircumcircleIsEquidistantOnTheSameSide) {
  using T = TypeParam;
  Small g(43, 20);
  int n = 0;
  for (int i = 0; i < 2000 * scale(); ++i) {
    std::array<long, 3> v[3];
    for (auto& a : v) {
      do a = g.triple();
      while (a[0] == 0);
      if (a[0] < 0 && (i % 2) == 0) a = {-a[0], -a[1], -a[2]};
      if (a[0] > 0 && (i % 2) == 1) a = {-a[0], -a[1], -a[2]};
    }
    const auto A = coords(pt<T>(v[0])), B = coords(pt<T>(v[1])), Cc = coords(pt<T>(v[2]));
    if (det_oracle(A, B, Cc) == 0) continue;
    const auto c = circle_through(pt<T>(v[0]), pt<T>(v[1]), pt<T>(v[2]));
    const auto C = coords(c.center());
    ASSERT_EQ(sgn(C[0]), sgn(A[0]));  // on the points' side
    const auto cc = pos(C);
    const Rational r = sq(cc, pos(A));
    ASSERT_EQ(sq(cc, pos(B)), r);
    ASSERT_EQ(sq(cc, pos(Cc)), r);
    ASSERT_EQ(c.orientation(), sign_of(det_oracle(A, B, Cc)));
    ASSERT_EQ(radius_kind(c), RadiusKind::finite);
    ++n;
  }
  EXPECT_GT(n, 1000);
}

TYPED_TEST(CircleT, ThreePointsOnBothSidesAreDefinedOnlyWhenCollinear) {
  using T = TypeParam;
  Small g(44, 12);
  int lines = 0, undefined = 0;
  for (int i = 0; i < 2000 * scale(); ++i) {
    const auto pa = g.triple(), qa = g.triple();
    if (pa[0] == 0 || qa[0] == 0) continue;
    const auto P = coords(pt<T>(pa)), Q = coords(pt<T>(qa));
    // r: on the line pq (αp + βq) half of the time, random otherwise; put on the other side.
    std::array<Integer, 3> R;
    if (i % 2) {
      R = combo(g(), P, g(), Q);
    } else {
      const auto ra = g.triple();
      R = {ra[0], ra[1], ra[2]};
    }
    if (R[0] == 0) continue;
    if (sgn(R[0]) == sgn(P[0])) R = combo(-1, R, 0, R);
    auto dependent = [](const std::array<Integer, 3>& a, const std::array<Integer, 3>& b) {
      return a[0] * b[1] == a[1] * b[0] && a[0] * b[2] == a[2] * b[0] && a[1] * b[2] == a[2] * b[1];
    };
    if (dependent(P, Q) || dependent(Q, R) || dependent(R, P)) continue;
    const bool collinear = det_oracle(P, Q, R) == 0;
    try {
      const auto c = circle_through(pt<T>(P), pt<T>(Q), pt<T>(R));
      ASSERT_TRUE(collinear);
      ++lines;
      // Centre on Ω, perpendicular to the line, on the positive side of p ∨ q.
      const auto C = coords(c.center());
      ASSERT_EQ(C[0], 0);
      const auto cp = pos(P), cq = pos(Q);
      ASSERT_EQ((cq[0] - cp[0]) * C[1] + (cq[1] - cp[1]) * C[2], 0);
      ASSERT_GT(det_oracle(P, Q, C), 0);
      ASSERT_EQ(radius_kind(c), RadiusKind::infinite);
    } catch (const Undefined&) {
      ASSERT_FALSE(collinear);
      ++undefined;
    }
  }
  EXPECT_GT(lines, 100);
  EXPECT_GT(undefined, 100);
}

TYPED_TEST(CircleT, UndefinedThreePointCircles) {
  using T = TypeParam;
  EXPECT_THROW(circle_through(pt<T>(1, 0, 0), pt<T>(0, 1, 0), pt<T>(1, 0, 1)), Undefined);
  EXPECT_THROW(circle_through(pt<T>(1, 0, 0), pt<T>(2, 0, 0), pt<T>(1, 0, 1)), Undefined);
  EXPECT_THROW(circle_through(pt<T>(1, 0, 0), pt<T>(-2, 0, 0), pt<T>(1, 0, 1)), Undefined);
  EXPECT_THROW(circle_through(pt<T>(0, 1, 0), pt<T>(0, 0, 1), pt<T>(0, 1, 1)), Undefined);
  // Collinear on one side: the line, as a circle of infinite radius.
  const auto l = circle_through(pt<T>(1, 0, 0), pt<T>(1, 1, 0), pt<T>(1, 5, 0));
  EXPECT_EQ(l.center(), pt<T>(0, 0, 1));
  EXPECT_EQ(to_string(BasicCircle<T>(pt<T>(1, 1, 1), pt<T>(1, 0, 0), NEGATIVE)), "circle(center [1, 1, 1], through [1, 0, 0], -)");
  const auto c = circle_through(pt<T>(1, 0, 0), pt<T>(1, 2, 0), pt<T>(1, 0, 2));
  EXPECT_EQ(c.center(), pt<T>(1, 1, 1));
}

}  // namespace
}  // namespace t2
