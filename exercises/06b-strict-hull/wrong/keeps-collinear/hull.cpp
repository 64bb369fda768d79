// Exercise 06b, wrong solution: the chain of edges that q replaces is taken with Δ < 0 only, so
// a vertex that q makes collinear (q beyond it on an edge's line) stays in the hull: the answer
// keeps points that are not strict vertices.
#include "hull.hpp"

#include <array>
#include <string>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/orient.hpp>

namespace ex06b {

namespace {

// y on the closed segment pq of T² (y on the line of p and q, p ≠ ±q): y = αp + βq, α, β ≥ 0,
// i.e. y is not beyond q as seen from p, nor beyond p as seen from q.
bool on_segment(const t2::ExactPoint& p, const t2::ExactPoint& q, const t2::ExactPoint& y) {
  auto cross = [](const t2::ExactPoint& a, const t2::ExactPoint& b) {
    return std::array<t2::Integer, 3>{a.x() * b.y() - a.y() * b.x(), a.y() * b.w() - a.w() * b.y(),
                                      a.w() * b.x() - a.x() * b.w()};
  };
  auto dot = [](const std::array<t2::Integer, 3>& a, const std::array<t2::Integer, 3>& b) -> t2::Integer {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  const auto L = cross(p, q);
  return dot(cross(y, q), L) >= 0 && dot(cross(p, y), L) >= 0;
}

[[noreturn]] void no_hull(std::size_t i, std::size_t j) {
  throw t2::Undefined("hull: p" + std::to_string(i) + " and p" + std::to_string(j) +
                      " with the points before them lie in no open hemisphere");
}

}  // namespace

std::vector<long> hull(const std::vector<t2::Point>& P) {
  std::vector<std::size_t> H;
  auto orient = [&](std::size_t a, std::size_t b, std::size_t c) { return t2::orient(P[a], P[b], P[c]); };
  for (std::size_t q = 0; q < P.size(); ++q) {
    if (H.empty()) {
      H.push_back(q);
    } else if (H.size() == 1) {
      if (P[q] == P[H[0]]) continue;
      if (t2::antipode(P[q]) == P[H[0]]) no_hull(H[0], q);
      H.push_back(q);
    } else if (H.size() == 2) {
      const std::size_t a = H[0], b = H[1];
      if (const t2::Sign s = orient(a, b, q); s != t2::ZERO) {
        H = s > 0 ? std::vector<std::size_t>{a, b, q} : std::vector<std::size_t>{b, a, q};
        continue;
      }
      const t2::ExactPoint A = t2::to_exact(P[a]), B = t2::to_exact(P[b]), Q = t2::to_exact(P[q]);
      if (on_segment(A, B, Q)) continue;
      if (on_segment(A, B, t2::antipode(Q))) no_hull(a, q);
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
      if (!neg) continue;             // q in H (perhaps on an edge, or a repeat of a vertex)
      if (!pos) no_hull(H[0], q);     // ¬q in H: q + ¬q = 0
      std::size_t i = 0;              // the first edge of the chain with s < 0
      while (!(s[(i + m - 1) % m] >= 0 && s[i] < 0)) ++i;
      std::size_t j = i;              // the first edge after it
      while (s[j % m] < 0) ++j;
      std::vector<std::size_t> kept;  // h_j, ..., h_i (indices mod m), then q
      for (std::size_t k = j; k <= i + m; ++k) kept.push_back(H[k % m]);
      kept.push_back(q);
      H = std::move(kept);
    }
  }
  return std::vector<long>(H.begin(), H.end());
}

}  // namespace ex06b
