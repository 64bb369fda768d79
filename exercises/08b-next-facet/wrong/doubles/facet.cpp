// Wrong on purpose: seed 004's Volume6 evaluated in doubles (t2::volume6) and its sign trusted,
// for the wrap and for "in the plane". Near a plane, rounded points are judged beyond it, or
// on it, by the rounding error: the wrap stops at a wrong point, or the facet gathers points
// off its plane.
#include "facet.hpp"

#include <algorithm>
#include <array>
#include <tuple>

#include <t2/kernel/orient.hpp>
#include <t2/kernel/point.hpp>

namespace ex08b {

namespace {

t2::Sign side(const t2::Point3& p, const t2::Point3& q, const t2::Point3& r, const t2::Point3& s) {
  const double v = t2::volume6(p, q, r, s);
  return v > 0 ? t2::POSITIVE : v < 0 ? t2::NEGATIVE : t2::ZERO;
}

// The projection dropping one coordinate: 0 keeps (x, y), 1 keeps (y, z), 2 keeps (z, x).
t2::Point project(const t2::Point3& p, int drop) {
  return drop == 0 ? t2::Point::cartesian(p.x, p.y) : drop == 1 ? t2::Point::cartesian(p.y, p.z)
                                                                 : t2::Point::cartesian(p.z, p.x);
}

}  // namespace

std::vector<long> next_facet(const std::vector<t2::Point3>& P, const std::vector<long>& f, long k) {
  const long n = long(P.size()), a = f[k], b = f[(k + 1) % f.size()];
  long p = -1;  // a point strictly inside the plane of f, then the wrap about a b
  for (long q = 0; q < n && p < 0; ++q)
    if (side(P[f[0]], P[f[1]], P[f[2]], P[q]) == t2::NEGATIVE) p = q;
  for (long q = 0; q < n; ++q)
    if (side(P[b], P[a], P[p], P[q]) == t2::POSITIVE) p = q;
  // FACET(b, a, p): the points of the plane, of equal points the smallest index.
  std::vector<long> S;
  for (long q = 0; q < n; ++q)
    if (side(P[b], P[a], P[p], P[q]) == t2::ZERO) S.push_back(q);
  auto key = [&](long q) { return std::tuple(P[q].x, P[q].y, P[q].z, q); };
  std::sort(S.begin(), S.end(), [&](long u, long v) { return key(u) < key(v); });
  S.erase(std::unique(S.begin(), S.end(),
                      [&](long u, long v) { return P[u].x == P[v].x && P[u].y == P[v].y && P[u].z == P[v].z; }),
          S.end());
  // A coordinate plane on which b, a, p do not project to a line; s: whether it mirrors them.
  int drop = 0;
  t2::Sign s = t2::ZERO;
  for (; drop < 3 && s == t2::ZERO; ++drop) s = t2::orient(project(P[b], drop), project(P[a], drop), project(P[p], drop));
  --drop;
  std::vector<std::pair<t2::Point, long>> Q;
  for (long q : S) Q.push_back({project(P[q], drop), q});
  std::sort(Q.begin(), Q.end(), [](const auto& u, const auto& v) {
    return std::pair(u.first.x(), u.first.y()) < std::pair(v.first.x(), v.first.y());
  });
  auto turn = [&](long u, long v, long w) {  // > 0: counter-clockwise seen from outside
    return s * t2::orient(project(P[u], drop), project(P[v], drop), project(P[w], drop));
  };
  // Andrew, keeping turns > 0 only (strict vertices): in the mirror (s < 0) the chains are the
  // upper and then the lower one, and the cycle still turns counter-clockwise seen from outside.
  std::vector<long> H;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t floor = H.size();
    for (std::size_t i = 0; i < Q.size(); ++i) {
      const long q = Q[pass == 0 ? i : Q.size() - 1 - i].second;
      while (H.size() >= floor + 2 && turn(H[H.size() - 2], H.back(), q) <= 0) H.pop_back();
      H.push_back(q);
    }
    H.pop_back();  // the last point of a chain starts the other one
  }
  std::rotate(H.begin(), std::find(H.begin(), H.end(), b), H.end());
  return H;
}

}  // namespace ex08b
