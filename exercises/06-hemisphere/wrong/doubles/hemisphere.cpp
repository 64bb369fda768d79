// Exercise 06, wrong solution: the right algorithm with orientations evaluated in doubles.
// Points a few units in the last place off a line get the wrong sign, and the certificate
// built from them is wrong.
#include "hemisphere.hpp"

#include <array>
#include <optional>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/orient.hpp>

namespace ex06 {

namespace {

using V = std::array<t2::Integer, 3>;

V vec(const t2::Point& p) {
  const t2::ExactPoint e = t2::to_exact(p);
  return {e.w(), e.x(), e.y()};
}
V cross(const V& p, const V& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
t2::Integer dot(const V& p, const V& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
V plus(const V& p, const V& q) { return {p[0] + q[0], p[1] + q[1], p[2] + q[2]}; }

// y on the closed segment pq of T² (y, p, q on one line, p ≠ ±q): y = αp + βq with α, β ≥ 0.
bool on_segment(const V& p, const V& q, const V& y) {
  const V L = cross(p, q);
  return dot(cross(y, q), L) >= 0 && dot(cross(p, y), L) >= 0;
}

// The orientation in doubles: the determinant, rounded.
t2::Sign det(const t2::Point& p, const t2::Point& q, const t2::Point& r) {
  const double d = p.w() * (q.x() * r.y() - q.y() * r.x()) - p.x() * (q.w() * r.y() - q.y() * r.w()) +
                   p.y() * (q.w() * r.x() - q.x() * r.w());
  return d > 0 ? t2::POSITIVE : (d < 0 ? t2::NEGATIVE : t2::ZERO);
}

struct Result {
  std::vector<std::size_t> hull;  // strict vertices, counter-clockwise
  std::vector<long> witness;      // non-empty when there is no hull
};

Result build(const std::vector<t2::Point>& P) {
  Result r;
  std::vector<std::size_t>& H = r.hull;
  auto orient = [&](std::size_t a, std::size_t b, std::size_t c) { return det(P[a], P[b], P[c]); };
  for (std::size_t q = 0; q < P.size(); ++q) {
    const t2::Point nq = t2::antipode(P[q]);
    if (H.empty()) {
      H.push_back(q);
    } else if (H.size() == 1) {
      if (P[q] == P[H[0]]) continue;
      if (nq == P[H[0]]) return {{}, {long(H[0]), long(q)}};
      H.push_back(q);
    } else if (H.size() == 2) {
      const std::size_t a = H[0], b = H[1];
      if (const t2::Sign s = orient(a, b, q); s != t2::ZERO) {
        H = s > 0 ? std::vector<std::size_t>{a, b, q} : std::vector<std::size_t>{b, a, q};
        continue;
      }
      const V A = vec(P[a]), B = vec(P[b]), Q = vec(P[q]);
      if (on_segment(A, B, Q)) continue;
      if (on_segment(A, B, V{-Q[0], -Q[1], -Q[2]})) return {{}, {long(a), long(b), long(q)}};
      if (on_segment(A, Q, B)) H[1] = q;
      else H[0] = q;
    } else {
      const std::size_t m = H.size();
      std::vector<t2::Sign> s(m);
      bool pos = false, neg = false;
      for (std::size_t i = 0; i < m; ++i) {
        s[i] = orient(H[i], H[(i + 1) % m], q);
        pos = pos || s[i] > 0;
        neg = neg || s[i] < 0;
      }
      if (!neg) continue;
      if (!pos) {  // ¬q is in H: find its fan triangle
        for (std::size_t i = 1; i + 1 < m; ++i) {
          const t2::Point &h0 = P[H[0]], &hi = P[H[i]], &hj = P[H[i + 1]];
          if (det(h0, hi, nq) >= 0 && det(hi, hj, nq) >= 0 && det(hj, h0, nq) >= 0)
            return {{}, {long(H[0]), long(H[i]), long(H[i + 1]), long(q)}};
        }
        throw std::logic_error("witness: ¬q is in no fan triangle (cannot happen)");
      }
      std::size_t i = 0;  // the first edge of the chain with s ≤ 0
      while (!(s[(i + m - 1) % m] > 0 && s[i] <= 0)) ++i;
      std::size_t j = i;  // the first edge after it
      while (s[j % m] <= 0) ++j;
      std::vector<std::size_t> kept;  // h_j, ..., h_i (indices mod m), then q
      for (std::size_t k = j; k <= i + m; ++k) kept.push_back(H[k % m]);
      kept.push_back(q);
      H = std::move(kept);
    }
  }
  return r;
}

}  // namespace

t2::ExactPoint hemisphere(const std::vector<t2::Point>& P) {
  const Result r = build(P);
  if (!r.witness.empty()) throw t2::Undefined("hemisphere: the points lie in no open hemisphere");
  const std::vector<std::size_t>& H = r.hull;
  V L{0, 0, 0};
  if (H.size() == 1) {
    L = vec(P[H[0]]);
  } else if (H.size() == 2) {
    const V a = vec(P[H[0]]), b = vec(P[H[1]]), n = cross(a, b);
    L = plus(cross(n, a), cross(b, n));
  } else {
    for (std::size_t i = 0; i < H.size(); ++i) L = plus(L, cross(vec(P[H[i]]), vec(P[H[(i + 1) % H.size()]])));
  }
  return t2::ExactPoint(L[0], L[1], L[2]);
}

std::vector<long> witness(const std::vector<t2::Point>& P) { return build(P).witness; }

}  // namespace ex06
