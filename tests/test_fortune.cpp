// t2::fortune (t2/voronoi/fortune.hpp) against oracles: the front half of t2::voronoi (the dual
// of the Delaunay complex, another algorithm: front vertices with their sites in order, edges
// between front vertices, and the point where each edge leaving the front side crosses Ω); a
// brute force on small inputs with exact rationals (every vertex equidistant from its sites, no
// site nearer, and every empty circle through three sites is a vertex); Boost.Polygon's sweep
// (vertex and edge counts) on integer coordinates; inputs that broke other Voronoi codes.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <boost/polygon/voronoi.hpp>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/voronoi/fortune.hpp"
#include "t2/voronoi/voronoi.hpp"
#include "voronoi_inputs.hpp"
#include "voronoi_regressions.hpp"

namespace t2 {
namespace {

using Index = FortuneDiagram::Index;
using Q2 = std::pair<mpq_class, mpq_class>;

Q2 cartesian(const ExactPoint& p) {
  Q2 c{mpq_class(p.x(), p.w()), mpq_class(p.y(), p.w())};
  c.first.canonicalize(), c.second.canonicalize();
  return c;
}

/// A point of Ω as a reduced integer direction.
std::pair<mpz_class, mpz_class> direction(const mpz_class& x, const mpz_class& y) {
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), x.get_mpz_t(), y.get_mpz_t());
  return {x / g, y / g};
}

/// The cyclic list of sites starting at its smallest.
std::vector<Index> rotated(std::span<const Index> s) {
  std::vector<Index> v(s.begin(), s.end());
  std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
  return v;
}

/// What the front half of a diagram is made of, in coordinates (comparable between the two).
struct FrontHalf {
  std::map<Q2, std::vector<Index>> vertices;
  std::multiset<std::tuple<Q2, Q2, Index, Index>> edges;  // (lower vertex, upper vertex, s < t)
  std::multiset<std::tuple<Q2, std::pair<mpz_class, mpz_class>, Index, Index>> rays;
  bool operator==(const FrontHalf&) const = default;
};

std::tuple<Q2, Q2, Index, Index> edge_key(Q2 a, Q2 b, Index s, Index t) {
  if (b < a) std::swap(a, b);
  return {a, b, std::min(s, t), std::max(s, t)};
}

FrontHalf of(const FortuneDiagram& fd) {
  FrontHalf h;
  std::vector<Q2> c;
  for (Index v = 0; v < fd.size(); ++v) {
    EXPECT_GT(sgn(fd.vertex(v).w()), 0);
    c.push_back(cartesian(fd.vertex(v)));
    EXPECT_TRUE(h.vertices.emplace(c.back(), rotated(fd.vertex_sites(v))).second) << "two vertices at one point";
  }
  for (const auto& e : fd.edges) h.edges.insert(edge_key(c[e.a], c[e.b], e.s, e.t));
  for (const auto& r : fd.rays) {
    EXPECT_EQ(sgn(r.end.w()), 0);
    h.rays.insert({c[r.a], direction(r.end.x(), r.end.y()), std::min(r.s, r.t), std::max(r.s, r.t)});
  }
  return h;
}

