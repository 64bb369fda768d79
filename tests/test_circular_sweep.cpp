// The circular sweep of T² (chapter 13, intersect/circular.cpp) against the brute force on every
// kind of segment (front, back, through Ω, on Ω, one point) and on the degenerate sets that the
// sweep's own geometry makes hard: segments on lines through its default centre [1, 0, 0], through
// that centre's antipode, on the initial half-line y = 0, x > 0 and crossing it at one point.
// Every reported point is certified with GMP integers: it lies on every segment it names.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "t2/gen/generate.hpp"
#include "t2/intersect/intersections.hpp"
#include "t2/kernel/join_meet.hpp"
#include "t2/kernel/orient.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using Z3 = std::array<Integer, 3>;

Z3 z3(const ExactPoint& p) { return {p.w(), p.x(), p.y()}; }
Z3 z3(const Point& p) { return z3(to_exact(p)); }
Z3 cross3(const Z3& a, const Z3& b) {
  return {Integer(a[1] * b[2] - a[2] * b[1]), Integer(a[2] * b[0] - a[0] * b[2]), Integer(a[0] * b[1] - a[1] * b[0])};
}
Integer dot3(const Z3& a, const Z3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const Z3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

/// The certificate: p = αa + βb with α, β ≥ 0 not both zero. With n = a × b ≠ 0 that is p·n = 0,
/// (a × p)·n = β|n|² ≥ 0 and (p × b)·n = α|n|² ≥ 0; for a = b (one point), p = λa with λ > 0.
bool lies_on(const Z3& p, const Segment& s) {
  const Z3 a = z3(s.source()), b = z3(s.target()), n = cross3(a, b);
  if (is_zero(n)) return is_zero(cross3(p, a)) && sgn(dot3(p, a)) > 0;  // a = b (a = ¬b is no segment)
  return sgn(dot3(p, n)) == 0 && sgn(dot3(cross3(a, p), n)) >= 0 && sgn(dot3(cross3(p, b), n)) >= 0;
}

/// The answer as `t2 intersect` prints it, one line per point.
std::string text(const std::vector<IntersectionPoint>& out) {
  std::string all;
  for (const auto& p : out) all += to_line(p) + "\n";
  return all;
}

/// The circular sweep gives the brute force's answer, and each of its points lies on every
/// segment it names.
void check(const std::vector<Segment>& S) {
  const auto circular = intersections_circular(S);
  EXPECT_EQ(text(circular), text(intersections_brute(S)));
  for (const auto& ip : circular) {
    ASSERT_GE(ip.segments.size(), 2u) << to_line(ip);
    for (std::size_t k : ip.segments) EXPECT_TRUE(lies_on(z3(ip.point), S[k])) << to_line(ip) << " s" << k;
  }
}

/// A random point with small integer coordinates: w in [wlo, whi], x, y in [-c, c], not [0,0,0].
Point random_point(std::mt19937_64& rng, int wlo, int whi, int c) {
  std::uniform_int_distribution<int> W(wlo, whi), C(-c, c);
  for (;;) {
    const int w = W(rng), x = C(rng), y = C(rng);
    if (w != 0 || x != 0 || y != 0) return Point(w, x, y);
  }
}

/// n segments from `point` (a = ¬b is drawn again).
template <class F>
std::vector<Segment> random_segments(std::size_t n, F&& point) {
  std::vector<Segment> S;
  while (S.size() < n) {
    const Point p = point(), q = point();
    if (!(p == antipode(q))) S.emplace_back(p, q);
  }
  return S;
}

TEST(CircularSweep, JoinMeetOrientAgreesWithTheConstructedPoints) {
  std::mt19937_64 rng(5);
  for (int round = 0; round < 2000; ++round) {
    Point q[9] = {random_point(rng, -2, 2, 3), random_point(rng, -2, 2, 3), random_point(rng, -2, 2, 3),
                  random_point(rng, -2, 2, 3), random_point(rng, -2, 2, 3), random_point(rng, -2, 2, 3),
                  random_point(rng, -2, 2, 3), random_point(rng, -2, 2, 3), random_point(rng, -2, 2, 3)};
    if (round % 3 == 0) q[5] = q[1];  // shared points: zero determinants
    if (round % 5 == 0) q[0] = q[2];
    const JoinMeet<double> X{&q[1], &q[2], &q[3], &q[4], ZERO}, Y{&q[5], &q[6], &q[7], &q[8], ZERO};
    // The points constructed here with GMP: [0,0,0] when undefined, and the sign is then 0.
    const Z3 x = cross3(cross3(z3(q[1]), z3(q[2])), cross3(z3(q[3]), z3(q[4])));
    const Z3 y = cross3(cross3(z3(q[5]), z3(q[6])), cross3(z3(q[7]), z3(q[8])));
    const int expected = sgn(dot3(z3(q[0]), cross3(x, y)));
    EXPECT_EQ(static_cast<int>(orient(q[0], X, Y)), expected) << round;
  }
}

TEST(CircularSweep, JoinMeetOrientIsExactOnNearDegenerateDoubles) {
  // Full 53-bit coordinates over many exponents: p = a puts p, X and Y on the line a ∨ b when Y
  // is on it too (the sign is 0 exactly), and p moved by one ulp gives a tiny nonzero sign.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> e(-60, 60);
  const auto point = [&] { return Point(1, std::ldexp(u(rng), e(rng)), std::ldexp(u(rng), e(rng))); };
  for (int round = 0; round < 500; ++round) {
    Point q[8] = {point(), point(), point(), point(), point(), point(), point(), point()};
    const JoinMeet<double> X{&q[0], &q[1], &q[2], &q[3], ZERO}, Y{&q[0], &q[1], &q[6], &q[7], ZERO};
    EXPECT_EQ(orient(q[0], X, Y), ZERO) << round;
    const Point p(1, std::nextafter(q[0].x(), 2.0), q[0].y());
    const Z3 x = cross3(cross3(z3(q[0]), z3(q[1])), cross3(z3(q[2]), z3(q[3])));
    const Z3 y = cross3(cross3(z3(q[0]), z3(q[1])), cross3(z3(q[6]), z3(q[7])));
    EXPECT_EQ(static_cast<int>(orient(p, X, Y)), sgn(dot3(z3(p), cross3(x, y)))) << round;
  }
}

TEST(CircularSweep, EqualsSweepAndBruteOnGeneratedCrossings) {
  for (std::uint64_t seed = 11; seed <= 10u + 3u * testing::scale(); ++seed) {
    const auto S = gen::segments({.n = 150, .seed = seed, .crossings = 250});
    const auto out = intersections_circular(S);
    EXPECT_EQ(out.size(), 250u);
    EXPECT_EQ(text(out), text(intersections_sweep(S)));
    check(S);
  }
}

TEST(CircularSweep, EveryKindOfSegment) {  // front, back, through Ω, on Ω, and all mixed
  std::mt19937_64 rng(26);
  const std::pair<int, int> w_ranges[] = {{1, 3}, {-3, -1}, {-1, 1}, {0, 0}, {-2, 2}};
  for (int round = 0; round < 60 * testing::scale(); ++round) {
    SCOPED_TRACE(round);
    const auto [lo, hi] = w_ranges[round % 5];
    const int c = round % 2 == 0 ? 3 : 9;
    if (round % 5 == 2) {  // through Ω: one end in front, the other behind
      check(random_segments(30, [&, flip = false]() mutable {
        flip = !flip;
        return flip ? random_point(rng, 1, 2, c) : random_point(rng, -2, -1, c);
      }));
    } else {
      check(random_segments(30, [&, lo = lo, hi = hi] { return random_point(rng, lo, hi, c); }));
    }
  }
}

TEST(CircularSweep, LinesThroughTheCentreAndItsAntipode) {
  // Every line through [1,0,0]: the sweep must move its centre. The star is through ¬o = [-1,0,0]
  // as well (back segments), and a segment passes through ¬o in its inside.
  std::vector<Segment> S;
  for (int k = 1; k <= 5; ++k) S.emplace_back(Point(1, -k, -1), Point(1, k, 1));
  for (int k = 1; k <= 5; ++k) S.emplace_back(Point(-1, -1, k), Point(-1, 1, -k));
  S.emplace_back(Point(1, 0, 0), Point(1, 5, 7));       // from the centre
  S.emplace_back(Point(-1, 0, 0), Point(-1, 3, -2));     // from its antipode
  S.emplace_back(Point(-1, 0, 0), Point(-1, 0, 0));      // ¬o, one point
  S.emplace_back(Point(1, 0, 0), Point(1, 0, 0));        // o, one point
  S.emplace_back(Point(-1, 2, 0), Point(-1, -2, 0));     // through ¬o in its inside, on y = 0
  S.emplace_back(Point(1, 1, 1), Point(1, 1, 1));        // [1,1,1] and [1,2,4]: the next candidates
  S.emplace_back(Point(1, 2, 4), Point(1, 3, 9));
  S.emplace_back(Point(1, 0, 1), Point(1, 2, 5));        // y = 2x + 1 holds [1,t,t²] for no integer... and 1+√2
  check(S);
  const auto out = intersections_circular(S);
  ASSERT_GE(out.size(), 2u);
}

TEST(CircularSweep, RandomLinesThroughTheOrigin) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> C(-4, 4), L(-3, 3);
  for (int round = 0; round < 40 * testing::scale(); ++round) {
    SCOPED_TRACE(round);
    std::vector<Segment> S;
    while (S.size() < 25) {  // a point p and ±λp: on a line through [1,0,0] (front, back, or through ¬o)
      const Point p = random_point(rng, -2, 2, 4);
      const double a = L(rng), b = L(rng);
      if ((a * p.w() + b == 0 && a * p.x() == 0 && a * p.y() == 0)) continue;
      const Point q(a * p.w() + b, a * p.x(), a * p.y());
      if (p == antipode(q)) continue;
      S.emplace_back(p, q);
      const Point u = random_point(rng, -1, 2, 4), v = random_point(rng, -1, 2, 4);
      if (round % 2 == 0 && !(u == antipode(v))) S.emplace_back(u, v);
    }
    check(S);
  }
}

