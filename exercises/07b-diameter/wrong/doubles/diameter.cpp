// Exercise 07b, wrong solution: the right ranks of T², but squared distances computed in doubles
// from the drawn positions. Two pairs whose distances differ by a few units in the last place
// round to the same square, or to the wrong order.
#include "diameter.hpp"

#include <algorithm>
#include <array>
#include <string>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>

namespace ex07b {

namespace {

using V = std::array<t2::Integer, 3>;  // w, x, y with w > 0

struct Dist {
  t2::Integer n, d;  // the squared drawn distance n / d, d > 0
};

Dist dist(const V& a, const V& b) {
  const t2::Integer dx = a[1] * b[0] - b[1] * a[0], dy = a[2] * b[0] - b[2] * a[0], ww = a[0] * b[0];
  return {dx * dx + dy * dy, ww * ww};
}

bool less(const Dist& u, const Dist& v) { return u.n * v.d < v.n * u.d; }

// The squared distance in doubles, from the drawing: what is compared below.
double rounded(const V& a, const V& b) {
  const double dx = a[1].get_d() / a[0].get_d() - b[1].get_d() / b[0].get_d();
  const double dy = a[2].get_d() / a[0].get_d() - b[2].get_d() / b[0].get_d();
  return dx * dx + dy * dy;
}

// The drawn turn a, b, c (w > 0): the sign of det(a, b, c).
int turn(const V& a, const V& b, const V& c) {
  return sgn(a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]));
}

// The strict hull of the points F[at[..]], counter-clockwise as drawn (Andrew's monotone chain
// on x/w, y/w, compared cross-multiplied since w > 0).
std::vector<long> hull(const std::vector<V>& F, std::vector<long> at) {
  const auto before = [&](long a, long b) {
    const t2::Integer ax = F[a][1] * F[b][0], bx = F[b][1] * F[a][0];
    if (ax != bx) return ax < bx;
    return F[a][2] * F[b][0] < F[b][2] * F[a][0];
  };
  std::sort(at.begin(), at.end(), before);
  at.erase(std::unique(at.begin(), at.end(), [&](long a, long b) { return !before(a, b) && !before(b, a); }), at.end());
  if (at.size() < 3) return at;
  std::vector<long> H(2 * at.size());
  std::size_t k = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t floor = k;
    for (long p : at) {
      while (k >= floor + 2 && turn(F[H[k - 2]], F[H[k - 1]], F[p]) <= 0) --k;
      H[k++] = p;
    }
    --k;  // the last point starts the other chain
    std::reverse(at.begin(), at.end());
  }
  H.resize(k);
  return H;
}

// The farthest pair of the front points F[proper[..]]: an antipodal pair of their hull. For the
// edge e_i = H[i] → H[i+1] the calipers find the farthest vertex j from its line (it only moves
// forward); H[i] is antipodal to the vertices from the previous edge's farthest to this one's,
// and both ends of e_i to a vertex as far as j (an edge parallel to e_i).
std::vector<long> farthest(const std::vector<V>& F, const std::vector<long>& proper) {
  const std::vector<long> H = hull(F, proper);
  const std::size_t h = H.size();
  if (h == 1) return {H[0], H[0]};
  std::vector<long> best = {H[0], H[1]};
  double d = rounded(F[H[0]], F[H[1]]);
  const auto offer = [&](long a, long b) {
    if (const double e = rounded(F[a], F[b]); d < e) d = e, best = {a, b};
  };
  if (h == 2) return best;
  const auto at = [&](std::size_t i) -> const V& { return F[H[i % h]]; };
  const auto height = [&](std::size_t i, std::size_t j) {  // det(a, b, v_j) / w_j: the distance times |ab| / (a_w b_w)
    const V &a = at(i), &b = at(i + 1), &v = at(j);
    const t2::Integer det = a[0] * (b[1] * v[2] - b[2] * v[1]) - a[1] * (b[0] * v[2] - b[2] * v[0]) +
                            a[2] * (b[0] * v[1] - b[1] * v[0]);
    return Dist{det, v[0]};
  };
  std::size_t j = 1;
  for (std::size_t i = 0; i < h; ++i) {
    const std::size_t from = std::max(j, i + 1);
    j = from;
    while (less(height(i, j), height(i, j + 1))) ++j;
    for (std::size_t k = from; k <= j; ++k) offer(H[i], H[k % h]);
    offer(H[(i + 1) % h], H[j % h]);
    if (!less(height(i, j + 1), height(i, j))) offer(H[i], H[(j + 1) % h]), offer(H[(i + 1) % h], H[(j + 1) % h]);
  }
  return best;
}

}  // namespace

std::vector<long> diameter(const std::vector<t2::Point>& P) {
  std::vector<long> front, back, omega;
  std::vector<V> E;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const t2::ExactPoint e = t2::to_exact(P[i]);
    E.push_back({e.w(), e.x(), e.y()});
    (P[i].w() > 0 ? front : P[i].w() < 0 ? back : omega).push_back(long(i));
  }
  for (long k : omega)
    if (!(P[k] == P[omega[0]]))
      throw t2::Undefined("diameter: p" + std::to_string(omega[0]) + " and p" + std::to_string(k) +
                          " are different points of Omega: their distance is an angle");
  if (!front.empty() && !back.empty()) {  // rank 1: the nearest front–back pair as drawn
    std::vector<long> best = {front[0], back[0]};
    double d = rounded(E[front[0]], E[back[0]]);
    for (long f : front)
      for (long b : back)
        if (const double e = rounded(E[f], E[b]); e < d) d = e, best = {f, b};
    return best;
  }
  const std::vector<long>& proper = front.empty() ? back : front;
  if (!omega.empty()) return proper.empty() ? std::vector<long>{omega[0], omega.back()} : std::vector<long>{proper[0], omega[0]};
  if (!back.empty())  // a back point's antipode is drawn at the same place
    for (V& e : E) e = {-e[0], -e[1], -e[2]};
  return farthest(E, proper);  // rank 3: the farthest pair of one side
}

}  // namespace ex07b