FrontHalf front_of(const VoronoiDiagram& vd) {
  FrontHalf h;
  std::vector<ExactPoint> x;
  for (Index v = 0; v < vd.size(); ++v) {
    x.push_back(vd.vertex(v));
    if (sgn(x.back().w()) > 0) h.vertices.emplace(cartesian(x.back()), rotated(vd.vertex_sites(v)));
  }
  for (const auto& e : vd.edges) {
    const ExactPoint &a = x[e.a], &b = x[e.b];
    const bool fa = sgn(a.w()) > 0, fb = sgn(b.w()) > 0;
    if (fa && fb) h.edges.insert(edge_key(cartesian(a), cartesian(b), e.s, e.t));
    if (fa == fb) continue;
    const ExactPoint& f = fa ? a : b;
    const ExactPoint& o = fa ? b : a;
    // Where the segment f → o crosses Ω: (−w_o)·f + w_f·o (both weights ≥ 0), o itself on Ω.
    mpz_class X = -o.w() * f.x() + f.w() * o.x(), Y = -o.w() * f.y() + f.w() * o.y();
    if (X == 0 && Y == 0) {  // o = ¬f (cocircular sites): the edge is the outer normal of the hull edge s t
      const Index v = sgn(a.w()) > 0 ? e.a : e.b;
      Index u = e.s;
      for (Index k : vd.vertex_sites(v))
        if (k != e.s && k != e.t) u = k;
      const Q2 S = cartesian(to_exact(vd.sites[e.s])), T = cartesian(to_exact(vd.sites[e.t])),
               U = cartesian(to_exact(vd.sites[u]));
      mpq_class nx = S.second - T.second, ny = T.first - S.first;  // perpendicular to s t
      if (sgn(nx * (U.first - S.first) + ny * (U.second - S.second)) > 0) nx = -nx, ny = -ny;
      X = nx.get_num() * ny.get_den(), Y = ny.get_num() * nx.get_den();
    }
    h.rays.insert({cartesian(f), direction(X, Y), std::min(e.s, e.t), std::max(e.s, e.t)});
  }
  return h;
}

/// Fortune equals the front half of the dual on `p`.
void expect_front_half(const std::vector<Point>& p) {
  const FortuneDiagram fd = fortune(p);
  const VoronoiDiagram vd = voronoi(p);
  const FrontHalf a = of(fd), b = front_of(vd);
  EXPECT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_EQ(a.edges.size(), b.edges.size());
  EXPECT_EQ(a.rays.size(), b.rays.size());
  EXPECT_TRUE(a.vertices == b.vertices) << "vertices differ";
  if (a.vertices != b.vertices)
    for (const auto& [k, v] : a.vertices) {
      const auto f = b.vertices.find(k);
      if (f == b.vertices.end()) ADD_FAILURE() << "fortune only: " << k.first << " " << k.second;
      else if (f->second != v) ADD_FAILURE() << "sites differ at " << k.first << " " << k.second << ": " << ::testing::PrintToString(v) << " vs " << ::testing::PrintToString(f->second);
    }
  for (const auto& [k, v] : b.vertices)
    if (!a.vertices.count(k)) ADD_FAILURE() << "dual only: " << k.first << " " << k.second << " " << ::testing::PrintToString(v);
  EXPECT_TRUE(a.edges == b.edges) << "edges differ";
  EXPECT_TRUE(a.rays == b.rays) << "rays differ";
  EXPECT_EQ(fd.duplicates, vd.duplicates);
}

Q2 site_of(const Point& p) { return {mpq_class(p.x()) / mpq_class(p.w()), mpq_class(p.y()) / mpq_class(p.w())}; }

mpq_class dist2(const Q2& a, const Q2& b) {
  const mpq_class dx = a.first - b.first, dy = a.second - b.second;
  return dx * dx + dy * dy;
}

