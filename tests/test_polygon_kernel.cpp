// The kernel of a polygon against brute force: every meet of two constraint lines (the edges'
// lines and Ω, both signs) that satisfies all constraints, in exact homogeneous integers. The
// region computed must hold all of them and its corners must be among them: then the two are
// the same convex region (a convex region is the hull of its extreme points, which are such
// meets). And against the O(n k) algorithm the library had before Lee and Preparata's
// (polygon_kernel_oracle.hpp): the same corners, exactly, as a cyclic sequence. Also: star
// polygons contain their centre, convex polygons are their own kernel, and the unbounded and
// degenerate cases.
#include <gtest/gtest.h>

#include <cmath>

#include "hull_testing.hpp"
#include "polygon_kernel_oracle.hpp"
#include "t2/gen/generate.hpp"
#include "t2/hull/polygon_kernel.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using gen::Kind;
using testing::polygon_of;

Integer dot(const ExactLine& l, const ExactPoint& p) { return l.W() * p.w() + l.X() * p.x() + l.Y() * p.y(); }

// polygon_kernel's reading of P: repeated consecutive vertices dropped, a clockwise front-only
// polygon reversed.
std::vector<Point> as_read(const Polygon& P) {
  std::vector<Point> V;
  for (const Point& p : P)
    if (V.empty() || !(V.back() == p)) V.push_back(p);
  while (V.size() > 1 && V.back() == V.front()) V.pop_back();
  if (std::all_of(V.begin(), V.end(), [](const Point& p) { return p.w() > 0; }) && orientation(V) < 0)
    std::reverse(V.begin(), V.end());
  return V;
}

// Lee and Preparata's corners are the oracle's, in the same cyclic order, and the first is
// the least in the wxy order. Returns the number of corners.
std::size_t expect_as_oracle(const Polygon& P, const std::string& what) {
  const std::vector<ExactPoint> want = testing::oracle_kernel(as_read(P));
  const PolygonKernel K = polygon_kernel(P);
  EXPECT_TRUE(testing::same_cycle(K.vertices, want)) << what << ": " << K.vertices.size() << " corners, the oracle "
                                                    << want.size();
  for (std::size_t k = 1; k < K.vertices.size(); ++k)
    EXPECT_LT(compare_lexicographic(K.vertices[0], K.vertices[k]), 0) << what;
  return K.vertices.size();
}

// P with the run of `count` vertices from `from` moved to Ω along their directions from the
// origin: a star polygon about the origin stays one, now unbounded, with edges along Ω.
Polygon to_omega(Polygon P, std::size_t from, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k) {
    Point& p = P[(from + k) % P.size()];
    p = Point(0, p.x() / p.w(), p.y() / p.w());
  }
  return P;
}

std::vector<ExactLine> constraints(Polygon P) {
  if (std::all_of(P.begin(), P.end(), [](const Point& p) { return p.w() > 0; }) && orientation(P) < 0)
    std::reverse(P.begin(), P.end());
  std::vector<ExactLine> L{omega<Integer>()};
  for (std::size_t i = 0; i < P.size(); ++i)
    if (!(P[i] == P[(i + 1) % P.size()])) L.push_back(join(to_exact(P[i]), to_exact(P[(i + 1) % P.size()])));
  return L;
}

std::vector<ExactPoint> brute_extreme_candidates(const std::vector<ExactLine>& L) {
  std::vector<ExactPoint> out;
  for (std::size_t i = 0; i < L.size(); ++i)
    for (std::size_t j = i + 1; j < L.size(); ++j) {
      const Integer w = L[i].X() * L[j].Y() - L[i].Y() * L[j].X(), x = L[i].Y() * L[j].W() - L[i].W() * L[j].Y(),
                    y = L[i].W() * L[j].X() - L[i].X() * L[j].W();
      if (w == 0 && x == 0 && y == 0) continue;  // one line
      for (const ExactPoint& c : {ExactPoint(w, x, y), ExactPoint(-w, -x, -y)})
        if (std::all_of(L.begin(), L.end(), [&](const ExactLine& l) { return dot(l, c) >= 0; })) out.push_back(c);
    }
  return out;
}