TEST(CircularSweep, TheInitialHalfLine) {
  // The initial half-line from [1,0,0] through [0,1,0]: y = 0, x > 0 in front (and x < 0
  // behind). Segments crossing it, ending on it, starting on it, crossing each other on it.
  std::vector<Segment> S = {
      {Point(1, 2, -1), Point(1, 2, 1)},   // cut at (2, 0)
      {Point(1, 1, -1), Point(1, 3, 1)},   // cut at (2, 0) too: a crossing on the half-line
      {Point(1, 2, 0), Point(1, 5, 3)},    // starts there
      {Point(1, 4, -2), Point(1, 2, 0)},   // ends there
      {Point(1, 5, -1), Point(1, 5, 1)},   // cut at (5, 0), alone: nothing between its pieces
      {Point(1, 7, -1), Point(1, 7, 0)},   // ends at (7, 0)
      {Point(1, 7, 0), Point(1, 8, 1)},    // starts at (7, 0): the two meet only at M0
      {Point(-1, -3, -1), Point(-1, -3, 1)},  // behind: cut where the half-line goes on behind
      {Point(1, 6, -1), Point(1, 3, 2)},   // crosses segment 2 above the half-line
  };
  check(S);
  const auto out = intersections_circular(S);
  const std::string got = text(out);
  EXPECT_NE(got.find("1 2 0  0 1 2 3\n"), std::string::npos) << got;
  EXPECT_NE(got.find("1 7 0  5 6\n"), std::string::npos) << got;
  for (const auto& ip : out) EXPECT_NE(ip.segments, std::vector<std::size_t>{4});
  // One segment cut by the half-line alone: its two pieces meet at the cut, nothing to report.
  EXPECT_TRUE(intersections_circular({S[4]}).empty());
}

