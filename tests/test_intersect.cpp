// Segment intersection (chapter 13): brute force and sweep against oracles that share no code
// with them: exact rationals for "the point lies on the segment" and "the two segments meet"
// (written here from the definition of a segment of T², αa + βb with α, β ≥ 0), the brute force
// as the sweep's reference, and CGAL's compute_intersection_points on front input.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "cgal/cgal_oracle.hpp"
#include "t2/gen/generate.hpp"
#include "t2/intersect/intersections.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using t2::Rational;
using testing::triple;
using R3 = std::array<Rational, 3>;

R3 cross(const R3& a, const R3& b) {
  return {Rational(a[1] * b[2] - a[2] * b[1]), Rational(a[2] * b[0] - a[0] * b[2]),
          Rational(a[0] * b[1] - a[1] * b[0])};
}
bool zero(const R3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
Rational dot(const R3& a, const R3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
/// p = t·a for some t > 0: the same point of T².
bool same(const R3& p, const R3& a) { return zero(cross(p, a)) && dot(p, a) > 0; }
R3 neg(const R3& a) { return {Rational(-a[0]), Rational(-a[1]), Rational(-a[2])}; }

/// Is p = αa + βb with α, β ≥ 0 (the segment from a to b of T²)? Cramer's rule on the first
/// pair of coordinates where a and b are independent, then the third coordinate checked.
bool on_oracle(const R3& p, const R3& a, const R3& b) {
  if (same(a, b)) return same(p, a);
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const Rational d = a[i] * b[j] - a[j] * b[i];
      if (d == 0) continue;
      const Rational alpha = (p[i] * b[j] - p[j] * b[i]) / d, beta = (a[i] * p[j] - a[j] * p[i]) / d;
      for (int k = 0; k < 3; ++k)
        if (alpha * a[k] + beta * b[k] != p[k]) return false;
      return alpha >= 0 && beta >= 0;
    }
  ADD_FAILURE() << "a and b are antipodal";
  return false;
}
bool on_oracle(const R3& p, const Segment& s) { return on_oracle(p, triple(s.source()), triple(s.target())); }

/// Do s and t share a point? Their great circles meet at ±(n₁ × n₂) unless they are one circle,
/// where two arcs shorter than a half circle meet iff one holds an endpoint of the other.
bool meet_oracle(const Segment& s, const Segment& t) {
  const R3 a = triple(s.source()), b = triple(s.target()), c = triple(t.source()), d = triple(t.target());
  if (same(a, b)) return on_oracle(a, c, d);
  if (same(c, d)) return on_oracle(c, a, b);
  const R3 m = cross(cross(a, b), cross(c, d));
  if (zero(m)) return on_oracle(a, c, d) || on_oracle(b, c, d) || on_oracle(c, a, b) || on_oracle(d, a, b);
  return (on_oracle(m, a, b) && on_oracle(m, c, d)) || (on_oracle(neg(m), a, b) && on_oracle(neg(m), c, d));
}

/// Everything the answer must be, checked by the oracles: each point lists exactly the segments
/// through it, is an endpoint or a crossing (intersections.hpp), and every meeting pair is
/// listed together at some point.
void check_answer(const std::vector<Segment>& S, const std::vector<IntersectionPoint>& out) {
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& ip : out) {
    const R3 p = triple(ip.point);
    std::vector<std::size_t> on;
    for (std::size_t k = 0; k < S.size(); ++k)
      if (on_oracle(p, S[k])) on.push_back(k);
    ASSERT_EQ(on, ip.segments) << to_line(ip);
    ASSERT_GE(on.size(), 2u) << to_line(ip);
    bool endpoint = false, crossing = false;
    for (std::size_t k : on) endpoint |= same(p, triple(S[k].source())) || same(p, triple(S[k].target()));
    for (std::size_t k : on)
      crossing |= !zero(cross(cross(triple(S[on[0]].source()), triple(S[on[0]].target())),
                              cross(triple(S[k].source()), triple(S[k].target()))));
    EXPECT_TRUE(endpoint || crossing) << "an inner point of an overlap: " << to_line(ip);
    for (std::size_t i : on)
      for (std::size_t j : on)
        if (i < j) pairs.insert({i, j});
  }
  for (std::size_t i = 0; i < S.size(); ++i)
    for (std::size_t j = i + 1; j < S.size(); ++j)
      if (meet_oracle(S[i], S[j])) {
        EXPECT_TRUE(pairs.count({i, j})) << "missed: segments " << i << " and " << j;
      }
}

