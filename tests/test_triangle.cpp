// Triangles of T²: the preconditions of seed 000 §4.1.6 and point location, for double and
// Integer coordinates, against oracles: points built as αa + βb + γc, and for flat triangles
// the angles of the three vertices on their common great circle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "t2/kernel/triangle.hpp"
#include "test_prim.hpp"

namespace t2 {
namespace {

using testing::combo;
using testing::coords;
using testing::det_oracle;
using testing::is_zero;
using testing::pt;
using testing::same_point;
using testing::scale;
using testing::Small;

template <class T>
class TriangleT : public ::testing::Test {};
TYPED_TEST_SUITE(TriangleT, testing::CoordinateTypes);

TYPED_TEST(TriangleT, RulesOfSection416) {
  using T = TypeParam;
  using Tr = BasicTriangle<T>;
  auto rule = [](auto make) -> std::string {
    try {
      make();
    } catch (const Undefined& e) {
      return e.what();
    }
    return "defined";
  };
  EXPECT_EQ(rule([] { Tr(pt<T>(1, 0, 0), pt<T>(-1, 0, 0), pt<T>(1, 1, 1)); }),
            "triangle(a, b, c) is undefined when two vertices are antipodal");
  EXPECT_EQ(rule([] { Tr(pt<T>(1, 1, 1), pt<T>(1, 0, 0), pt<T>(-2, 0, 0)); }),
            "triangle(a, b, c) is undefined when two vertices are antipodal");
  // Flat, on the line y = 0: a = front x 0, b = front x 1, c = back copy of x 1/2. ¬c is the
  // front point x = 1/2, on ab; and ¬a is on bc too (bc leaves x = 1 away from 1/2, through
  // +∞, to the back side): for three collinear, pairwise non-antipodal, distinct vertices
  // the three conditions of §4.1.6 fail together, so the first one is named.
  EXPECT_EQ(rule([] { Tr(pt<T>(1, 0, 0), pt<T>(1, 1, 0), pt<T>(-2, -1, 0)); }),
            "triangle(a, b, c) is undefined when antipode(a) is on segment bc");
  // Flat but defined: a = front 0, b = front 1, c = back copy of 5 (¬c = 5 is not on ab; bc
  // runs from 1 to −∞ and on through the back points beyond 5: not through ¬a).
  EXPECT_EQ(rule([] { Tr(pt<T>(1, 0, 0), pt<T>(1, 1, 0), pt<T>(-1, -5, 0)); }), "defined");
  EXPECT_EQ(rule([] { Tr(pt<T>(1, 0, 0), pt<T>(1, 3, 0), pt<T>(1, 1, 0)); }), "defined");
  EXPECT_EQ(rule([] { Tr(pt<T>(1, 0, 0), pt<T>(1, 3, 0), pt<T>(0, 1, 0)); }), "defined");
  EXPECT_EQ(rule([] { Tr(pt<T>(1, 0, 0), pt<T>(0, 1, 0), pt<T>(-1, 3, 0)); }), "defined");  // back x=-3
  EXPECT_EQ(rule([] { Tr(pt<T>(1, 0, 0), pt<T>(0, 1, 0), pt<T>(0, -1, 1)); }), "defined");  // not flat
}

TYPED_TEST(TriangleT, FlatTrianglesExistIffTheVerticesFitInAnOpenHalfCircle) {
  using T = TypeParam;
  Small g(21, 6);
  int defined = 0, undefined = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    const auto U = coords(pt<T>(g.triple())), V = coords(pt<T>(g.triple()));
    if (is_zero({U[1] * V[2] - U[2] * V[1], U[2] * V[0] - U[0] * V[2], U[0] * V[1] - U[1] * V[0]})) continue;
    std::array<long, 2> e[3];
    for (auto& x : e)
      do x = {g(), g()};
      while (x[0] == 0 && x[1] == 0);
    auto antipodal = [](const auto& a, const auto& b) {
      return a[0] * b[1] == a[1] * b[0] && a[0] * b[0] + a[1] * b[1] < 0;
    };
    const bool pairs = antipodal(e[0], e[1]) || antipodal(e[1], e[2]) || antipodal(e[2], e[0]);
    // Oracle: angles on the circle (small integer vectors: the gaps are far from π unless two
    // points are antipodal, which is decided exactly above).
    double ang[3];
    for (int k = 0; k < 3; ++k) ang[k] = std::atan2(double(e[k][1]), double(e[k][0]));
    std::sort(ang, ang + 3);
    const double gap = std::max({ang[1] - ang[0], ang[2] - ang[1], 2 * std::numbers::pi - (ang[2] - ang[0])});
    const bool want = !pairs && gap > std::numbers::pi;
    auto lift = [&](const std::array<long, 2>& a) { return pt<T>(combo(a[0], U, a[1], V)); };
    bool got = true;
    try {
      BasicTriangle<T> t(lift(e[0]), lift(e[1]), lift(e[2]));
      EXPECT_EQ(orientation(t), ZERO);
      // A flat triangle is its longest side: every vertex is on the boundary, the
      // antipodes of the vertices are not in it.
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(bounded_side(t, t.vertex(k)), BoundedSide::boundary);
        ASSERT_FALSE(contains(t, antipode(t.vertex(k))));
      }
    } catch (const Undefined&) {
      got = false;
    }
    ASSERT_EQ(got, want);
    (want ? defined : undefined)++;
  }
  EXPECT_GT(defined, 200);
  EXPECT_GT(undefined, 200);
}

