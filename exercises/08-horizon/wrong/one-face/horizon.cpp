// Wrong on purpose: the planar habit of inserting into one triangle. It finds the first triangle
// p sees, replaces it by the three triangles joining its edges to p, and stops: right when p sees
// one triangle only, a surface with folds when it sees several.
#include "horizon.hpp"

namespace ex08 {

std::vector<long> insert_point(const std::vector<t2::Point3>& P, const std::vector<long>& H, long p) {
  std::vector<long> out;
  bool done = false;
  for (std::size_t k = 0; k + 2 < H.size(); k += 3) {
    const long a = H[k], b = H[k + 1], c = H[k + 2];
    if (!done && t2::orient3d(P[a], P[b], P[c], P[p]) == t2::POSITIVE) {
      out.insert(out.end(), {a, b, p, b, c, p, c, a, p});
      done = true;
    } else {
      out.insert(out.end(), {a, b, c});
    }
  }
  return out;
}

}  // namespace ex08