TEST(CircularSweep, TheSeedsFigure537) {
  // s0 crosses the initial half-line, and s1 crosses s0 just after it, before s0's far end:
  // a sweep started in the middle of s0 that never cut it would not have s0 in its status there.
  const std::vector<Segment> S = {{Point(1, 3, -2), Point(1, 1, 3)}, {Point(1, 1, 0.5), Point(1, 4, 1)}};
  EXPECT_EQ(intersections_circular(S).size(), 1u);
  check(S);
}

TEST(CircularSweep, DegenerateGrids) {  // shared endpoints, overlaps, many through one point, points
  std::mt19937_64 rng(31);
  for (int round = 0; round < 60 * testing::scale(); ++round) {
    SCOPED_TRACE(round);
    const int c = round % 3 == 0 ? 1 : 2;
    const int lo = round % 4 == 1 ? -2 : round % 4 == 2 ? 0 : 1;
    check(random_segments(40, [&] { return random_point(rng, lo, 2, c); }));
  }
}

TEST(CircularSweep, FullDoublesWithSharedEndpoints) {  // 53-bit coordinates, both sides, shared ends
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> side(0, 2);
  for (int round = 0; round < 20 * testing::scale(); ++round) {
    SCOPED_TRACE(round);
    std::vector<Point> pool;
    for (int k = 0; k < 30; ++k) pool.emplace_back(side(rng) == 0 ? -1.0 : 1.0, u(rng), u(rng));
    std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
    check(random_segments(50, [&] { return pool[pick(rng)]; }));
  }
}

TEST(CircularSweep, StarFansAndOverlaps) {
  std::vector<Segment> S;
  for (int k = 0; k < 8; ++k) S.emplace_back(Point(1, 3, 3), Point(1, 3 + (k % 3) - 1, 3 + (k / 3) - 1));
  for (int k = 0; k < 4; ++k) S.emplace_back(Point(1, k, 1), Point(1, k + 3, 1));  // overlaps on y = 1
  S.emplace_back(Point(1, 2, 1), Point(1, 2, 1));
  S.emplace_back(Point(2, 6, 2), Point(2, 6, 2));  // (3, 1) once more, scaled
  for (int k = 0; k < 5; ++k) S.emplace_back(Point(1, k, -1), Point(1, 4 - k, 5));  // through (2, 2)
  check(S);
}

