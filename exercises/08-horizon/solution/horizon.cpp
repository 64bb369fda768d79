// Exercise 08, reference solution: the seen triangles by the exact orient3d, the horizon as the
// directed edges of seen triangles whose reverse belongs to an unseen one, and the cone.
#include "horizon.hpp"

#include <map>
#include <utility>

namespace ex08 {

std::vector<long> insert_point(const std::vector<t2::Point3>& P, const std::vector<long>& H, long p) {
  const std::size_t n = H.size() / 3;
  std::vector<bool> seen(n);
  std::map<std::pair<long, long>, std::size_t> owner;  // directed edge a -> b: its triangle
  for (std::size_t t = 0; t < n; ++t) {
    const long a = H[3 * t], b = H[3 * t + 1], c = H[3 * t + 2];
    seen[t] = t2::orient3d(P[a], P[b], P[c], P[p]) == t2::POSITIVE;
    owner[{a, b}] = owner[{b, c}] = owner[{c, a}] = t;
  }
  std::vector<long> out;
  for (std::size_t t = 0; t < n; ++t)
    if (!seen[t]) out.insert(out.end(), {H[3 * t], H[3 * t + 1], H[3 * t + 2]});
  for (std::size_t t = 0; t < n; ++t) {
    if (!seen[t]) continue;
    for (int i = 0; i < 3; ++i) {
      const long a = H[3 * t + i], b = H[3 * t + (i + 1) % 3];
      if (!seen[owner.at({b, a})]) out.insert(out.end(), {a, b, p});  // a horizon edge
    }
  }
  return out;
}

}  // namespace ex08
