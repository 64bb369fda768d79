// Exercise 09, reference solution: the sweep with two chains. Sorted by (x, y), each point is
// outside the hull of the previous ones; it is joined to the lower chain while that chain turns
// clockwise at its end, and to the upper chain while it turns counter-clockwise.
#include "triangulate.hpp"

#include <algorithm>
#include <numeric>

#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>

namespace ex09 {

std::vector<long> triangulate(const std::vector<t2::Point>& P) {
  std::vector<long> order(P.size()), lower, upper, T;
  std::iota(order.begin(), order.end(), 0L);
  std::sort(order.begin(), order.end(), [&](long a, long b) { return t2::compare_xy(P[a], P[b]) < 0; });
  for (long p : order) {
    while (lower.size() >= 2 && t2::orient(P[lower[lower.size() - 2]], P[lower.back()], P[p]) < 0) {
      T.insert(T.end(), {lower[lower.size() - 2], p, lower.back()});
      lower.pop_back();
    }
    while (upper.size() >= 2 && t2::orient(P[upper[upper.size() - 2]], P[upper.back()], P[p]) > 0) {
      T.insert(T.end(), {upper[upper.size() - 2], upper.back(), p});
      upper.pop_back();
    }
    lower.push_back(p);
    upper.push_back(p);
  }
  return T;
}

}  // namespace ex09
