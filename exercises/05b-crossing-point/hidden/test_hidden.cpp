// Exercise 05b, hidden tests. Oracle, in exact rationals and by another route than the meet:
// the point αa + βb of the line ab that is on the line cd has (α, β) ∝ (b·M, −a·M), M = c × d;
// the sign that makes α, β ≥ 0 (if any) gives the only candidate of segment ab, which must then
// be γc + δd with γ, δ ≥ 0 as well.
#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <random>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "crossing.hpp"

namespace {

using t2::Point;
using t2::Rational;
using R3 = std::array<Rational, 3>;

R3 vec(const Point& p) { return {t2::to_rational(p.w()), t2::to_rational(p.x()), t2::to_rational(p.y())}; }
R3 cross(const R3& p, const R3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
Rational dot(const R3& p, const R3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
R3 comb(const Rational& s, const R3& p, const Rational& t, const R3& q) {
  return {s * p[0] + t * q[0], s * p[1] + t * q[1], s * p[2] + t * q[2]};
}
bool is_zero(const R3& p) { return p[0] == 0 && p[1] == 0 && p[2] == 0; }
bool same_point(const R3& p, const R3& q) { return is_zero(cross(p, q)) && dot(p, q) > 0; }

// The point of segment pq on the line l, if exactly one: (α, β) = ±(q·l, −p·l) with α, β ≥ 0.
std::optional<R3> point_on_line(const R3& p, const R3& q, const R3& l) {
  const Rational s = dot(q, l), t = -dot(p, l);
  if (s >= 0 && t >= 0 && !(s == 0 && t == 0)) return comb(s, p, t, q);
  if (s <= 0 && t <= 0 && !(s == 0 && t == 0)) return comb(-s, p, -t, q);
  return std::nullopt;
}

std::optional<R3> oracle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const R3 A = vec(a), B = vec(b), C = vec(c), D = vec(d);
  const R3 L = cross(A, B), M = cross(C, D);
  if (is_zero(cross(L, M))) return std::nullopt;  // one line
  const auto p = point_on_line(A, B, M), q = point_on_line(C, D, L);
  if (p && q && same_point(*p, *q)) return p;
  return std::nullopt;
}

void check(const Point& a, const Point& b, const Point& c, const Point& d) {
  const auto want = oracle(a, b, c, d);
  const std::string where = t2::to_string(a) + " " + t2::to_string(b) + " / " + t2::to_string(c) + " " + t2::to_string(d);
  if (!want) {
    EXPECT_THROW(ex05b::crossing(a, b, c, d), t2::Undefined) << where;
    return;
  }
  const t2::ExactPoint got = ex05b::crossing(a, b, c, d);
  const R3 g = {Rational(got.w()), Rational(got.x()), Rational(got.y())};
  EXPECT_TRUE(same_point(g, *want)) << where << " gave " << t2::to_string(got);
}

bool parallel(const Point& p, const Point& q) { return is_zero(cross(vec(p), vec(q))); }

void random_pairs(int seed, int n, int wmin) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> c(-4, 4), w(wmin, 2);
  auto pt = [&] {
    for (;;) {
      const double pw = w(rng), px = c(rng), py = c(rng);
      if (pw != 0 || px != 0 || py != 0) return Point(pw, px, py);
    }
  };
  for (int i = 0; i < n; ++i) {
    const Point a = pt(), b = pt(), p = pt(), q = pt();
    if (parallel(a, b) || parallel(p, q)) continue;
    check(a, b, p, q);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(Hidden, FrontSegmentsAgreeWithOracle) { random_pairs(3, 2000, 1); }

TEST(Hidden, SegmentsThroughInfinity) { random_pairs(5, 3000, -2); }

TEST(Hidden, AntipodalCopiesDoNotMeet) {
  // cd is the antipodal copy of a segment that crosses ab: drawn, they cross; in T² they do not.
  check(Point(1, 0, 0), Point(1, 2, 0), Point(-1, -1, -1), Point(-1, -1, 1));
  check(Point(1, 0, 0), Point(1, 2, 0), Point(1, 1, -1), Point(1, 1, 1));  // the copy itself crosses
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> c(-4, 4);
  for (int i = 0; i < 500; ++i) {
    const Point a(1, c(rng), c(rng)), b(1, c(rng), c(rng)), p(1, c(rng), c(rng)), q(1, c(rng), c(rng));
    if (parallel(a, b) || parallel(p, q)) continue;
    check(a, b, p, q);
    check(a, b, t2::antipode(p), t2::antipode(q));
    check(t2::antipode(a), t2::antipode(b), p, q);
  }
}

TEST(Hidden, CommonEndpoint) {
  check(Point(1, 0, 0), Point(1, 1, 0), Point(1, 1, 0), Point(1, 1, 1));
  check(Point(-1, 0, 0), Point(0, 1, 0), Point(0, 1, 0), Point(1, 1, 1));
  check(Point(1, 0, 0), Point(1, 1, 0), Point(2, 2, 2), Point(2, 2, 0));
}

}  // namespace
