// Exercise 07b, wrong solution: the right ranks of T² and exact distances, but the farthest pair
// of one side by brute force, every pair: O(n²). Correct on every small input; on the large
// hidden input (about 20 000 points, 10 000 of them on their hull) it runs out of time, where the
// hull and the calipers take O(n log n).
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
