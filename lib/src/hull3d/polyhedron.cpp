// Face lists: edges, Euler's characteristic, and the surface and convexity certificates.
#include "t2/hull3d/polyhedron.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <string>

namespace t2 {

std::vector<Edge3> edges(const Polyhedron& P) {
  std::vector<Edge3> e;
  for (const auto& f : P.faces)
    for (std::size_t k = 0; k < f.size(); ++k) {
      const std::uint32_t a = f[k], b = f[(k + 1) % f.size()];
      e.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

long euler_characteristic(const Polyhedron& P) {
  return static_cast<long>(P.vertices.size()) - static_cast<long>(edges(P).size()) +
         static_cast<long>(P.faces.size());
}

std::string validate_surface(const Polyhedron& P) {
  const std::size_t V = P.vertices.size();
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> directed;
  std::vector<std::uint32_t> parent(V);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<bool> used(V, false);
  for (std::size_t f = 0; f < P.faces.size(); ++f) {
    const auto& F = P.faces[f];
    std::vector<std::uint32_t> s(F);
    std::sort(s.begin(), s.end());
    if (F.size() < 3 || std::adjacent_find(s.begin(), s.end()) != s.end())
      return "face " + std::to_string(f) + " has fewer than three distinct vertices";
    for (std::size_t k = 0; k < F.size(); ++k) {
      const std::uint32_t a = F[k], b = F[(k + 1) % F.size()];
      if (a >= V || b >= V) return "face " + std::to_string(f) + " names a vertex that does not exist";
      used[a] = true;
      parent[find(a)] = find(b);
      if (!directed.emplace(std::pair{a, b}, f).second)
        return "the directed edge " + std::to_string(a) + " -> " + std::to_string(b) + " occurs twice";
    }
  }
  for (const auto& [e, f] : directed)
    if (!directed.count({e.second, e.first}))
      return "the edge " + std::to_string(e.first) + " -> " + std::to_string(e.second) + " of face " +
             std::to_string(f) + " has no reverse";
  for (std::uint32_t v = 0; v < V; ++v) {
    if (!used[v]) return "vertex " + std::to_string(v) + " lies on no face";
    if (find(v) != find(0)) return "the 1-skeleton is not connected";
  }
  return "";
}

std::string validate_convex(const Polyhedron& P) {
  const auto& X = P.vertices;
  for (std::size_t f = 0; f < P.faces.size(); ++f) {
    const auto& F = P.faces[f];
    const std::string name = "face " + std::to_string(f);
    if (F.size() < 3) return name + " has fewer than three vertices";
    std::vector<bool> on(X.size(), false);
    for (std::uint32_t v : F) on[v] = true;
    const Point3 &a = X[F[0]], &b = X[F[1]], &c = X[F[2]];
    std::size_t witness = X.size();  // a vertex strictly off the face's plane
    for (std::size_t v = 0; v < X.size(); ++v) {
      const Sign s = orient3d(a, b, c, X[v]);
      if (on[v] && s != ZERO) return name + " is not planar";
      if (!on[v] && s != NEGATIVE) return "vertex " + std::to_string(v) + " is not strictly inside " + name;
      if (!on[v]) witness = v;
    }
    if (witness == X.size()) return "all vertices lie on " + name;
    for (std::size_t k = 0; k < F.size(); ++k)
      if (orient3d(X[F[k]], X[F[(k + 1) % F.size()]], X[F[(k + 2) % F.size()]], X[witness]) != NEGATIVE)
        return name + " does not turn strictly counter-clockwise at its vertex " + std::to_string(F[(k + 1) % F.size()]);
  }
  return "";
}

bool contains_all(const Polyhedron& P, std::span<const Point3> points) {
  for (const auto& F : P.faces) {
    if (F.size() < 3) return false;
    const Point3 &a = P.vertices[F[0]], &b = P.vertices[F[1]], &c = P.vertices[F[2]];
    for (const Point3& q : points)
      if (orient3d(a, b, c, q) == POSITIVE) return false;
  }
  return true;
}

}  // namespace t2