void expect_kernel(const Polygon& P, const std::string& what) {
  const auto L = constraints(P);
  const auto feasible = brute_extreme_candidates(L);
  const PolygonKernel K = polygon_kernel(P);
  EXPECT_EQ(K.empty(), feasible.empty()) << what;
  for (const auto& v : K.vertices)  // every corner satisfies every constraint
    for (const auto& l : L) EXPECT_GE(dot(l, v), 0) << what << ": corner " << to_string(v);
  for (std::size_t k = 0; k < K.edges.size(); ++k) {  // edges join their corners
    EXPECT_EQ(dot(K.edges[k], K.vertices[k]), 0) << what;
    EXPECT_EQ(dot(K.edges[k], K.vertices[(k + 1) % K.vertices.size()]), 0) << what;
  }
  for (const auto& c : feasible) {  // every extreme candidate lies in the region
    if (K.vertices.size() == 1) {
      EXPECT_TRUE(c == K.vertices[0]) << what;
      continue;
    }
    for (const auto& e : K.edges) EXPECT_GE(dot(e, c), 0) << what << ": " << to_string(c) << " outside";
  }
}

TEST(PolygonKernel, RandomPolygonsAgainstBruteForce) {
  int nonempty = 0;
  for (Kind k : {Kind::simple_polygon, Kind::star_polygon, Kind::monotone_polygon, Kind::convex_polygon})
    for (std::uint64_t s = 1; s <= 8; ++s)
      for (std::size_t n : {5, 12, 30}) {
        const Polygon P = polygon_of(k, n, s);
        expect_kernel(P, std::string(gen::name(k)) + " n " + std::to_string(n) + " seed " + std::to_string(s));
        nonempty += !polygon_kernel(P).empty();
      }
  EXPECT_GT(nonempty, 40);  // the star and convex polygons at least
}

TEST(PolygonKernel, StarAndConvexPolygons) {
  for (std::uint64_t s = 1; s <= 10; ++s) {
    const Polygon star = polygon_of(Kind::star_polygon, 200, s);
    const PolygonKernel K = polygon_kernel(star);
    ASSERT_FALSE(K.empty());
    EXPECT_TRUE(K.bounded());
    for (const auto& e : K.edges) EXPECT_GE(sign_of(e.W()), 0);  // the origin [1,0,0] is inside
    Polygon convex = polygon_of(Kind::convex_polygon, 50, s);
    const PolygonKernel C = polygon_kernel(convex);
    const auto hull = convex_hull(convex);  // the corners are the hull vertices, exactly
    ASSERT_EQ(C.vertices.size(), hull.size());
    std::size_t r = 0;
    while (r < hull.size() && !(C.vertices[0] == to_exact(convex[hull[r]]))) ++r;
    for (std::size_t k = 0; k < hull.size(); ++k)
      EXPECT_TRUE(C.vertices[k] == to_exact(convex[hull[(r + k) % hull.size()]])) << "seed " << s << " corner " << k;
    std::reverse(convex.begin(), convex.end());  // clockwise: read backwards, the same kernel
    EXPECT_EQ(polygon_kernel(convex).vertices.size(), C.vertices.size());
  }
}

