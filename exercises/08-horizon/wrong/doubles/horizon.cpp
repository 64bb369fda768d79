// Wrong on purpose: Volume6 evaluated in doubles (seed 004 as written) and its sign trusted. For
// a point a few units in the last place off the plane of a face the rounding error exceeds the
// determinant: the point sees a face it is behind, or misses one it is in front of, and the
// surface gets a dent or a fold.
#include "horizon.hpp"

#include <map>
#include <utility>

namespace ex08 {

std::vector<long> insert_point(const std::vector<t2::Point3>& P, const std::vector<long>& H, long p) {
  const std::size_t n = H.size() / 3;
  std::vector<bool> seen(n);
  std::map<std::pair<long, long>, std::size_t> owner;
  for (std::size_t t = 0; t < n; ++t) {
    const long a = H[3 * t], b = H[3 * t + 1], c = H[3 * t + 2];
    seen[t] = t2::volume6(P[a], P[b], P[c], P[p]) > 0;
    owner[{a, b}] = owner[{b, c}] = owner[{c, a}] = t;
  }
  std::vector<long> out;
  for (std::size_t t = 0; t < n; ++t)
    if (!seen[t]) out.insert(out.end(), {H[3 * t], H[3 * t + 1], H[3 * t + 2]});
  for (std::size_t t = 0; t < n; ++t) {
    if (!seen[t]) continue;
    for (int i = 0; i < 3; ++i) {
      const long a = H[3 * t + i], b = H[3 * t + (i + 1) % 3];
      if (!seen[owner.at({b, a})]) out.insert(out.end(), {a, b, p});
    }
  }
  return out;
}

}  // namespace ex08