/// Brute force: every vertex is equidistant from its sites, no site is nearer, and every circle
/// through three distinct sites with no site inside is a vertex with those sites among its own.
std::string certificate_error(const std::vector<Point>& p, const FortuneDiagram& fd) {
  std::vector<Q2> s;
  for (const Point& q : p) s.push_back(site_of(q));
  std::map<Q2, std::set<Index>> at;
  for (Index v = 0; v < fd.size(); ++v) {
    const Q2 c = cartesian(fd.vertex(v));
    const auto vs = fd.vertex_sites(v);
    if (vs.size() < 3) return "vertex with fewer than three cells";
    const mpq_class r = dist2(c, s[vs[0]]);
    for (Index a : vs)
      if (dist2(c, s[a]) != r) return "vertex " + std::to_string(v) + " not equidistant";
    for (const Q2& q : s)
      if (dist2(c, q) < r) return "a site is nearer than vertex " + std::to_string(v) + "'s sites";
    at[c].insert(vs.begin(), vs.end());
  }
  std::set<Index> dropped;
  for (auto [d, k] : fd.duplicates) dropped.insert(d);
  for (Index i = 0; i < s.size(); ++i)
    for (Index j = i + 1; j < s.size(); ++j)
      for (Index k = j + 1; k < s.size(); ++k) {
        if (dropped.count(i) || dropped.count(j) || dropped.count(k)) continue;
        const Q2 &a = s[i], &b = s[j], &c = s[k];
        const mpq_class bx = b.first - a.first, by = b.second - a.second, cx = c.first - a.first,
                        cy = c.second - a.second, D = 2 * (bx * cy - by * cx);
        if (sgn(D) == 0) continue;
        const mpq_class B = bx * bx + by * by, C = cx * cx + cy * cy;
        const Q2 o{a.first + (cy * B - by * C) / D, a.second + (bx * C - cx * B) / D};
        const mpq_class r = dist2(o, a);
        if (std::any_of(s.begin(), s.end(), [&](const Q2& q) { return dist2(o, q) < r; })) continue;
        const auto f = at.find(o);
        if (f == at.end() || !f->second.count(i) || !f->second.count(j) || !f->second.count(k))
          return "the empty circle through sites " + std::to_string(i) + ", " + std::to_string(j) + ", " +
                 std::to_string(k) + " is not a vertex";
      }
  return "";
}

std::vector<Point> integer_sites(std::size_t n, int range, std::mt19937& rng) {
  std::uniform_int_distribution<int> d(-range, range);
  std::vector<Point> p;
  for (std::size_t k = 0; k < n; ++k) p.push_back(Point(1, d(rng), d(rng)));
  return p;
}

TEST(Fortune, RandomFrontSitesEqualTheDualsFrontHalf) {
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    std::mt19937 rng(seed);
    for (std::size_t n : {4u, 10u, 50u, 300u}) expect_front_half(testing::scattered_sites(n, 1, rng));
  }
  std::mt19937 rng(7);
  expect_front_half(testing::scattered_sites(3000, 1, rng));
}

TEST(Fortune, WeightsOtherThanOne) {
  for (double w : {0.5, 3.0, 1e-3}) {
    std::mt19937 rng(11);
    expect_front_half(testing::scattered_sites(200, w, rng));
    expect_front_half(testing::grid_sites(200, 6, w, rng));
  }
  // One set of points, each site with its own weight: the same diagram.
  std::mt19937 rng(12);
  auto p = testing::grid_sites(100, 5, 1, rng);
  const FrontHalf a = of(fortune(p));
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = Point(double(1 << (k % 5)) * p[k].w(), double(1 << (k % 5)) * p[k].x(), double(1 << (k % 5)) * p[k].y());
  EXPECT_TRUE(of(fortune(p)).vertices == a.vertices);
}

TEST(Fortune, LatticeManyCocircularQuadruples) {
  std::vector<Point> p;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) p.push_back(Point(1, i, j));
  const FortuneDiagram fd = fortune(p);
  EXPECT_EQ(fd.size(), 19u * 19u);  // one vertex per square, four cells each
  for (Index v = 0; v < fd.size(); ++v) EXPECT_EQ(fd.vertex_sites(v).size(), 4u);
  expect_front_half(p);
  std::mt19937 rng(5);
  for (int k = 0; k < 5; ++k) expect_front_half(testing::grid_sites(150, 4, 1, rng));  // dense: many duplicates
  for (int side : {10, 30}) expect_front_half(testing::grid_sites(2000, side, 1, rng));  // every degeneracy at once
}

