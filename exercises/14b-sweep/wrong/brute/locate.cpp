// Wrong on purpose: correct answers, but every query tests every face in order (no sweep): with
// 10⁵ faces and 10⁵ queries that is ~10¹⁰ orientations, far over the time limit. The first face
// whose closed triangle holds the query is the least face that has its edge or vertex.
#include <t2/kernel/orient.hpp>

#include "locate.hpp"

namespace ex14b {

std::vector<Location> locate_all(const std::vector<t2::Point>& P, const std::vector<Triangle>& T,
                                 const std::vector<t2::Point>& Q) {
  std::vector<Location> r;
  for (const t2::Point& q : Q) {
    Location l;
    for (int f = 0; f < int(T.size()) && l.face < 0; ++f) {
      int s[3], zeros = 0, z = 0;
      for (int k = 0; k < 3; ++k) s[k] = int(t2::orient(P[T[f][k]], P[T[f][(k + 1) % 3]], q));
      if (s[0] < 0 || s[1] < 0 || s[2] < 0) continue;
      for (int k = 0; k < 3; ++k)
        if (s[k] == 0) ++zeros, z += k;
      if (zeros == 0) l = {Location::Kind::face, f, 0};
      if (zeros == 1) l = {Location::Kind::edge, f, z};
      if (zeros == 2) l = {Location::Kind::vertex, f, (5 - z) % 3};  // the vertex off the nonzero edge
    }
    r.push_back(l);
  }
  return r;
}

}  // namespace ex14b