TEST(PolygonKernel, DegenerateKernels) {
  // A pinwheel whose four inner edges lie on the axes: the kernel is the origin alone.
  const Polygon pin{Point(1, 2, 0),  Point(1, 1, 0),  Point(1, 0, 2),  Point(1, 0, 1),
                    Point(1, -2, 0), Point(1, -1, 0), Point(1, 0, -2), Point(1, 0, -1)};
  PolygonKernel K = polygon_kernel(pin);
  ASSERT_EQ(K.vertices.size(), 1u);
  EXPECT_TRUE(K.vertices[0] == ExactPoint(1, 0, 0));
  expect_kernel(pin, "pinwheel");
  // An hourglass, two reflex vertices facing each other: the kernel is the rhombus between them.
  const Polygon hourglass{Point(1, 0, 0), Point(1, 4, 0), Point(1, 3, 2), Point(1, 4, 4), Point(1, 0, 4), Point(1, 1, 2)};
  K = polygon_kernel(hourglass);
  std::vector<Point> rhombus;
  for (const auto& v : K.vertices) rhombus.push_back(to_double(v));
  EXPECT_TRUE(testing::same_cycle(rhombus, {Point(1, 2, 0), Point(1, 3, 2), Point(1, 2, 4), Point(1, 1, 2)}));
  expect_kernel(hourglass, "hourglass");
  // A comb: empty kernel.
  const Polygon comb{Point(1, 0, 0), Point(1, 5, 0), Point(1, 5, 3), Point(1, 4, 3), Point(1, 4, 1),
                     Point(1, 1, 1), Point(1, 1, 3), Point(1, 0, 3)};
  EXPECT_TRUE(polygon_kernel(comb).empty());
  expect_kernel(comb, "comb");
  EXPECT_THROW(polygon_kernel(Polygon{Point(1, 0, 0), Point(1, 1, 0), Point(2, 2, 0)}), BadInput);
  EXPECT_THROW(polygon_kernel(Polygon{Point(1, 0, 0), Point(1, 1, 0), Point(-1, 0, 1)}), BadInput);
  // An edge clockwise along Ω: the polygon's left side would be the back.
  EXPECT_THROW(polygon_kernel(Polygon{Point(1, 0, 0), Point(0, 0, 1), Point(0, 1, 0)}), BadInput);
}

TEST(PolygonKernel, UnboundedKernelsReachOmega) {
  // The quadrant x, y >= 0: the origin, then the directions +x and +y.
  const Polygon quadrant{Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  PolygonKernel K = polygon_kernel(quadrant);
  EXPECT_FALSE(K.bounded());
  std::vector<Point> corners;
  for (const auto& v : K.vertices) corners.push_back(to_double(v));
  EXPECT_TRUE(testing::same_cycle(corners, {Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)}));
  expect_kernel(quadrant, "quadrant");
  // The half-plane y >= 0: its corners on Ω are +x and -x, half a turn apart, so a point between
  // them (+y) stays as a vertex, and every edge is a segment of T².
  const Polygon half{Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(0, -1, 0)};
  K = polygon_kernel(half);
  expect_kernel(half, "half-plane");
  EXPECT_FALSE(K.bounded());
  for (std::size_t k = 0; k < K.vertices.size(); ++k)
    EXPECT_FALSE(K.vertices[k] == antipode(K.vertices[(k + 1) % K.vertices.size()]));
  // An L-shaped corridor running off to +x and +y: unbounded, but its kernel is the unit square.
  const Polygon ell{Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 1), Point(0, 0, 1)};
  expect_kernel(ell, "L corridor");
  corners.clear();
  for (const auto& v : polygon_kernel(ell).vertices) corners.push_back(to_double(v));
  EXPECT_TRUE(testing::same_cycle(corners, {Point(1, 0, 0), Point(1, 1, 0), Point(1, 1, 1), Point(1, 0, 1)}));
}

TEST(PolygonKernel, LeePreparataAgreesWithTheOracleOnEveryPolygonKind) {
  std::size_t corners = 0, empty = 0;
  for (Kind k : {Kind::simple_polygon, Kind::star_polygon, Kind::monotone_polygon, Kind::convex_polygon})
    for (std::uint64_t s = 1; s <= 12; ++s)
      for (std::size_t n : {3, 4, 7, 20, 60, 250}) {
        const std::string what = std::string(gen::name(k)) + " n " + std::to_string(n) + " seed " + std::to_string(s);
        const std::size_t c = expect_as_oracle(polygon_of(k, n, s), what);
        corners += c, empty += c == 0;
      }
  EXPECT_GT(empty, 50u);     // simple and monotone polygons: mostly empty kernels
  EXPECT_GT(corners, 4000u);  // convex polygons: all their vertices
}