// The exact stages on doubles (fortune_exact.hpp) and the translation test of equal circles
// meet lattices: a triangular lattice (rows of equal circles, triples turned), a square grid
// turned by 45 degrees (circle tops on site rows: event and site at one point), one grid with
// half its sites at weight 3 (doubles and rationals mixed in one sweep), with duplicates and a
// collinear row; mirror-symmetric sets; each about 3000 sites, against the dual.
TEST(Fortune, LatticesOfThousandsOfSitesEqualTheDual) {
  std::vector<Point> tri, turned, mixed;
  for (int i = 0; i < 55; ++i)
    for (int j = 0; j < 55; ++j) {
      tri.push_back(Point(1, 2 * j + (i % 2), 3 * i));  // near-equilateral: rows of equal circles
      turned.push_back(Point(1, i + j, i - j));
      const double w = (i + j) % 2 ? 3 : 1;
      mixed.push_back(Point(w, w * (i % 40), w * j));  // i and i - 40 coincide: duplicates
    }
  for (int k = 0; k < 50; ++k) mixed.push_back(Point(1, -5, k));  // a collinear column beside it
  // Symmetric left to right (mirror circles: one y, the x order by centre_x_vs): 3000 points of a
  // circle rounded to integers (jc_voronoi's pathological circles, larger), and random pairs.
  std::vector<Point> round, mirror;
  for (int k = 0; k < 3000; ++k) {
    const double t = 2 * std::numbers::pi * k / 3000;
    round.push_back(Point(1, std::round(std::cos(t) * 1048576), std::round(std::sin(t) * 1048576)));
  }
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> d(1, 60);
  for (int k = 0; k < 1500; ++k) {
    const int x = d(rng), y = d(rng);
    mirror.push_back(Point(1, 7 + x, y));
    mirror.push_back(Point(1, 7 - x, y));
  }
  for (const auto& p : {tri, turned, mixed, round, mirror}) {
    expect_front_half(p);
    const FortuneDiagram fd = fortune(p);
    for (Index v = 0; v < fd.size(); ++v) ASSERT_GE(fd.vertex_sites(v).size(), 3u);
  }
}

TEST(Fortune, SitesOnOneCircle) {
  std::vector<Point> p;  // Pythagorean points of the circle of radius 25
  for (auto [x, y] : std::vector<std::pair<int, int>>{{25, 0}, {24, 7}, {20, 15}, {15, 20}, {7, 24}, {0, 25}, {-7, 24}, {-15, 20}, {-20, 15}, {-24, 7}, {-25, 0}, {-24, -7}, {-20, -15}, {-15, -20}, {-7, -24}, {0, -25}, {7, -24}, {15, -20}, {20, -15}, {24, -7}})
    p.push_back(Point(1, x, y));
  const FortuneDiagram fd = fortune(p);
  ASSERT_EQ(fd.size(), 1u);
  EXPECT_EQ(fd.vertex_sites(0).size(), 20u);
  EXPECT_EQ(fd.edges.size(), 0u);
  EXPECT_EQ(fd.rays.size(), 20u);
  EXPECT_EQ(certificate_error(p, fd), "");
  expect_front_half(p);
}

TEST(Fortune, DuplicatesCollinearAndRows) {
  const std::vector<Point> dup{Point(1, 0, 0), Point(2, 2, 4), Point(1, 0, 0), Point(1, 3, 1), Point(1, 1, 2)};
  const FortuneDiagram fd = fortune(dup);
  EXPECT_EQ(fd.duplicates, (std::vector<std::pair<Index, Index>>{{2, 0}, {4, 1}}));
  EXPECT_EQ(certificate_error(dup, fd), "");
  expect_front_half(dup);
  for (auto line : {std::vector<Point>{Point(1, 0, 0), Point(1, 1, 1), Point(1, 3, 3), Point(1, 2, 2)},
                    std::vector<Point>{Point(1, 0, 5), Point(1, 3, 5), Point(1, 1, 5), Point(1, 9, 5)},
                    std::vector<Point>{Point(1, 2, 0), Point(1, 2, 7), Point(1, 2, 3)}}) {
    const FortuneDiagram c = fortune(line);
    EXPECT_TRUE(c.size() == 0);
    EXPECT_EQ(c.lines.size(), line.size() - 1);
    std::set<std::pair<Index, Index>> got;
    for (auto [s, t] : c.lines) got.insert({std::min(s, t), std::max(s, t)});
    std::vector<Index> order(line.size());  // consecutive along the line
    for (Index k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](Index a, Index b) { return std::pair(line[a].x(), line[a].y()) < std::pair(line[b].x(), line[b].y()); });
    for (Index k = 0; k + 1 < order.size(); ++k) EXPECT_TRUE(got.count({std::min(order[k], order[k + 1]), std::max(order[k], order[k + 1])}));
  }
  // Rows of equal y, the first one long: vertical rays first, then sites on breakpoints.
  std::vector<Point> rows;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 7; ++x) rows.push_back(Point(1, 2 * x + (y % 2), y));
  expect_front_half(rows);
  EXPECT_EQ(certificate_error(rows, fortune(rows)), "");
}