std::vector<std::string> lines(const std::vector<IntersectionPoint>& v) {
  std::vector<std::string> s;
  for (const auto& p : v) s.push_back(to_line(p));
  return s;
}

/// Brute force checked by the oracles, and the sweep equal to it line for line.
void check_both(const std::vector<Segment>& S) {
  const auto brute = intersections_brute(S);
  check_answer(S, brute);
  EXPECT_EQ(lines(intersections_sweep(S)), lines(brute));
}

/// n segments with endpoints on the small grid {0..g}²: shared endpoints, collinear overlaps,
/// vertical and zero-length segments, many segments through one point. Each endpoint written
/// with a random positive weight (homogeneous, and dyadic when the weight is a power of two).
std::vector<Segment> grid_segments(std::mt19937_64& rng, int n, int g) {
  std::uniform_int_distribution<int> c(0, g), w(1, 4);
  auto point = [&] {
    const double k = w(rng);
    return Point(k == 3 ? 1 : k, (k == 3 ? 1 : k) * c(rng), (k == 3 ? 1 : k) * c(rng));
  };
  std::vector<Segment> S;
  for (int i = 0; i < n; ++i) S.emplace_back(point(), point());
  return S;
}

TEST(Intersect, SweepEqualsBruteOnRandomCrossings) {
  for (std::uint64_t seed = 1; seed <= 3u * testing::scale(); ++seed) {
    gen::Options o;
    o.n = 120;
    o.crossings = 200;
    o.seed = seed;
    const auto S = gen::segments(o);
    const auto out = intersections_sweep(S);
    std::size_t proper = 0;
    for (const auto& p : out) proper += p.segments.size() == 2;
    EXPECT_EQ(out.size(), o.crossings);  // the generator makes exactly this many, no other contact
    EXPECT_EQ(proper, o.crossings);
    check_both(S);
  }
}

TEST(Intersect, SweepEqualsBruteOnDegenerateGrids) {
  std::mt19937_64 rng(26);
  for (int round = 0; round < 60 * testing::scale(); ++round) {
    SCOPED_TRACE(round);
    check_both(grid_segments(rng, 40, round % 2 == 0 ? 3 : 6));
  }
}

TEST(Intersect, Star) {  // 2k segments through the origin, and one through it only at its end
  std::vector<Segment> S;
  for (int k = 1; k <= 6; ++k) S.emplace_back(Point(1, -k, -1), Point(1, k, 1));
  for (int k = 1; k <= 6; ++k) S.emplace_back(Point(1, -1, k), Point(1, 1, -k));
  S.emplace_back(Point(1, 0, 0), Point(1, 5, 7));
  S.emplace_back(Point(1, 0, -3), Point(1, 0, 3));  // vertical through the centre
  const auto out = intersections_sweep(S);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(to_line(out[0]), "1 0 0  0 1 2 3 4 5 6 7 8 9 10 11 12 13");
  check_both(S);
}