// Pencils: segments through a few common points (inside them, or ending there; some through
// two of the points), in front, behind, on Ω and on the initial half-line, among segments
// crossing them elsewhere. The sweep schedules a crossing once for all the pieces through one
// point (circular.cpp): a crossing taken for one already waiting, or a piece taken to pass
// through the event, is a point missed or a segment wrongly listed, which brute force shows.
TEST(CircularSweep, PencilsAmongOtherCrossings) {
  std::mt19937_64 rng(1313);
  std::uniform_int_distribution<int> small(-4, 4), dir(-2, 2), len(1, 3), kind(0, 9), k2(0, 2);
  using H = std::array<double, 3>;  // homogeneous w, x, y
  const auto comb = [](double s, const H& a, double t, const H& b) {
    return H{s * a[0] + t * b[0], s * a[1] + t * b[1], s * a[2] + t * b[2]};
  };
  const auto independent = [](const H& a, const H& b) {
    return a[1] * b[2] != a[2] * b[1] || a[2] * b[0] != a[0] * b[2] || a[0] * b[1] != a[1] * b[0];
  };
  for (int round = 0; round < 20 * testing::scale(); ++round) {
    SCOPED_TRACE(round);
    std::array<H, 3> centre;  // behind, on Ω, in front; on y = 0 every third round
    for (int k = 0; k < 3; ++k)
      do centre[k] = {double(k - 1), double(small(rng)), round % 3 == 0 ? 0.0 : double(small(rng))};
      while (centre[k] == H{0, 0, 0});
    std::vector<Segment> S;
    const auto add = [&](const H& p, const H& q) {  // scaled by 1, 2 or 4
      const double a = 1 << k2(rng), b = 1 << k2(rng);
      const Point P(a * p[0], a * p[1], a * p[2]), Q(b * q[0], b * q[1], b * q[2]);
      if (!(P == antipode(Q))) S.emplace_back(P, Q);
    };
    while (S.size() < 60) {
      const H& c = centre[S.size() % 3];
      const H& c2 = centre[(S.size() + 1) % 3];
      const H d{double(dir(rng)), double(small(rng)), double(small(rng))};
      if (!independent(c, d)) continue;
      const double t = len(rng), u = len(rng);
      const int r = kind(rng);
      if (r < 4) add(comb(1, c, -t, d), comb(1, c, u, d));  // c strictly inside
      else if (r == 4) add(c, comb(1, c, u, d));             // starts at c
      else if (r == 5) add(comb(1, c, -t, d), c);            // ends at c
      else if (r == 6 && independent(c, c2)) add(comb(2, c, -1, c2), comb(2, c2, -1, c));
      else if (const H e{double(dir(rng)), double(small(rng)), double(small(rng))}; e != H{0, 0, 0})
        add(d, e);  // anywhere
    }
    check(S);
  }
}

TEST(CircularSweep, LargePencilsInFrontBehindAndOnOmega) {  // hundreds of pieces through one point
  gen::Options o;
  o.n = 400;
  o.seed = 5;
  const std::vector<Segment> P = gen::segments(gen::Kind::segments_through_point, o);
  std::vector<Segment> S = P;
  // The same segments mapped exactly (a linear map keeps segments): through ¬[1,0,0] behind,
  // [0,0,1] on Ω and [0,1,0] on Ω and on the initial half-line (cut there).
  const auto map = [&](std::size_t from, std::size_t to, auto f) {
    for (std::size_t k = from; k < to; ++k) S.emplace_back(f(P[k].source()), f(P[k].target()));
  };
  map(0, 150, [](const Point& p) { return Point(-p.w(), -p.y(), -p.x()); });
  map(150, 300, [](const Point& p) { return Point(p.y(), p.x(), p.w()); });
  map(300, 400, [](const Point& p) { return Point(p.x(), p.w(), p.y()); });
  check(S);
  const auto out = intersections_circular(S);
  std::size_t big = 0;
  for (const auto& ip : out) big += ip.segments.size() >= 100;
  EXPECT_EQ(big, 4u);
}

TEST(CircularSweep, TakesAnyCentreItNeedsOnLargerInput) {
  // Random segments through the points [1, t, t²] for t = 0..9 (candidate centres), and on
  // Ω: the search skips them all.
  std::mt19937_64 rng(99);
  std::vector<Segment> S;
  std::uniform_int_distribution<int> C(-20, 20);
  for (int t = 0; t < 10; ++t)
    for (int k = 0; k < 3; ++k) S.emplace_back(Point(1, t, t * t), Point(1, C(rng), C(rng)));
  S.emplace_back(Point(0, 1, 0), Point(0, 0, 1));
  S.emplace_back(Point(0, -1, 2), Point(0, 1, 1));
  check(S);
}

}  // namespace
}  // namespace t2