TEST(PolygonKernel, LeePreparataAgreesWithTheOracleOnUnboundedPolygons) {
  std::size_t unbounded = 0;
  for (std::uint64_t s = 1; s <= 30; ++s)
    for (std::size_t count : {1, 2, 4, 7}) {
      const Polygon P = to_omega(polygon_of(Kind::star_polygon, 9 + s % 7, s), s, count);
      const std::string what = "seed " + std::to_string(s) + ", " + std::to_string(count) + " on Omega";
      expect_as_oracle(P, what);
      expect_kernel(P, what);
      unbounded += !polygon_kernel(P).empty() && !polygon_kernel(P).bounded();
    }
  EXPECT_GT(unbounded, 20u);
}

TEST(PolygonKernel, LeePreparataAgreesWithTheOracleOnDegeneratePolygons) {
  for (std::uint64_t s = 1; s <= 10; ++s) {
    // Integer polygons with a vertex in the middle of every edge: collinear edges throughout.
    for (Kind k : {Kind::convex_polygon, Kind::star_polygon}) {
      Polygon P;
      const Polygon Q = polygon_of(k, 12, s);
      for (std::size_t i = 0; i < Q.size(); ++i) {
        const Point& a = Q[i];
        const Point& b = Q[(i + 1) % Q.size()];
        const double ax = 2 * std::round(64 * a.x()), ay = 2 * std::round(64 * a.y());
        const double bx = 2 * std::round(64 * b.x()), by = 2 * std::round(64 * b.y());
        P.push_back(Point(1, ax, ay));
        P.push_back(Point(1, (ax + bx) / 2, (ay + by) / 2));
      }
      expect_as_oracle(P, std::string(gen::name(k)) + " with midpoints, seed " + std::to_string(s));
      expect_kernel(P, "with midpoints");
    }
    // Random vertex sequences (not simple): the half-plane intersection all the same.
    const Polygon scramble = polygon_of(Kind::simple_polygon, 8, s);
    Polygon shuffled = scramble;
    std::swap(shuffled[1], shuffled[4]);
    expect_as_oracle(shuffled, "a self-crossing polygon");
  }
  // A Z of two blocks: the kernel is the segment [1, 3] × {0} between two opposite edges on y = 0.
  const Polygon zed{Point(1, 0, 0), Point(1, 1, 0), Point(1, 1, -1), Point(1, 4, -1),
                    Point(1, 4, 0), Point(1, 3, 0), Point(1, 3, 1),  Point(1, 0, 1)};
  const PolygonKernel K = polygon_kernel(zed);
  ASSERT_EQ(K.vertices.size(), 2u);
  EXPECT_TRUE(K.vertices[0] == ExactPoint(1, 1, 0) && K.vertices[1] == ExactPoint(1, 3, 0));
  expect_as_oracle(zed, "Z");
  expect_kernel(zed, "Z");
  for (const Polygon& P : {Polygon{Point(1, 2, 0), Point(1, 1, 0), Point(1, 0, 2), Point(1, 0, 1), Point(1, -2, 0),
                                   Point(1, -1, 0), Point(1, 0, -2), Point(1, 0, -1)},
                           Polygon{Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(0, -1, 0)},
                           Polygon{Point(0, 1, 0), Point(0, 0, 1), Point(0, -1, 0), Point(0, 0, -1)}})
    expect_as_oracle(P, "pinwheel, half-plane, hemisphere");
}

}  // namespace
}  // namespace t2
