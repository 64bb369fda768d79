// Wrong on purpose: chapter 05's corrected Algorithm 2, right in T², but every orientation and
// every other sign is evaluated in doubles. A query a few units in the last place off an edge
// gets a rounded sign: on the edge when it is not, or on the wrong side of it.
#include "locate.hpp"

#include <stdexcept>

#include <t2/kernel/error.hpp>

namespace ex05 {

namespace {

int sgn(double v) { return (v > 0) - (v < 0); }

t2::Sign naive_orient(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  return t2::Sign(sgn(p.w() * (q.x() * r.y() - q.y() * r.x()) - p.x() * (q.w() * r.y() - q.y() * r.w()) +
                      p.y() * (q.w() * r.x() - q.x() * r.w())));
}

template <class F, class... A>
t2::Sign naive_sign(F f, const A&... a) {
  return t2::Sign(sgn(f(a...)));
}

// (u × v)·(s × t) = (u·s)(v·t) − (u·t)(v·s), a polynomial of degree 4 (Binet–Cauchy).
const auto cross_dot = [](const auto& u0, const auto& u1, const auto& u2, const auto& v0, const auto& v1,
                          const auto& v2, const auto& s0, const auto& s1, const auto& s2, const auto& t0,
                          const auto& t1, const auto& t2_) {
  return (u0 * s0 + u1 * s1 + u2 * s2) * (v0 * t0 + v1 * t1 + v2 * t2_) -
         (u0 * t0 + u1 * t1 + u2 * t2_) * (v0 * s0 + v1 * s1 + v2 * s2);
};

t2::Sign cross_dot_sign(const t2::Point& u, const t2::Point& v, const t2::Point& s, const t2::Point& t) {
  return naive_sign(cross_dot, u.w(), u.x(), u.y(), v.w(), v.x(), v.y(), s.w(), s.x(), s.y(), t.w(),
                          t.x(), t.y());
}

// The closed T² segment ab (a ≠ ±b) holds q: q on the line, and α, β ≥ 0 in q = αa + βb.
bool on_edge(const t2::Point& a, const t2::Point& b, const t2::Point& q) {
  if (naive_orient(a, b, q) != t2::ZERO) return false;
  return cross_dot_sign(q, b, a, b) >= 0 && cross_dot_sign(a, q, a, b) >= 0;
}

// ¬q = p exactly: all 2×2 minors of p, q vanish and p·q < 0.
bool antipodal(const t2::Point& p, const t2::Point& q) {
  const auto minor = [](const auto& a, const auto& b, const auto& c, const auto& d) { return a * d - b * c; };
  const auto dot = [](const auto& a, const auto& b, const auto& c, const auto& d, const auto& e, const auto& f) {
    return a * d + b * e + c * f;
  };
  return naive_sign(minor, p.w(), p.x(), q.w(), q.x()) == t2::ZERO &&
         naive_sign(minor, p.w(), p.y(), q.w(), q.y()) == t2::ZERO &&
         naive_sign(minor, p.x(), p.y(), q.x(), q.y()) == t2::ZERO &&
         naive_sign(dot, p.w(), p.x(), p.y(), q.w(), q.x(), q.y()) < 0;
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
    if (!nn && naive_orient(p0, q, e) != t2::ZERO) nn = &e;
  if (!nn) throw std::logic_error("locate: q = ±p0 after the boundary test");
  const auto oq = [&](const t2::Point& a, const t2::Point& b) {  // Δ(q_ε, a, b)
    const t2::Sign s = naive_orient(q, a, b);
    return s != t2::ZERO ? s : naive_orient(*nn, a, b);
  };
  t2::Sign s = oq(p0, p(1));
  const t2::Sign t = naive_orient(p(n - 1), p0, p(1));
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
    const t2::Sign ka = naive_orient(c, d, p0), kb = oq(c, d);
    if (ka * kb == t2::NEGATIVE && Lc == -ka) s = -s;
  }
  return s;
}

}  // namespace ex05
