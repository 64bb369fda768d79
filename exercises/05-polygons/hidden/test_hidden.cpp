// Exercise 05, hidden tests. Oracle: exact rational Cartesian geometry (shoelace area,
// crossing number with exact intersection abscissas, on-segment by rational comparisons) and
// the antipodal rule locate(P, q) = -locate(¬P, ¬q), and projective maps: an invertible integer
// matrix M maps T² onto itself, the segment ab onto the segment (Ma)(Mb), and Δ(Ma, Mb, Mc) =
// det M · Δ(a, b, c), so locate(MP, Mq) = sign(det M) · locate(P, q). Planar polygons become
// polygons with vertices on both sides and edges through Ω, answered by the planar oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

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

using Matrix = std::array<std::array<int, 3>, 3>;

Point map_by(const Matrix& M, const Point& p) {
  const double c[3] = {p.w(), p.x(), p.y()};
  double r[3];
  for (int i = 0; i < 3; ++i) r[i] = M[i][0] * c[0] + M[i][1] * c[1] + M[i][2] * c[2];  // exact: small integers
  return Point(r[0], r[1], r[2]);
}
std::vector<Point> map_by(const Matrix& M, const std::vector<Point>& P) {
  std::vector<Point> r;
  for (const auto& p : P) r.push_back(map_by(M, p));
  return r;
}
int det(const Matrix& M) {
  return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
         M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
}

// A star-shaped polygon around the origin, front or back, either orientation (empty if the
// random directions do not make one).
std::vector<Point> random_star(std::mt19937_64& rng, int iter) {
  std::uniform_int_distribution<int> radius(1, 8), scale(1, 4), n_of(3, 9);
  const int dirs[16][2] = {{1, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 1}, {-1, 2}, {-1, 1}, {-2, 1},
                           {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2}, {0, -1}, {1, -2}, {1, -1}, {2, -1}};
  const int n = n_of(rng);
  std::vector<int> idx(16);
  for (int i = 0; i < 16; ++i) idx[i] = i;
  std::shuffle(idx.begin(), idx.end(), rng);
  idx.resize(n);
  std::sort(idx.begin(), idx.end());
  // Reject polygons whose consecutive directions span half a turn or more (not star-shaped).
  for (int i = 0; i < n; ++i)
    if ((idx[(i + 1) % n] - idx[i] + 16) % 16 >= 8) return {};
  std::vector<Point> P;
  for (int i : idx) {
    const double r = radius(rng), sc = scale(rng);
    P.push_back(Point(sc, sc * r * dirs[i][0], sc * r * dirs[i][1]));
  }
  if (iter % 2) std::reverse(P.begin(), P.end());
  if (iter % 3 == 0)
    for (auto& p : P) p = t2::antipode(p);
  return P;
}

// Queries: random points of both sides and Ω, every vertex, and a point inside every edge.
std::vector<Point> queries(std::mt19937_64& rng, const std::vector<Point>& P) {
  std::uniform_int_distribution<int> coord(-10, 10), wq(-2, 2);
  std::vector<Point> r;
  for (int k = 0; k < 20; ++k) {
    const double w = wq(rng), x = coord(rng), y = coord(rng);
    if (w != 0 || x != 0 || y != 0) r.push_back(Point(w, x, y));
  }
  for (size_t i = 0; i < P.size(); ++i) {
    const Point &a = P[i], &b = P[(i + 1) % P.size()];
    r.push_back(a);
    // |w_b| a + |w_a| b: a point of the segment ab (both ends on the same side).
    r.push_back(Point(std::abs(b.w()) * a.w() + std::abs(a.w()) * b.w(), std::abs(b.w()) * a.x() + std::abs(a.w()) * b.x(),
                      std::abs(b.w()) * a.y() + std::abs(a.w()) * b.y()));
  }
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
  for (int iter = 0; iter < 300; ++iter) {
    const auto P = random_star(rng, iter);
    if (P.empty()) continue;
    for (const Point& q : queries(rng, P)) check(P, q);
    if (HasFailure()) return;
  }
}

TEST(Hidden, EdgesThroughInfinity) {
  // (w, x, y) -> (2x - w, w, y) sends the line x = 1/2 to Ω: the unit square's vertices (0,0)
  // and (0,1) go to the back, and its bottom and top edges cross Ω. det = -2: orientation flips.
  const Matrix M = {{{-1, 2, 0}, {1, 0, 0}, {0, 0, 1}}};
  const auto Q = map_by(M, square);
  for (const Point& q : {Point(4, 1, 1), Point(4, 3, 1), Point(2, 1, 1), Point(1, 3, 0.5), Point(-1, 3, 0.5),
                         Point(0, 1, 0), Point(0, 0, 1), Point(-2, -1, -1), Point(1, 1, 0.5), Point(1, 0, 1)}) {
    EXPECT_EQ(static_cast<int>(ex05::locate(Q, map_by(M, q))), -oracle(square, q)) << "preimage " << t2::to_string(q);
  }
}

TEST(Hidden, ProjectiveImagesAgreeWithOracle) {
  // Random star polygons under random invertible integer maps: vertices on both sides, edges
  // through Ω, walks through vertices and along edges (integer coordinates are often collinear).
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int> m(-3, 3);
  int mixed = 0;
  for (int iter = 0; iter < 400; ++iter) {
    const auto P = random_star(rng, iter);
    if (P.empty()) continue;
    Matrix M;
    for (auto& row : M)
      for (auto& e : row) e = m(rng);
    if (det(M) == 0) continue;
    const auto Q = map_by(M, P);
    const bool front = std::any_of(Q.begin(), Q.end(), [](const Point& p) { return p.w() > 0; });
    const bool back = std::any_of(Q.begin(), Q.end(), [](const Point& p) { return p.w() < 0; });
    if (!(front && back)) continue;
    ++mixed;
    const int sign = det(M) > 0 ? 1 : -1;
    for (const Point& q : queries(rng, P))
      ASSERT_EQ(static_cast<int>(ex05::locate(Q, map_by(M, q))), sign * oracle(P, q))
          << "polygon image of a star, query image of " << t2::to_string(q);
  }
  ASSERT_GE(mixed, 50) << "test bug: too few polygons with vertices on both sides";
}

TEST(Hidden, NearlyOnAnEdgeIsExact) {
  // A long thin triangle with double coordinates; queries are rounded points of its long edges
  // moved a few units in the last place: inside, outside or exactly on the edge, only exact
  // signs tell. Also its antipodal (back) copy.
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> t(0.05, 0.95);
  std::uniform_int_distribution<int> ulps(-4, 4);
  const std::vector<Point> T = {Point(1, 0.1, 0.3), Point(1, 17.3, 24.9), Point(1, 12.7, 25.1)};
  const std::vector<Point> back = {t2::antipode(T[0]), t2::antipode(T[2]), t2::antipode(T[1])};
  for (int i = 0; i < 600; ++i) {
    const Point &a = T[i % 3], &b = T[(i + 1) % 3];
    const double s = t(rng);
    double x = a.x() + s * (b.x() - a.x()), y = a.y() + s * (b.y() - a.y());
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) x = std::nextafter(x, k > 0 ? 100.0 : -100.0);
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) y = std::nextafter(y, k > 0 ? 100.0 : -100.0);
    const Point q(1, x, y);
    ASSERT_EQ(static_cast<int>(ex05::locate(T, q)), oracle(T, q)) << t2::to_string(q);
    ASSERT_EQ(static_cast<int>(ex05::locate(back, t2::antipode(q))), oracle(back, t2::antipode(q)))
        << t2::to_string(t2::antipode(q));
  }
}

}  // namespace
