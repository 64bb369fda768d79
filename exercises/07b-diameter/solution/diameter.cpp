// Exercise 07b, reference solution. The order of squared distances of T¹ splits the pairs in
// three ranks, and the answer comes from the highest rank present:
//   1. a front and a back point ("beyond infinity"): the pair *nearest* as drawn, a bichromatic
//      closest pair — by brute force here (O(|F|·|B|); chapter 11's Voronoi diagram does better);
//   2. else a proper point and a point of Ω: +∞, any such pair;
//   3. else one side only: the Euclidean farthest pair — by brute force here; chapter 07's hull
//      and calipers make it O(n log n), since only antipodal pairs of the hull can be farthest.
// Two different points of Ω make the diameter undefined, whatever else there is. Distances are
// compared exactly as fractions N/D of big integers, N = |a_w b − b_w a|² over the plane
// coordinates and D = (a_w b_w)² > 0, cross-multiplied: no division, no rounding.
#include "diameter.hpp"

#include <string>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>

namespace ex07b {

namespace {

struct Dist {
  t2::Integer n, d;  // the squared drawn distance n / d, d > 0
};

Dist dist(const t2::ExactPoint& a, const t2::ExactPoint& b) {
  const t2::Integer dx = a.x() * b.w() - b.x() * a.w(), dy = a.y() * b.w() - b.y() * a.w(), ww = a.w() * b.w();
  return {dx * dx + dy * dy, ww * ww};
}

bool less(const Dist& u, const Dist& v) { return u.n * v.d < v.n * u.d; }

}  // namespace

std::vector<long> diameter(const std::vector<t2::Point>& P) {
  std::vector<long> front, back, omega;
  std::vector<t2::ExactPoint> E;
  for (std::size_t i = 0; i < P.size(); ++i) {
    E.push_back(t2::to_exact(P[i]));
    (P[i].w() > 0 ? front : P[i].w() < 0 ? back : omega).push_back(long(i));
  }
  for (long k : omega)
    if (!(P[k] == P[omega[0]]))
      throw t2::Undefined("diameter: p" + std::to_string(omega[0]) + " and p" + std::to_string(k) +
                          " are different points of Omega: their distance is an angle");
  if (!front.empty() && !back.empty()) {  // rank 1: the nearest front–back pair as drawn
    std::vector<long> best = {front[0], back[0]};
    Dist d = dist(E[front[0]], E[back[0]]);
    for (long f : front)
      for (long b : back)
        if (const Dist e = dist(E[f], E[b]); less(e, d)) d = e, best = {f, b};
    return best;
  }
  const std::vector<long>& proper = front.empty() ? back : front;
  if (!omega.empty()) return proper.empty() ? std::vector<long>{omega[0], omega.back()} : std::vector<long>{proper[0], omega[0]};
  std::vector<long> best = {proper[0], proper[0]};  // rank 3: the farthest pair of one side
  Dist d{0, 1};
  for (std::size_t i = 0; i < proper.size(); ++i)
    for (std::size_t j = i + 1; j < proper.size(); ++j)
      if (const Dist e = dist(E[proper[i]], E[proper[j]]); less(d, e)) d = e, best = {proper[i], proper[j]};
  return best;
}

}  // namespace ex07b
