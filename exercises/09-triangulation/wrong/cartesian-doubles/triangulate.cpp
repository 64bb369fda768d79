// Wrong on purpose: the sweep with the textbook orientation, the cross product of the x and y
// coordinates in doubles. It ignores w (a point [2, 4, 0] is taken for (4, 0), not (2, 0)) and
// rounds (a tiny determinant can get the wrong sign).
#include "triangulate.hpp"

#include <algorithm>
#include <numeric>

#include <t2/kernel/lexicographic.hpp>

namespace ex09 {

static int turn(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  const double d = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  return d > 0 ? 1 : d < 0 ? -1 : 0;
}

std::vector<long> triangulate(const std::vector<t2::Point>& P) {
  std::vector<long> order(P.size()), lower, upper, T;
  std::iota(order.begin(), order.end(), 0L);
  std::sort(order.begin(), order.end(), [&](long a, long b) { return t2::compare_xy(P[a], P[b]) < 0; });
  for (long p : order) {
    while (lower.size() >= 2 && turn(P[lower[lower.size() - 2]], P[lower.back()], P[p]) < 0) {
      T.insert(T.end(), {lower[lower.size() - 2], p, lower.back()});
      lower.pop_back();
    }
    while (upper.size() >= 2 && turn(P[upper[upper.size() - 2]], P[upper.back()], P[p]) > 0) {
      T.insert(T.end(), {upper[upper.size() - 2], upper.back(), p});
      upper.pop_back();
    }
    lower.push_back(p);
    upper.push_back(p);
  }
  return T;
}

}  // namespace ex09
