// Wrong on purpose: the wrap of the chapter's listing without FACET. It returns the triangle
// b, a, p: right while no four points are coplanar (the seed's assumption), wrong on a cube,
// whose facets are squares.
#include "facet.hpp"

namespace ex08b {

namespace {

t2::Sign side(const t2::Point3& p, const t2::Point3& q, const t2::Point3& r, const t2::Point3& s) {
  return t2::orient3d(p, q, r, s);
}

}  // namespace

std::vector<long> next_facet(const std::vector<t2::Point3>& P, const std::vector<long>& f, long k) {
  const long n = long(P.size()), a = f[k], b = f[(k + 1) % f.size()];
  long p = -1;  // a point strictly inside the plane of f, then the wrap about a b
  for (long q = 0; q < n && p < 0; ++q)
    if (side(P[f[0]], P[f[1]], P[f[2]], P[q]) == t2::NEGATIVE) p = q;
  for (long q = 0; q < n; ++q)
    if (side(P[b], P[a], P[p], P[q]) == t2::POSITIVE) p = q;
  return {b, a, p};
}

}  // namespace ex08b
