// t2::farthest_delaunay (t2/voronoi/complex.hpp), Chew's randomized insertion, against
// certificates computed from its output alone: h − 2 counter-clockwise triangles that tile the
// convex polygon (each boundary edge once, each inner edge once each way, E = 2h − 3, areas
// summing to the polygon's, exactly), and every triangle's circle holding every corner
// (exact in_circle). In general position the farthest-point Delaunay triangulation is unique,
// so it is also compared with the brute-force set of triangles whose circle holds all corners.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "t2/kernel/incircle.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/voronoi/complex.hpp"

namespace t2 {
namespace {

using Index = Triangulation::Index;
using Face = std::array<Index, 3>;

/// Twice the signed area of (a, b, c) drawn, exactly: the test's points are integers with w = 1
/// (converted to GMP integers without rounding).
mpz_class area2(const Point& a, const Point& b, const Point& c) {
  auto i = [](double v) { return mpz_class(static_cast<long>(v)); };
  return (i(b.x()) - i(a.x())) * (i(c.y()) - i(a.y())) - (i(b.y()) - i(a.y())) * (i(c.x()) - i(a.x()));
}

/// Empty when `faces` is a farthest-point Delaunay triangulation of the convex polygon `c`
/// (its corners counter-clockwise, strictly convex); else what is wrong.
std::string certificate_error(const std::vector<Point>& c, const std::vector<Face>& faces) {
  const Index h = static_cast<Index>(c.size());
  if (h < 3) return faces.empty() ? "" : "faces for fewer than three corners";
  if (faces.size() != h - 2) return "not h - 2 triangles: " + std::to_string(faces.size());
  std::map<std::pair<Index, Index>, int> directed;
  mpz_class sum = 0, polygon = 0;
  for (const Face& t : faces) {
    for (Index v : t)
      if (v >= h) return "an index out of range";
    if (orient(c[t[0]], c[t[1]], c[t[2]]) != POSITIVE) return "a triangle not counter-clockwise";
    for (int i = 0; i < 3; ++i)
      if (++directed[{t[i], t[(i + 1) % 3]}] > 1) return "a directed edge twice";
    for (const Point& d : c)
      if (in_circle(c[t[0]], c[t[1]], c[t[2]], d) == NEGATIVE) return "a corner outside a triangle's circle";
    sum += area2(c[t[0]], c[t[1]], c[t[2]]);
  }
  for (Index i = 1; i + 1 < h; ++i) polygon += area2(c[0], c[i], c[i + 1]);
  if (sum != polygon) return "the areas do not sum to the polygon's";
  std::set<std::pair<Index, Index>> undirected;
  for (const auto& [e, n] : directed) {
    const auto [u, v] = e;
    undirected.insert({std::min(u, v), std::max(u, v)});
    const bool boundary = v == (u + 1) % h, reverse = directed.count({v, u}) > 0;
    if (boundary && reverse) return "a boundary edge used from outside";
    if (!boundary && !reverse) return "an inner edge in one triangle only";
  }
  for (Index i = 0; i < h; ++i)
    if (!directed.count({i, (i + 1) % h})) return "a boundary edge missing";
  // Euler for a disk: V − E + F = 1.
  if (std::int64_t(h) - std::int64_t(undirected.size()) + std::int64_t(faces.size()) != 1) return "V - E + F != 1";
  return "";
}

/// The brute-force farthest-point Delaunay triangles: counter-clockwise triples, smallest index
/// first, whose circle holds every corner.
std::set<Face> brute(const std::vector<Point>& c) {
  std::set<Face> out;
  const Index h = static_cast<Index>(c.size());
  for (Index a = 0; a < h; ++a)
    for (Index b = a + 1; b < h; ++b)
      for (Index d = b + 1; d < h; ++d) {  // a < b < d counter-clockwise: the polygon's order
        bool all = true;
        for (const Point& e : c) all = all && in_circle(c[a], c[b], c[d], e) != NEGATIVE;
        if (all) out.insert({a, b, d});
      }
  return out;
}

Face rotated(Face t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

/// The strict hull corners of integer points, counter-clockwise (Andrew's monotone chain with
/// exact 64-bit crosses), as front points.
std::vector<Point> hull_corners(std::vector<std::pair<std::int64_t, std::int64_t>> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  auto cross = [](auto o, auto a, auto b) {
    return (a.first - o.first) * (b.second - o.second) - (a.second - o.second) * (b.first - o.first);
  };
  std::vector<std::pair<std::int64_t, std::int64_t>> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  std::vector<Point> out;
  for (std::size_t i = 0; i + 1 < k; ++i) out.push_back(Point(1, double(h[i].first), double(h[i].second)));
  return out;
}

/// The integer points of the circle x² + y² = r², counter-clockwise from (r, 0).
std::vector<Point> circle_points(std::int64_t r) {
  std::vector<std::pair<std::int64_t, std::int64_t>> q;  // the first quadrant, x > 0, y ≥ 0
  for (std::int64_t x = 1; x <= r; ++x) {
    const std::int64_t y2 = r * r - x * x;
    std::int64_t y = static_cast<std::int64_t>(std::llround(std::sqrt(double(y2))));
    while (y * y > y2) --y;
    while ((y + 1) * (y + 1) <= y2) ++y;
    if (y * y == y2) q.push_back({x, y});
  }
  std::sort(q.begin(), q.end(), [](auto a, auto b) { return a.first > b.first; });  // by angle
  std::vector<Point> out;
  for (int turn = 0; turn < 4; ++turn)  // each quarter turn: (x, y) → (−y, x)
    for (auto [x, y] : q) {
      std::int64_t u = x, v = y;
      for (int k = 0; k < turn; ++k) std::tie(u, v) = std::pair{-v, u};
      out.push_back(Point(1, double(u), double(v)));
    }
  return out;
}

TEST(FarthestDelaunay, RandomConvexPolygonsMatchTheBruteForceTriangles) {
  std::mt19937 rng(24);
  std::uniform_int_distribution<std::int64_t> d(-1000000, 1000000);
  for (int r = 0; r < 60; ++r) {
    std::vector<std::pair<std::int64_t, std::int64_t>> p;
    const int n = 3 + r * 3;
    for (int k = 0; k < n; ++k) p.push_back({d(rng), d(rng)});
    const std::vector<Point> c = hull_corners(p);
    const std::vector<Face> f = farthest_delaunay(c);
    ASSERT_EQ(certificate_error(c, f), "") << "round " << r << ", " << c.size() << " corners";
    std::set<Face> got;
    for (const Face& t : f) got.insert(rotated(t));
    // Random large coordinates: no four corners cocircular, so the triangulation is unique.
    EXPECT_EQ(got, brute(c)) << "round " << r;
  }
}

TEST(FarthestDelaunay, ManyCornersOnAParabola) {
  // (x, x²): every point a strict corner, the input on which the fan and flips took O(h²).
  std::vector<Point> c;
  for (int x = -300; x < 300; ++x) c.push_back(Point(1, x, double(x) * x));
  EXPECT_EQ(certificate_error(c, farthest_delaunay(c)), "");
}

TEST(FarthestDelaunay, CocircularCorners) {
  // x² + y² = r² with r = 5⁴·13²: r² = 5⁸·13⁴ has 4·(8 + 1)·(4 + 1) = 180 lattice points, all on
  // one circle. Every triangulation is then farthest-point Delaunay; the certificate checks one.
  const std::vector<Point> all = circle_points(625 * 169);
  ASSERT_EQ(all.size(), 180u);
  EXPECT_EQ(certificate_error(all, farthest_delaunay(all)), "") << all.size() << " corners";
  std::mt19937 rng(5);
  for (int r = 0; r < 10; ++r) {  // random subsets: still cocircular, convex position
    std::vector<Point> c;
    for (const Point& p : all)
      if (rng() % 3 == 0) c.push_back(p);
    EXPECT_EQ(certificate_error(c, farthest_delaunay(c)), "") << "round " << r << ", " << c.size() << " corners";
  }
  // The 36 lattice points of x² + y² = 65² plus a corner outside the circle: cocircular and not.
  std::vector<Point> c = circle_points(65);
  ASSERT_EQ(c.size(), 36u);
  c.insert(c.begin() + 1, Point(1, 65, 1));  // outside the circle, still strictly convex
  EXPECT_EQ(certificate_error(c, farthest_delaunay(c)), "");
}

TEST(FarthestDelaunay, SmallSizes) {
  EXPECT_TRUE(farthest_delaunay(std::vector<Point>{}).empty());
  EXPECT_TRUE(farthest_delaunay(std::vector<Point>{Point(1, 0, 0)}).empty());
  EXPECT_TRUE(farthest_delaunay(std::vector<Point>{Point(1, 0, 0), Point(1, 1, 0)}).empty());
  const std::vector<Point> tri{Point(1, 0, 0), Point(1, 4, 0), Point(1, 1, 3)};
  const auto t = farthest_delaunay(tri);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(rotated(t[0]), (Face{0, 1, 2}));
  // Four corners: the farthest diagonal is the one whose circles hold the other corners. Each
  // rotation of the input, so that either diagonal comes first in every order.
  const std::vector<Point> kite{Point(1, 0, 0), Point(1, 10, -1), Point(1, 20, 0), Point(1, 10, 1)};
  for (int s = 0; s < 4; ++s) {
    std::vector<Point> c(kite.begin() + s, kite.end());
    c.insert(c.end(), kite.begin(), kite.begin() + s);
    const auto f = farthest_delaunay(c);
    EXPECT_EQ(certificate_error(c, f), "");
    std::set<Face> got;
    for (const Face& g : f) got.insert(rotated(g));
    EXPECT_EQ(got, brute(c)) << "shift " << s;
  }
  const std::vector<Point> square{Point(1, 0, 0), Point(1, 1, 0), Point(1, 1, 1), Point(1, 0, 1)};
  EXPECT_EQ(certificate_error(square, farthest_delaunay(square)), "");  // either diagonal
}

TEST(FarthestDelaunay, TheSameOutputEveryTime) {
  const std::vector<Point> c = circle_points(625 * 169);
  EXPECT_EQ(farthest_delaunay(c), farthest_delaunay(c));
}

}  // namespace
}  // namespace t2
