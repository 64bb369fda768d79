// Exercise 05, reference solution: Algorithm 2 of seed 000 (§5.1) with chapter 05's four
// corrections, written from the chapter's proof rather than from the library.
// 1. On the boundary: q on some closed edge ab, i.e. q = αa + βb with α, β ≥ 0 (exercise 02).
// 2. Start from a vertex p0 ≠ ¬q, so that the walk p0 → q is a segment of T².
// 3. Perturb q to q_ε = q + εn, n off the line p0 ∨ q: every orientation with q becomes the sign
//    of Δ(q, ·, ·), or of Δ(n, ·, ·) when that is zero. The perturbed walk touches no vertex
//    but p0 and runs along no edge, and q_ε is on q's side (q is not on the boundary).
// 4. The side where the walk starts, from the two edge lines at p0 and the turn t at p0; then
//    each edge c d the walk crosses flips it. A crossing in T² is the four orientations plus the
//    fifth sign: c and d on opposite sides of the walk's line, p0 and q_ε on opposite sides of
//    the edge's line, and the walk's line seen from c in the right direction (Lc = −ka).
#include "locate.hpp"

#include <stdexcept>

#include <t2/kernel/error.hpp>
#include <t2/kernel/filter.hpp>
#include <t2/kernel/orient.hpp>

namespace ex05 {

namespace {

// (u × v)·(s × t) = (u·s)(v·t) − (u·t)(v·s), a polynomial of degree 4 (Binet–Cauchy).
const auto cross_dot = [](const auto& u0, const auto& u1, const auto& u2, const auto& v0, const auto& v1,
                          const auto& v2, const auto& s0, const auto& s1, const auto& s2, const auto& t0,
                          const auto& t1, const auto& t2_) {
  return (u0 * s0 + u1 * s1 + u2 * s2) * (v0 * t0 + v1 * t1 + v2 * t2_) -
         (u0 * t0 + u1 * t1 + u2 * t2_) * (v0 * s0 + v1 * s1 + v2 * s2);
};

t2::Sign cross_dot_sign(const t2::Point& u, const t2::Point& v, const t2::Point& s, const t2::Point& t) {
  return t2::sign_of_poly(cross_dot, u.w(), u.x(), u.y(), v.w(), v.x(), v.y(), s.w(), s.x(), s.y(), t.w(),
                          t.x(), t.y());
}

// The closed T² segment ab (a ≠ ±b) holds q: q on the line, and α, β ≥ 0 in q = αa + βb.
bool on_edge(const t2::Point& a, const t2::Point& b, const t2::Point& q) {
  if (t2::orient(a, b, q) != t2::ZERO) return false;
  return cross_dot_sign(q, b, a, b) >= 0 && cross_dot_sign(a, q, a, b) >= 0;
}

// ¬q = p exactly: all 2×2 minors of p, q vanish and p·q < 0.
bool antipodal(const t2::Point& p, const t2::Point& q) {
  const auto minor = [](const auto& a, const auto& b, const auto& c, const auto& d) { return a * d - b * c; };
  const auto dot = [](const auto& a, const auto& b, const auto& c, const auto& d, const auto& e, const auto& f) {
    return a * d + b * e + c * f;
  };
  return t2::sign_of_poly(minor, p.w(), p.x(), q.w(), q.x()) == t2::ZERO &&
         t2::sign_of_poly(minor, p.w(), p.y(), q.w(), q.y()) == t2::ZERO &&
         t2::sign_of_poly(minor, p.x(), p.y(), q.x(), q.y()) == t2::ZERO &&
         t2::sign_of_poly(dot, p.w(), p.x(), p.y(), q.w(), q.x(), q.y()) < 0;
}

}  // namespace

t2::Sign locate(const std::vector<t2::Point>& P, const t2::Point& q) {
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    if (on_edge(P[i], P[(i + 1) % n], q)) return t2::ZERO;
  std::size_t k = 0;
  while (antipodal(P[k], q)) ++k;  // at most one vertex is ¬q
  const auto p = [&](std::size_t i) -> const t2::Point& { return P[(k + i) % n]; };
  const t2::Point& p0 = p(0);
  // A unit vector off the line p0 ∨ q (one of the three always is: p0 ≠ ±q).
  const t2::Point units[3] = {t2::Point(1, 0, 0), t2::Point(0, 1, 0), t2::Point(0, 0, 1)};
  const t2::Point* nn = nullptr;
  for (const auto& e : units)
    if (!nn && t2::orient(p0, q, e) != t2::ZERO) nn = &e;
  if (!nn) throw std::logic_error("locate: q = ±p0 after the boundary test");
  const auto oq = [&](const t2::Point& a, const t2::Point& b) {  // Δ(q_ε, a, b)
    const t2::Sign s = t2::orient(q, a, b);
    return s != t2::ZERO ? s : t2::orient(*nn, a, b);
  };
  t2::Sign s = oq(p0, p(1));
  const t2::Sign t = t2::orient(p(n - 1), p0, p(1));
  const t2::Sign b = oq(p(n - 1), p0);
  if (s * b == t2::NEGATIVE) {
    if (t == t2::ZERO) throw t2::Undefined("locate(P, q): P doubles back at a vertex, it is not simple");
    s = -t;
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const t2::Point& c = p(i);
    const t2::Point& d = p(i + 1);
    const t2::Sign Lc = -oq(p0, c), Ld = -oq(p0, d);
    if (Lc == t2::ZERO || Ld == t2::ZERO || Lc == Ld) continue;
    const t2::Sign ka = t2::orient(c, d, p0), kb = oq(c, d);
    if (ka * kb == t2::NEGATIVE && Lc == -ka) s = -s;
  }
  return s;
}

}  // namespace ex05
