// Exercise 05, hidden tests. Oracle: exact rational Cartesian geometry (shoelace area,
// crossing number with exact intersection abscissas, on-segment by rational comparisons) and
// the antipodal rule locate(P, q) = -locate(¬P, ¬q).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <t2/number.hpp>
#include <t2/point.hpp>

#include "locate.hpp"

namespace {

using t2::Point;
using t2::Rational;

struct RP {
  Rational x, y;
};
RP cart(const Point& p) {
  Rational x = t2::to_rational(p.x()) / t2::to_rational(p.w()), y = t2::to_rational(p.y()) / t2::to_rational(p.w());
  return {x, y};
}

int oracle_front(const std::vector<Point>& P, const Point& q) {
  std::vector<RP> v;
  for (const auto& p : P) v.push_back(cart(p));
  Rational area = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const RP &a = v[i], &b = v[(i + 1) % v.size()];
    area += a.x * b.y - b.x * a.y;
  }
  const int o = sgn(area);
  if (q.w() <= 0) return -o;
  const RP c = cart(q);
  int crossings = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const RP &a = v[i], &b = v[(i + 1) % v.size()];
    const Rational cr = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (cr == 0 && std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
        c.y <= std::max(a.y, b.y))
      return 0;
    if ((a.y > c.y) != (b.y > c.y)) {
      const Rational x = a.x + (c.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (x > c.x) ++crossings;
    }
  }
  return crossings % 2 ? o : -o;
}

int oracle(const std::vector<Point>& P, const Point& q) {
  if (P[0].w() > 0) return oracle_front(P, q);
  std::vector<Point> F;
  for (const auto& p : P) F.push_back(t2::antipode(p));
  return -oracle_front(F, t2::antipode(q));
}

std::vector<Point> reversed(std::vector<Point> P) {
  std::reverse(P.begin(), P.end());
  return P;
}
std::vector<Point> antipodal(const std::vector<Point>& P) {
  std::vector<Point> r;
  for (const auto& p : P) r.push_back(t2::antipode(p));
  return r;
}

const std::vector<Point> square = {Point(1, 0, 0), Point(1, 1, 0), Point(1, 1, 1), Point(1, 0, 1)};

void check(const std::vector<Point>& P, const Point& q) {
  EXPECT_EQ(static_cast<int>(ex05::locate(P, q)), oracle(P, q)) << "q = " << t2::to_string(q);
}

TEST(Hidden, QueryOnTheBackSide) {
  check(square, Point(-2, -1, -1));
  check(square, Point(-1, -3, 0));
  check(square, t2::antipode(square[2]));
}

TEST(Hidden, ClockwisePolygon) {
  check(reversed(square), Point(2, 1, 1));
  check(reversed(square), Point(1, 3, 0.5));
}

TEST(Hidden, BackSidePolygon) {
  for (const Point& q : {Point(-2, -1, -1), Point(2, 1, 1), Point(-1, -3, 0), Point(0, 1, 1)})
    check(antipodal(square), q);
}

TEST(Hidden, QueryAtInfinity) {
  check(reversed(square), Point(0, 1, 0));
  check(antipodal(square), Point(0, -1, 2));
}

TEST(Hidden, PointsOnTheBoundary) {
  check(reversed(square), Point(1, 0.5, 0));
  check(antipodal(square), Point(-1, -1, -0.5));
  check(antipodal(square), square[1]);
  check(square, Point(2, 2, 1));
}

TEST(Hidden, RandomStarPolygonsAgreeWithOracle) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> radius(1, 8), scale(1, 4), coord(-10, 10), n_of(3, 9), wq(-2, 2);
  // Star-shaped around the origin: directions in angular order, integer radii.
  const int dirs[16][2] = {{1, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 1}, {-1, 2}, {-1, 1}, {-2, 1},
                           {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2}, {0, -1}, {1, -2}, {1, -1}, {2, -1}};
  for (int iter = 0; iter < 300; ++iter) {
    const int n = n_of(rng);
    std::vector<int> idx(16);
    for (int i = 0; i < 16; ++i) idx[i] = i;
    std::shuffle(idx.begin(), idx.end(), rng);
    idx.resize(n);
    std::sort(idx.begin(), idx.end());
    // Reject polygons whose consecutive directions span half a turn or more (not star-shaped).
    bool ok = true;
    for (int i = 0; i < n; ++i) {
      const int gap = (idx[(i + 1) % n] - idx[i] + 16) % 16;
      if (gap >= 8 || (n > 1 && gap == 0)) ok = false;
    }
    if (!ok) continue;
    std::vector<Point> P;
    for (int i : idx) {
      const double r = radius(rng), s = scale(rng);
      P.push_back(Point(s, s * r * dirs[i][0], s * r * dirs[i][1]));
    }
    if (iter % 2) P = reversed(P);
    if (iter % 3 == 0) P = antipodal(P);
    for (int k = 0; k < 20; ++k) {
      const double w = wq(rng);
      const double x = coord(rng), y = coord(rng);
      if (w == 0 && x == 0 && y == 0) continue;
      check(P, Point(w, x, y));
    }
    // Vertices and points of edges are on the boundary.
    for (size_t i = 0; i < P.size(); ++i) {
      const Point &a = P[i], &b = P[(i + 1) % P.size()];
      check(P, a);
      // |w_b| a + |w_a| b: a point of the segment ab (both ends on the same side).
      check(P, Point(std::abs(b.w()) * a.w() + std::abs(a.w()) * b.w(),
                     std::abs(b.w()) * a.x() + std::abs(a.w()) * b.x(),
                     std::abs(b.w()) * a.y() + std::abs(a.w()) * b.y()));
    }
    if (HasFailure()) return;
  }
}

}  // namespace