// Pencils: segments through a few common points (inside them, or ending there; some on one
// line, some vertical, some through two of the points), among segments crossing them elsewhere.
// The sweep schedules a crossing only once for all the pairs through one point (sweep.cpp):
// a crossing taken for one already waiting, or a segment taken to pass through the event, is a
// point missed or a segment wrongly listed, which brute force (checked by the oracles) shows.
TEST(Intersect, PencilsAmongOtherCrossings) {
  std::mt19937_64 rng(1326);
  std::uniform_int_distribution<int> small(-4, 4), wide(-9, 9), len(1, 3), kind(0, 9), w(0, 2);
  for (int round = 0; round < 20 * testing::scale(); ++round) {
    SCOPED_TRACE(round);
    std::array<std::array<int, 2>, 3> centre;
    for (auto& c : centre) c = {small(rng), small(rng)};
    std::vector<Segment> S;
    auto add = [&](std::array<int, 2> p, std::array<int, 2> q) {
      const double k = 1 << w(rng), l = 1 << w(rng);
      S.emplace_back(Point(k, k * p[0], k * p[1]), Point(l, l * q[0], l * q[1]));
    };
    while (S.size() < 50) {
      const auto& c = centre[S.size() % 3];
      const auto& c2 = centre[(S.size() + 1) % 3];
      std::array<int, 2> d{small(rng), small(rng)};
      if (d[0] == 0 && d[1] == 0) continue;
      const int t = len(rng), u = len(rng), r = kind(rng);
      const std::array<int, 2> back{c[0] - t * d[0], c[1] - t * d[1]}, ahead{c[0] + u * d[0], c[1] + u * d[1]};
      if (r < 4) {
        add(back, ahead);  // through c
      } else if (r < 6) {
        if (r % 2) add(c, ahead);  // ends at c
        else add(back, c);
      } else if (r == 6 && c != c2) {  // through c and c2
        add({2 * c[0] - c2[0], 2 * c[1] - c2[1]}, {2 * c2[0] - c[0], 2 * c2[1] - c[1]});
      } else {
        add({wide(rng), wide(rng)}, {wide(rng), wide(rng)});
      }
    }
    check_both(S);
  }
}

TEST(Intersect, GridOfHorizontalsAndVerticals) {  // unit cells: every inner node is an endpoint
  std::vector<Segment> S;
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; j < 5; ++j) {
      S.emplace_back(Point(1, j, i), Point(1, j + 1, i));
      S.emplace_back(Point(1, i, j), Point(1, i, j + 1));
    }
  S.emplace_back(Point(1, -1, 2.5), Point(1, 6, 2.5));  // crosses every vertical between nodes
  const auto out = intersections_sweep(S);
  EXPECT_EQ(out.size(), 36u + 6u);  // every node (each on two edges or more), and 6 crossings
  check_both(S);
}

TEST(Intersect, OverlapsReportTheEndsOfTheCommonPiece) {
  const std::vector<Segment> S = {
      {Point(1, 0, 0), Point(1, 4, 4)}, {Point(1, 1, 1), Point(1, 6, 6)},  // common piece (1,1)-(4,4)
      {Point(1, 2, 0), Point(1, 2, 9)},                                    // crosses it at (2,2)
      {Point(1, 5, 5), Point(1, 5, 5)},                                    // a point inside segment 1
      {Point(2, 0, 0), Point(2, 8, 8)},                                    // segment 0 again, scaled
  };
  EXPECT_EQ(lines(intersections_sweep(S)),
            (std::vector<std::string>{"1 0 0  0 4", "1 1 1  0 1 4", "1 2 2  0 1 2 4", "1 4 4  0 1 4", "1 5 5  1 3"}));
  check_both(S);
}