TEST(Fortune, TwoAndThreeSitesAndBreakpointHits) {
  const std::vector<Point> two{Point(1, 0, 0), Point(1, 1, 3)};
  const FortuneDiagram a = fortune(two);
  EXPECT_TRUE(a.size() == 0);
  ASSERT_EQ(a.lines.size(), 1u);
  const std::vector<Point> three{Point(1, 0, 0), Point(1, 4, 0), Point(1, 1, 3)};
  const FortuneDiagram b = fortune(three);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b.rays.size(), 3u);
  expect_front_half(three);
  // The third site on the breakpoint of the first two at its sweep position; then a circle event
  // at a site (the circle through (−1, 0), (1, 0), (0, 1) has its top at (0, 1)).
  for (auto p : {std::vector<Point>{Point(1, -1, 0), Point(1, 1, 0), Point(1, 0, 1)},
                 std::vector<Point>{Point(1, -1, 0), Point(1, 1, 0), Point(1, 0, 1), Point(1, 0, -1), Point(1, 0, 3)},
                 std::vector<Point>{Point(1, -3, 0), Point(1, 3, 0), Point(1, 0, -4), Point(1, 0, 5), Point(1, 5, 5)}}) {
    EXPECT_EQ(certificate_error(p, fortune(p)), "");
    expect_front_half(p);
  }
  EXPECT_THROW(fortune(std::vector<Point>{Point(1, 0, 0), Point(-1, 1, 1)}), Undefined);
}

TEST(Fortune, BruteForceOnSmallInputs) {
  std::mt19937 rng(21);
  for (int k = 0; k < 200; ++k) {
    const auto p = k % 2 ? testing::grid_sites(3 + k % 9, 2, 1, rng) : integer_sites(3 + k % 9, 3, rng);
    EXPECT_EQ(certificate_error(p, fortune(p)), "") << k;
  }
}

// Inputs that broke other Voronoi codes (voronoi_regressions.hpp): Fortune equals the dual on each,
// and the brute force certifies the small ones.
TEST(Fortune, InputsThatBrokeOtherVoronoiCodes) {
  for (const auto& in : testing::voronoi_regressions()) {
    SCOPED_TRACE(in.name);
    expect_front_half(in.sites);
    if (in.sites.size() <= 40) EXPECT_EQ(certificate_error(in.sites, fortune(in.sites)), "");
  }
}

TEST(Fortune, BoostPolygonCounts) {
  using boost::polygon::voronoi_diagram;
  int compared = 0;
  for (unsigned seed : {31u, 32u}) {
    std::mt19937 rng(seed);
    const auto p = integer_sites(2000, 1 << 20, rng);
    std::vector<boost::polygon::point_data<int>> q;
    for (const Point& x : p) q.push_back({int(x.x()), int(x.y())});
    voronoi_diagram<double> vd;
    boost::polygon::construct_voronoi(q.begin(), q.end(), &vd);
    const FortuneDiagram fd = fortune(p);
    if (!fd.duplicates.empty()) continue;  // Boost keeps no record of which it dropped
    EXPECT_EQ(fd.size(), vd.num_vertices());
    EXPECT_EQ(fd.edges.size() + fd.rays.size() + fd.lines.size(), vd.num_edges() / 2);
    ++compared;
  }
  EXPECT_GT(compared, 0);
}

}  // namespace
}  // namespace t2
