// Exercise 07, wrong solution: it assumes a strip exists. Proper points on both sides, or two
// different directions of Ω, still get an answer (the first direction of Ω is taken as the
// strip's), instead of t2::Undefined.
#include "width.hpp"

#include <algorithm>
#include <array>
#include <string>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>

namespace ex07 {

namespace {

using V = std::array<t2::Integer, 3>;

V cross(const V& p, const V& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
t2::Integer dot(const V& p, const V& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }

struct Frac {
  t2::Integer n, d;  // n / d, d > 0
};
bool less(const Frac& a, const Frac& b) { return a.n * b.d < b.n * a.d; }

// The strict hull of the front points F[at[..]], counter-clockwise as drawn (Andrew's monotone
// chain on the drawn positions x/w, y/w, compared cross-multiplied since w > 0).
std::vector<long> hull(const std::vector<V>& F, std::vector<long> at) {
  const auto before = [&](long a, long b) {
    const t2::Integer ax = F[a][1] * F[b][0], bx = F[b][1] * F[a][0];
    if (ax != bx) return ax < bx;
    return F[a][2] * F[b][0] < F[b][2] * F[a][0];
  };
  std::sort(at.begin(), at.end(), before);
  at.erase(std::unique(at.begin(), at.end(), [&](long a, long b) { return !before(a, b) && !before(b, a); }), at.end());
  std::vector<long> H(2 * at.size());
  std::size_t k = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t floor = k;
    for (long p : at) {
      while (k >= floor + 2 && sgn(dot(cross(F[H[k - 2]], F[H[k - 1]]), F[p])) <= 0) --k;
      H[k++] = p;
    }
    --k;  // the last point starts the other chain
    std::reverse(at.begin(), at.end());
  }
  H.resize(k);
  return H;
}

}  // namespace

std::vector<long> width(const std::vector<t2::Point>& P) {
  std::vector<V> E;
  std::vector<long> proper, omega;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const t2::ExactPoint e = t2::to_exact(P[i]);
    E.push_back({e.w(), e.x(), e.y()});
    (P[i].w() != 0 ? proper : omega).push_back(long(i));
  }
  if (!omega.empty()) {  // the direction is given: from the least to the largest offset
    const V L0 = cross(V{1, 0, 0}, E[omega[0]]);
    auto offset = [&](long p) { return Frac{dot(L0, E[p]) * E[p][0], E[p][0] * E[p][0]}; };  // (L0·p)/p_w
    long lo = proper[0], hi = proper[0];
    for (long p : proper) {
      if (less(offset(p), offset(lo))) lo = p;
      if (less(offset(hi), offset(p))) hi = p;
    }
    return {lo, omega[0], hi};
  }
  std::vector<V> F = E;  // on the front: a back point's antipode is drawn at the same place
  if (P[proper[0]].w() < 0)
    for (V& f : F) f = {-f[0], -f[1], -f[2]};
  const std::vector<long> H = hull(F, proper);  // h ≥ 3: the points are not on one line
  const std::size_t h = H.size();
  const auto at = [&](std::size_t i) -> const V& { return F[H[i % h]]; };
  // The distance of vertex j from the line L, up to the factor 1 / |L_xy| of the edge: (L·v_j) / w_j.
  const auto height = [&](const V& L, std::size_t j) { return Frac{dot(L, at(j)), at(j)[0]}; };
  std::vector<long> best;
  Frac w{0, 0};  // the least squared width so far (none while d = 0)
  std::size_t j = 1;
  for (std::size_t i = 0; i < h; ++i) {  // edge e_i = H[i] → H[i+1]; j only moves forward
    const V L = cross(at(i), at(i + 1));
    if (j < i + 1) j = i + 1;
    while (less(height(L, j), height(L, j + 1))) ++j;
    const Frac d = height(L, j);
    const Frac f{d.n * d.n, d.d * d.d * (L[1] * L[1] + L[2] * L[2])};
    if (w.d == 0 || less(f, w)) w = f, best = {H[i], H[(i + 1) % h], H[j % h]};
  }
  return best;
}

}  // namespace ex07
