// Exercise 07b, wrong solution: "the diameter is realized by antipodal pairs of the hull", so
// it is taken on each side separately (where a hull and calipers exist) and the larger of the two
// kept. A front point and a back point are never compared, though their distance is beyond
// infinity, larger than every same-side distance.
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
  std::vector<long> proper = front;  // both sides: the calipers per side, the larger answer
  proper.insert(proper.end(), back.begin(), back.end());
  if (!omega.empty()) return proper.empty() ? std::vector<long>{omega[0], omega.back()} : std::vector<long>{proper[0], omega[0]};
  std::vector<long> best = {proper[0], proper[0]};  // rank 3: the farthest pair of one side
  Dist d{0, 1};
  for (std::size_t i = 0; i < proper.size(); ++i)
    for (std::size_t j = i + 1; j < proper.size(); ++j)
      if ((P[proper[i]].w() > 0) == (P[proper[j]].w() > 0))
        if (const Dist e = dist(E[proper[i]], E[proper[j]]); less(d, e)) d = e, best = {proper[i], proper[j]};
  return best;
}

}  // namespace ex07b