TEST(Intersect, BruteForceOnTheWholeOfT2) {  // back, crossing Ω, rays and arcs of Ω
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<int> c(-3, 3), w(-1, 1);
  for (int round = 0; round < 40 * testing::scale(); ++round) {
    std::vector<Segment> S;
    while (S.size() < 30) {
      double a[6];
      for (int k = 0; k < 6; ++k) a[k] = k % 3 == 0 ? w(rng) : c(rng);
      if ((a[0] == 0 && a[1] == 0 && a[2] == 0) || (a[3] == 0 && a[4] == 0 && a[5] == 0)) continue;
      const Point p(a[0], a[1], a[2]), q(a[3], a[4], a[5]);
      if (p == antipode(q)) continue;
      S.emplace_back(p, q);
    }
    const auto out = intersections_brute(S);
    check_answer(S, out);
    bool front = true;
    for (const auto& s : S) front &= s.source().w() > 0 && s.target().w() > 0;
    if (!front) {
      EXPECT_THROW(intersections_sweep(S), Undefined);
    }
  }
}

TEST(Intersect, AgreesWithCgal) {
  // CGAL with report_endpoints = false leaves out the points where every segment through the
  // point ends there (two segments that only share an endpoint): so do we, for the comparison.
  std::vector<Segment> S;
  auto cartesian = [&S](const std::vector<IntersectionPoint>& v) {
    std::vector<std::array<Rational, 2>> pts;
    for (const auto& p : v) {
      bool inner = false;
      for (std::size_t k : p.segments)
        inner |= !same(triple(p.point), triple(S[k].source())) && !same(triple(p.point), triple(S[k].target()));
      if (inner) pts.push_back(testing::pos(p.point));
    }
    std::sort(pts.begin(), pts.end());
    return pts;
  };
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    gen::Options o;
    o.n = 400;
    o.crossings = 1000;
    o.seed = seed;
    S = gen::segments(o);
    EXPECT_EQ(cartesian(intersections_sweep(S)), testing::cgal::intersection_points_2(S));
  }
}

// CGAL 5.5.1 (Debian 12) is not an oracle on degenerate grids. Its sweep breaks its own status
// line's precondition (Multiset.h: "comp_f(object, parentP->object) != SMALLER", seen with
// CGAL's checks on, for Epeck and for Cartesian<Gmpq> alike) on these four segments: three of
// them cross at (5/2, 5/2) and the fourth ends at (3, 2), inside the first. Built with NDEBUG it
// goes on, leaks the status line's nodes (LeakSanitizer's report sent us here) and reports three
// points, not four: (3, 2) is missed. The degenerate grids are therefore checked against the
// rational oracle and brute force only (SweepEqualsBruteOnDegenerateGrids), and this input stays
// as the regression test for the point CGAL misses; CGAL is not called on it.
TEST(Intersect, TheEndpointCgalMissesBesideATriplePoint) {
  const std::vector<Segment> S = {{Point(1, 2, 3), Point(1, 5, 0)},
                                  {Point(1, 5, 2), Point(1, 0, 3)},
                                  {Point(1, 3, 4), Point(1, 2, 1)},
                                  {Point(1, 1, 3), Point(1, 3, 2)}};
  const auto out = intersections_sweep(S);
  check_answer(S, out);
  std::vector<std::string> got;
  for (const auto& p : out) got.push_back(to_line(p));
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, (std::vector<std::string>{"1 3 2  0 3", "2 5 5  0 1 2", "3 5 8  1 3", "7 17 16  2 3"}));
}

TEST(Intersect, TheOneAlgorithmEntryAndTheLineFormat) {
  const std::vector<Segment> S = {{Point(1, 0, 0), Point(1, 2, 2)}, {Point(1, 0, 2), Point(1, 2, 0)}};
  EXPECT_EQ(lines(intersections(S, IntersectAlgorithm::brute)), std::vector<std::string>{"1 1 1  0 1"});
  EXPECT_EQ(lines(intersections(S, IntersectAlgorithm::sweep)), std::vector<std::string>{"1 1 1  0 1"});
  EXPECT_STREQ(name(IntersectAlgorithm::sweep), "sweep");
  EXPECT_EQ(to_line({reduced(ExactPoint(-4, 6, 2)), {3}}), "-2 3 1  3");
}

}  // namespace
}  // namespace t2
