// Facets of a triangulated convex surface: merging coplanar triangles, the canonical form.
#include "t2/hull3d/facets.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "t2/hull3d/degenerate.hpp"

namespace t2 {

namespace {

std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

// Drops the vertices of a convex polygon that lie on the segment of their two neighbours.
std::vector<std::uint32_t> drop_collinear(std::span<const Point3> P, std::vector<std::uint32_t> c) {
  for (bool changed = true; changed && c.size() > 3;) {
    changed = false;
    for (std::size_t k = 0; k < c.size() && c.size() > 3; ++k) {
      const std::size_t m = c.size();
      if (collinear(P[c[(k + m - 1) % m]], P[c[k]], P[c[(k + 1) % m]])) {
        c.erase(c.begin() + static_cast<std::ptrdiff_t>(k));
        changed = true;
      }
    }
  }
  return c;
}

}  // namespace

void canonicalize(Facets& facets) {
  for (auto& f : facets) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(facets.begin(), facets.end());
}

Facets merge_coplanar(std::span<const Point3> P, const std::vector<Triangle3>& T) {
  std::unordered_map<std::uint64_t, std::uint32_t> across;  // directed edge a -> b: its triangle
  across.reserve(3 * T.size());
  for (std::uint32_t t = 0; t < T.size(); ++t)
    for (int k = 0; k < 3; ++k) across[key(T[t][k], T[t][(k + 1) % 3])] = t;
  std::vector<std::uint32_t> group(T.size());
  std::iota(group.begin(), group.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (group[x] != x) x = group[x] = group[group[x]];
    return x;
  };
  bool merged = false;
  for (std::uint32_t t = 0; t < T.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = across.at(key(T[t][(k + 1) % 3], T[t][k]));
      if (u < t) continue;
      const std::uint32_t opposite = T[u][0] + T[u][1] + T[u][2] - T[t][k] - T[t][(k + 1) % 3];
      if (orient3d(P[T[t][0]], P[T[t][1]], P[T[t][2]], P[opposite]) == ZERO) {
        group[find(t)] = find(u);
        merged = true;
      }
    }
  Facets out;
  if (!merged) {
    for (const auto& t : T) out.push_back({t[0], t[1], t[2]});
  } else {
    // each group is a triangulated convex polygon: chain its boundary edges a -> b
    std::unordered_map<std::uint32_t, std::unordered_map<std::uint32_t, std::uint32_t>> next;  // group: a -> b
    for (std::uint32_t t = 0; t < T.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = T[t][k], b = T[t][(k + 1) % 3];
        if (find(across.at(key(b, a))) != find(t)) next[find(t)][a] = b;
      }
    for (auto& [g, succ] : next) {
      std::vector<std::uint32_t> cycle;
      const std::uint32_t start = succ.begin()->first;
      std::uint32_t v = start;
      do {
        cycle.push_back(v);
        v = succ.at(v);
      } while (v != start && cycle.size() <= succ.size());
      out.push_back(drop_collinear(P, std::move(cycle)));
    }
  }
  canonicalize(out);
  return out;
}

std::vector<Triangle3> fan_triangles(const Facets& facets) {
  std::vector<Triangle3> out;
  for (const auto& f : facets)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) out.push_back({f[0], f[k], f[k + 1]});
  std::sort(out.begin(), out.end());
  return out;
}

Polyhedron polyhedron_of(std::span<const Point3> P, const Facets& facets) {
  std::vector<std::uint32_t> used;
  for (const auto& f : facets) used.insert(used.end(), f.begin(), f.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  Polyhedron out;
  for (std::uint32_t v : used) out.vertices.push_back(P[v]);
  for (const auto& f : facets) {
    std::vector<std::uint32_t> g;
    for (std::uint32_t v : f)
      g.push_back(static_cast<std::uint32_t>(std::lower_bound(used.begin(), used.end(), v) - used.begin()));
    out.faces.push_back(std::move(g));
  }
  return out;
}

}  // namespace t2
