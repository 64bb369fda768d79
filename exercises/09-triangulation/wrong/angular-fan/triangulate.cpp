// Wrong on purpose: a fan from the lowest point to the others sorted by angle around it. It
// triangulates the star-shaped polygon through the points, which is the hull only when the
// points are in convex position: the pockets between the polygon and the hull stay empty.
#include "triangulate.hpp"

#include <algorithm>
#include <numeric>

#include <t2/kernel/orient.hpp>

namespace ex09 {

std::vector<long> triangulate(const std::vector<t2::Point>& P) {
  long low = 0;
  for (long k = 1; k < long(P.size()); ++k)
    if (P[k].y() / P[k].w() < P[low].y() / P[low].w() ||
        (P[k].y() / P[k].w() == P[low].y() / P[low].w() && P[k].x() / P[k].w() < P[low].x() / P[low].w()))
      low = k;
  std::vector<long> others;
  for (long k = 0; k < long(P.size()); ++k)
    if (k != low) others.push_back(k);
  std::sort(others.begin(), others.end(), [&](long a, long b) { return t2::orient(P[low], P[a], P[b]) > 0; });
  std::vector<long> T;
  for (std::size_t k = 0; k + 1 < others.size(); ++k)
    if (t2::orient(P[low], P[others[k]], P[others[k + 1]]) > 0) T.insert(T.end(), {low, others[k], others[k + 1]});
  return T;
}

}  // namespace ex09
