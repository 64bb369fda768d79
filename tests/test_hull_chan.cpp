// Chan's algorithm (t2/hull/chan.hpp): its tangent search against a brute force on small convex
// polygons full of degeneracies (every rotation of the polygon, u a vertex, u outside, u on an
// edge's line, collinear and repeated points), and the whole algorithm against Graham's scan,
// the exact brute force of hull_testing.hpp and its own orientation count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

#include "hull_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/hull/chan.hpp"
#include "t2/hull/convex_hull.hpp"

namespace t2 {
namespace {

using gen::Kind;
using testing::at;
using testing::CountingTraits;
using testing::same_cycle;
using testing::text;

std::vector<std::size_t> all(std::size_t n) {
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  return idx;
}

// Jarvis's rule by brute force: the vertex c of C (not u) with no vertex strictly right of
// u → c, the farthest from u if several; C.size() when there is none.
std::size_t brute_tangent(const std::vector<Point>& P, const std::vector<std::size_t>& C, const Point& u) {
  const ChartOrder<HullTraits> order{front_chart()};
  std::size_t best = C.size();
  for (std::size_t j = 0; j < C.size(); ++j) {
    const Point& c = P[C[j]];
    if (c == u) continue;
    bool ok = true;
    for (std::size_t x : C)
      ok = ok && orient(u, c, P[x]) >= 0;
    for (std::size_t x : C)
      if (P[x] != u && P[x] != c && orient(u, c, P[x]) == 0 && order.farther(u, c, P[x])) ok = false;
    if (ok) {
      EXPECT_EQ(best, C.size()) << "two tangent points";
      best = j;
    }
  }
  return best;
}

// u is a strict vertex of the hull of C ∪ {u} (the precondition of the tangent search).
bool strict_vertex(const std::vector<Point>& P, const std::vector<std::size_t>& C, const Point& u) {
  std::vector<Point> Q = at(P, C);
  Q.push_back(u);
  const auto h = graham(std::span<const Point>(Q), all(Q.size()), front_chart());
  return std::any_of(h.begin(), h.end(), [&](std::size_t i) { return Q[i] == u; });
}

// Every rotation of the group hull C and every u of `from` that meets the precondition.
int check_tangents(const std::vector<Point>& P, std::vector<std::size_t> C, const std::vector<Point>& from) {
  const ChartOrder<HullTraits> order{front_chart()};
  int checked = 0;
  for (const Point& u : from) {
    if (!strict_vertex(P, C, u)) continue;
    for (std::size_t r = 0; r < std::max<std::size_t>(1, C.size()); ++r) {  // C starting at each vertex
      const std::size_t want = brute_tangent(P, C, u), got = detail::tangent<HullTraits>(P, C, u, order);
      EXPECT_EQ(got, want) << "u = " << to_string(u) << ", C = " << text(at(P, C));
      ++checked;
      if (!C.empty()) std::rotate(C.begin(), C.begin() + 1, C.end());
    }
  }
  return checked;
}

// Small grids are full of collinear points: every group hull of a few random grid points, and u
// every point of a larger grid (outside, a vertex, on the line of an edge).
TEST(ChanTangent, AgreesWithBruteForceOnEveryRotation) {
  std::mt19937_64 rng(28);
  std::uniform_int_distribution<int> coord(-3, 3), size(1, 14);
  std::vector<Point> from;
  for (int x = -4; x <= 4; ++x)
    for (int y = -4; y <= 4; ++y) from.push_back(Point::cartesian(x, y));
  int checked = 0;
  std::size_t largest = 0;
  for (int trial = 0; trial < 120; ++trial) {
    std::vector<Point> P;
    for (int i = size(rng); i > 0; --i) P.push_back(Point(1 + trial % 2, coord(rng), coord(rng)));  // w = 1 or 2
    const auto C = graham(std::span<const Point>(P), all(P.size()), front_chart());
    largest = std::max(largest, C.size());
    checked += check_tangents(P, C, from);
  }
  EXPECT_GT(checked, 10000);
  EXPECT_GE(largest, 7u);
}

// A polygon of many vertices (exactly on a circle) and u far and near, on its edge lines and at
// its vertices: the binary search takes many steps.
TEST(ChanTangent, LargePolygonOnACircle) {
  gen::Options o;
  o.n = 64;
  const auto P = gen::points(Kind::circle, o);
  const auto C = graham(std::span<const Point>(P), all(P.size()), front_chart());
  ASSERT_GT(C.size(), 50u);
  std::vector<Point> from(P.begin(), P.end());
  for (std::size_t i = 0; i < C.size(); i += 3) {  // on the line of an edge, beyond either end
    const Point &a = P[C[i]], &b = P[C[(i + 1) % C.size()]];
    for (const Point& q : {mix(3.0, a, -2.0, b), mix(-2.0, a, 3.0, b)})  // exact: small integers
      if (q.w() != 0) from.push_back(q.w() > 0 ? q : antipode(q));
  }
  for (int k = 0; k < 16; ++k) from.push_back(Point(1, 3 * std::cos(k), 3 * std::sin(k)));
  EXPECT_GT(check_tangents(P, C, from), 4000);
}

// Chan's hull and Graham's, in the same chart, on every point kind of t2 gen and several sizes:
// the same vertices from the same start.
TEST(Chan, EqualsGrahamOnEveryKind) {
  for (Kind k : {Kind::uniform, Kind::disk, Kind::polygon_interior, Kind::normal, Kind::kuzmin, Kind::circle,
                 Kind::segment, Kind::boundary, Kind::grid, Kind::duplicates, Kind::both_sides, Kind::infinity,
                 Kind::circle_both_sides}) {
    for (std::size_t n : {0, 1, 2, 3, 4, 5, 17, 300, 3000}) {
      gen::Options o;
      o.n = n;
      o.seed = n + 5;
      const auto P = gen::points(k, o);
      const auto want = convex_hull(P, HullAlgorithm::graham), got = convex_hull(P, HullAlgorithm::chan);
      EXPECT_TRUE(same_cycle(at(P, got), at(P, want)))
          << gen::name(k) << " n = " << n << ": " << text(at(P, got)) << "\ngraham: " << text(at(P, want));
      if (P.empty() || std::any_of(P.begin(), P.end(), [](const Point& p) { return p.w() <= 0; })) continue;
      std::vector<std::size_t> h;
      const Chart chart = chart_for(std::span<const Point>(P), h);
      EXPECT_EQ(at(P, chan(std::span<const Point>(P), all(P.size()), chart)),
                at(P, graham(std::span<const Point>(P), all(P.size()), chart)))
          << gen::name(k) << " n = " << n;  // front: the same points, from the same start
    }
  }
}

// Tiny random sets on a 3×3 grid (collinear, repeated, scaled) against the hull by definition.
TEST(Chan, EqualsTheBruteForceOnTinySets) {
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<int> coord(-1, 1), scale(1, 3);
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<Point> P;
    for (int i = trial % 13; i > 0; --i) {
      const int s = scale(rng);
      P.push_back(Point(s, s * coord(rng), s * coord(rng)));
    }
    const auto got = at(P, convex_hull(P, HullAlgorithm::chan));
    const auto want = testing::brute_hull(P);
    ASSERT_TRUE(same_cycle(got, want)) << text(P) << "\nchan: " << text(got) << "\nbrute: " << text(want);
  }
}

// A hull of h exact circle points with many points inside: the rounds stop at the first
// m = 2^(2^t) ≥ h, and the count of orientation tests stays below 12 n log₂ h (h = 40 and h = 4,
// where the first round, m = 4, is the last).
struct VertexTrace {
  std::vector<std::size_t> vertices;
  void operator()(const trace::Report& r) {
    if (r.event == trace::Event::vertex) vertices.push_back(r.at[0]);
  }
};

TEST(Chan, OrientationTestsAndTrace) {
  gen::Options o;
  o.n = 40;
  const auto ring = gen::points(Kind::circle, o);
  o.n = 20000;
  auto P = gen::points(Kind::disk, o);
  for (auto& p : P) p = Point(2 * p.w(), p.x(), p.y());  // inside the disk of radius 1/2
  P.insert(P.end(), ring.begin(), ring.end());
  const auto want = at(P, convex_hull(P, HullAlgorithm::graham));
  CountingTraits::calls = 0;
  VertexTrace tr;
  const auto idx = all(P.size());
  const auto h = chan<CountingTraits>(std::span<const Point>(P), idx, front_chart(), tr);
  EXPECT_TRUE(same_cycle(at(P, h), want));
  const double n = double(P.size()), bound = 12 * n * std::log2(double(want.size()));
  EXPECT_LT(double(CountingTraits::calls), bound) << CountingTraits::calls;
  ASSERT_GE(tr.vertices.size(), h.size());  // the last round's vertices are the hull
  EXPECT_EQ(std::vector<std::size_t>(tr.vertices.end() - static_cast<std::ptrdiff_t>(h.size()), tr.vertices.end()), h);
  P.erase(P.begin() + 20000, P.end());  // the disk only, in a square
  for (const Point& c : {Point::cartesian(-1, -1), Point::cartesian(1, -1), Point::cartesian(1, 1),
                         Point::cartesian(-1, 1)})
    P.push_back(c);
  CountingTraits::calls = 0;
  EXPECT_EQ(convex_hull<CountingTraits>(P, HullAlgorithm::chan).size(), 4u);
  EXPECT_LT(double(CountingTraits::calls), 12 * double(P.size()) * 2) << CountingTraits::calls;
}

// What `t2 animate chan` narrates (chan.hpp's trace), checked by brute force: every group's hull
// is Graham's hull of its points, the groups of a round cover the input in order, and every
// tangent is Jarvis's rule on the hull of the group that holds it.
TEST(Chan, TraceTellsEachGroupHullAndTangent) {
  gen::Options o;
  o.n = 300;
  o.seed = 7;
  const auto P = gen::points(Kind::uniform, o);
  struct Told {
    std::vector<std::vector<std::size_t>> hulls, points;  // the group hulls, their points
    std::vector<std::array<std::size_t, 2>> tangents;
    std::vector<std::size_t> groups_at;                   // groups told before each tangent
    void operator()(const trace::Report& r) {
      if (r.event == trace::Event::group_hull) {
        hulls.emplace_back(r.chain.begin(), r.chain.end());
        points.emplace_back(r.through.begin(), r.through.end());
      } else if (r.event == trace::Event::tangent) {
        tangents.push_back({r.at[0], r.at[1]});
        groups_at.push_back(hulls.size());
      }
    }
  } told;
  const auto h = chan(std::span<const Point>(P), all(P.size()), front_chart(), told);
  EXPECT_TRUE(same_cycle(at(P, h), at(P, convex_hull(P, HullAlgorithm::graham))));
  ASSERT_GT(told.hulls.size(), 2u);
  ASSERT_FALSE(told.tangents.empty());
  std::size_t next = 0;  // the groups of a round deal the points 0, 1, 2, ... in order
  for (std::size_t g = 0; g < told.hulls.size(); ++g) {
    if (told.points[g].front() == 0) next = 0;  // a new round
    for (std::size_t i : told.points[g]) EXPECT_EQ(i, next++) << "group " << g;
    EXPECT_TRUE(same_cycle(at(P, told.hulls[g]),
                           at(P, told.points[g]).empty() ? std::vector<Point>{}
                                                         : at(P, graham(std::span<const Point>(P), told.points[g],
                                                                        front_chart()))))
        << "group " << g;
  }
  for (std::size_t t = 0; t < told.tangents.size(); ++t) {
    const auto [u, c] = told.tangents[t];
    std::size_t g = told.groups_at[t];  // the round's groups are the last ones told; find c's
    while (g > 0 && std::find(told.hulls[g - 1].begin(), told.hulls[g - 1].end(), c) == told.hulls[g - 1].end()) --g;
    ASSERT_GT(g, 0u) << "tangent " << t << ": p" << c << " is on no group hull";
    const auto& C = told.hulls[g - 1];
    EXPECT_EQ(C[brute_tangent(P, C, P[u])], c) << "tangent " << t << " from p" << u;
  }
}

}  // namespace
}  // namespace t2