TYPED_TEST(TriangleT, ContainsMatchesBarycentricOracle) {
  using T = TypeParam;
  Small g(22, 20);
  std::uniform_int_distribution<long> co(-3, 3);
  int in = 0, on = 0, out = 0;
  for (int i = 0; i < 3000 * scale(); ++i) {
    const auto A = coords(pt<T>(g.triple())), B = coords(pt<T>(g.triple())), C = coords(pt<T>(g.triple()));
    const Integer d = det_oracle(A, B, C);
    if (d == 0) continue;
    const BasicTriangle<T> t(pt<T>(A), pt<T>(B), pt<T>(C));
    ASSERT_EQ(orientation(t), sign_of(d));
    const long al = co(g.rng), be = co(g.rng), ga = co(g.rng);
    const auto P = combo(1, combo(al, A, be, B), ga, C);
    if (is_zero(P)) continue;
    BoundedSide want = BoundedSide::inside;
    if (al < 0 || be < 0 || ga < 0) {
      want = BoundedSide::outside;
    } else if (al == 0 || be == 0 || ga == 0) {
      want = BoundedSide::boundary;
    }
    ASSERT_EQ(bounded_side(t, pt<T>(P)), want);
    ASSERT_EQ(contains(t, pt<T>(P)), want != BoundedSide::outside);
    // The antipode of an inside point is outside: a triangle lies in an open hemisphere.
    if (want == BoundedSide::inside) {
      ASSERT_EQ(bounded_side(t, antipode(pt<T>(P))), BoundedSide::outside);
    }
    // Vertex order and orientation do not change the set.
    const BasicTriangle<T> r(pt<T>(B), pt<T>(A), pt<T>(C));
    ASSERT_EQ(bounded_side(r, pt<T>(P)), want);
    (want == BoundedSide::inside ? in : want == BoundedSide::outside ? out : on)++;
  }
  EXPECT_GT(in, 50);
  EXPECT_GT(on, 50);
  EXPECT_GT(out, 500);
}

TYPED_TEST(TriangleT, ToString) {
  using T = TypeParam;
  EXPECT_EQ(to_string(BasicTriangle<T>(pt<T>(1, 0, 0), pt<T>(0, 1, 0), pt<T>(-1, 0, 1))),
            "triangle([1, 0, 0], [0, 1, 0], [-1, 0, 1])");
}

TEST(Triangle, BackAndCrossingTriangles) {
  // The back copy of the unit triangle: orientation flips, it contains the back points only.
  const Triangle front(Point(1, 0, 0), Point(1, 1, 0), Point(1, 0, 1));
  const Triangle back(Point(-1, 0, 0), Point(-1, -1, 0), Point(-1, 0, -1));
  EXPECT_EQ(orientation(front), POSITIVE);
  EXPECT_EQ(orientation(back), NEGATIVE);
  EXPECT_TRUE(contains(front, Point(4, 1, 1)));
  EXPECT_FALSE(contains(front, Point(-4, -1, -1)));
  EXPECT_TRUE(contains(back, Point(-4, -1, -1)));
  // A triangle with a vertex at infinity is an unbounded wedge of the front plane.
  const ExactTriangle wedge(ExactPoint(1, 0, 0), ExactPoint(1, 1, 0), ExactPoint(0, 0, 1));
  EXPECT_TRUE(contains(wedge, ExactPoint(1, 1, 1000000)));
  EXPECT_FALSE(contains(wedge, ExactPoint(1, 2, 1000000)));
  EXPECT_EQ(bounded_side(wedge, ExactPoint(0, 0, 5)), BoundedSide::boundary);
  EXPECT_EQ(to_string(front), "triangle([1, 0, 0], [1, 1, 0], [1, 0, 1])");
  EXPECT_EQ(front.vertex(4), Point(1, 1, 0));
  EXPECT_EQ(front.vertex(-1), Point(1, 0, 1));
}

}  // namespace
}  // namespace t2
