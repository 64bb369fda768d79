// Gift wrapping in R³ (Chand and Kapur, seed 004 §7): from one facet, wrap a plane around each
// free edge to the next facet. O(n) per hull edge, exact (orient3d, and orient2 on projections).
#include <algorithm>
#include <deque>
#include <stdexcept>
#include <unordered_map>

#include "t2/hull3d/convex_hull_3d.hpp"
#include "t2/hull3d/degenerate.hpp"

namespace t2 {

namespace {

using detail::orient2;

// The strict hull, counter-clockwise seen from the outside of the plane of (a, b, c), of the
// points S of that plane (distinct): Andrew's monotone chain on a projection to a coordinate
// plane that the plane's normal is not parallel to, reversed if the projection flips it.
std::vector<std::uint32_t> planar_hull(std::span<const Point3> P, std::vector<std::uint32_t> S, const Point3& a,
                                       const Point3& b, const Point3& c) {
  struct UV {
    double u, v;
  };
  auto uv = [&](int axis, const Point3& p) {
    return axis == 2 ? UV{p.x, p.y} : axis == 0 ? UV{p.y, p.z} : UV{p.z, p.x};
  };
  int axis = 2;  // the coordinate the projection drops
  Sign s = orient2(a.x, a.y, b.x, b.y, c.x, c.y);
  if (s == ZERO) axis = 0, s = orient2(a.y, a.z, b.y, b.z, c.y, c.z);
  if (s == ZERO) axis = 1, s = orient2(a.z, a.x, b.z, b.x, c.z, c.x);
  std::sort(S.begin(), S.end(), [&](std::uint32_t i, std::uint32_t j) {
    const UV p = uv(axis, P[i]), q = uv(axis, P[j]);
    return p.u != q.u ? p.u < q.u : p.v < q.v;
  });
  auto turn = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    const UV p = uv(axis, P[i]), q = uv(axis, P[j]), r = uv(axis, P[k]);
    return orient2(p.u, p.v, q.u, q.v, r.u, r.v);
  };
  std::vector<std::uint32_t> h;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = h.size();
    for (std::uint32_t q : S) {
      while (h.size() >= base + 2 && turn(h[h.size() - 2], h.back(), q) != POSITIVE) h.pop_back();
      h.push_back(q);
    }
    h.pop_back();  // the last point starts the other chain
    std::reverse(S.begin(), S.end());
  }
  if (s == NEGATIVE) std::reverse(h.begin(), h.end());
  return h;
}

}  // namespace

Facets gift_wrap_3d(std::span<const Point3> P) {
  require_finite(P);
  const std::vector<std::uint32_t> ids = distinct_points(P);  // lexicographic order
  first_simplex(P, ids);                                       // throws unless the points span R³
  // The facet of all points on the plane (a, b, c), which has no point on its positive side.
  auto facet = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::vector<std::uint32_t> S;
    for (std::uint32_t q : ids)
      if (orient3d(P[a], P[b], P[c], P[q]) == ZERO) S.push_back(q);
    return planar_hull(P, std::move(S), P[a], P[b], P[c]);
  };
  // The first edge: p0 is lexicographically smallest; the vertical plane through p0 and p1
  // leaves every point on its left in the projection to z = 0.
  const std::uint32_t p0 = ids[0];
  std::uint32_t p1 = p0;
  for (std::uint32_t q : ids)
    if ((P[q].x != P[p0].x || P[q].y != P[p0].y) &&
        (p1 == p0 || orient2(P[p0].x, P[p0].y, P[p1].x, P[p1].y, P[q].x, P[q].y) == NEGATIVE))
      p1 = q;
  // Wrap: rotate the plane around p0p1 until no point lies beyond it.
  std::uint32_t p2 = p0;
  for (std::uint32_t q : ids)
    if (!collinear(P[p0], P[p1], P[q]) && (p2 == p0 || orient3d(P[p0], P[p1], P[p2], P[q]) == POSITIVE)) p2 = q;
  Facets facets;
  std::unordered_map<std::uint64_t, std::uint32_t> owner;  // directed edge a -> b: its facet
  std::deque<std::pair<std::uint32_t, std::size_t>> free_edges;
  auto add = [&](std::vector<std::uint32_t> f) {
    const auto id = static_cast<std::uint32_t>(facets.size());
    for (std::size_t k = 0; k < f.size(); ++k) {
      const std::uint64_t e = (std::uint64_t{f[k]} << 32) | f[(k + 1) % f.size()];
      if (!owner.emplace(e, id).second) throw std::logic_error("gift wrapping: an edge in two facets");
      free_edges.emplace_back(id, k);
    }
    facets.push_back(std::move(f));
  };
  //> gift-wrap
  add(facet(p0, p1, p2));
  while (!free_edges.empty()) {
    const auto [f, k] = free_edges.front();
    free_edges.pop_front();
    const std::uint32_t a = facets[f][k], b = facets[f][(k + 1) % facets[f].size()];
    if (owner.count((std::uint64_t{b} << 32) | a)) continue;  // the facet across is known
    const Point3 &f0 = P[facets[f][0]], &f1 = P[facets[f][1]], &f2 = P[facets[f][2]];
    std::uint32_t p = a;  // a point strictly inside the plane of f, then the wrap
    for (std::uint32_t q : ids)
      if (p == a ? orient3d(f0, f1, f2, P[q]) == NEGATIVE
                 : orient3d(P[b], P[a], P[p], P[q]) == POSITIVE)
        p = q;
    add(facet(b, a, p));
  }
  //< gift-wrap
  canonicalize(facets);
  return facets;
}

}  // namespace t2
