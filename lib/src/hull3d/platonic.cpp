// The five Platonic solids with integer coordinates, and the polar dual.
#include "t2/hull3d/platonic.hpp"

#include <cmath>
#include <numeric>

#include "t2/kernel/error.hpp"
#include "t2/hull3d/convex_hull_3d.hpp"
#include "t2/hull3d/winged_edge.hpp"

namespace t2 {

const std::vector<Platonic>& all_platonic() {
  static const std::vector<Platonic> all{Platonic::tetrahedron, Platonic::cube, Platonic::octahedron,
                                         Platonic::dodecahedron, Platonic::icosahedron};
  return all;
}

std::string_view name(Platonic s) {
  switch (s) {
    case Platonic::tetrahedron: return "tetrahedron";
    case Platonic::cube: return "cube";
    case Platonic::octahedron: return "octahedron";
    case Platonic::dodecahedron: return "dodecahedron";
    case Platonic::icosahedron: return "icosahedron";
  }
  return "?";
}

Polyhedron polar_dual(const Polyhedron& P) {
  __extension__ typedef __int128 I;
  for (const Point3& p : P.vertices)
    for (double c : {p.x, p.y, p.z})
      if (c != std::trunc(c) || std::fabs(c) > 0x1p20) throw Undefined("polar dual: coordinates must be integers below 2^20");
  auto as = [](double c) { return static_cast<I>(static_cast<long long>(c)); };
  std::vector<std::array<I, 4>> pole;  // (n, d): the face's plane n·x = d, reduced
  I L = 1;
  for (const auto& f : P.faces) {
    const Point3 &a = P.vertices[f[0]], &b = P.vertices[f[1]], &c = P.vertices[f[2]];
    const I ux = as(b.x) - as(a.x), uy = as(b.y) - as(a.y), uz = as(b.z) - as(a.z);
    const I vx = as(c.x) - as(a.x), vy = as(c.y) - as(a.y), vz = as(c.z) - as(a.z);
    I n[3] = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    I d = n[0] * as(a.x) + n[1] * as(a.y) + n[2] * as(a.z);
    if (d <= 0) throw Undefined("polar dual: the origin is not strictly inside");
    auto g = static_cast<long long>(d);
    for (I x : n) g = std::gcd(g, static_cast<long long>(x < 0 ? -x : x));
    pole.push_back({n[0] / g, n[1] / g, n[2] / g, d / g});
    L = L / std::gcd(static_cast<long long>(L), static_cast<long long>(d / g)) * (d / g);
    if (L > (I{1} << 60)) throw Undefined("polar dual: the coordinates would not be exact doubles");
  }
  Polyhedron D;
  for (const auto& [x, y, z, d] : pole) {
    const I s = L / d;
    for (I c : {x * s, y * s, z * s})
      if (c > (I{1} << 53) || c < -(I{1} << 53)) throw Undefined("polar dual: the coordinates would not be exact doubles");
    D.vertices.push_back({static_cast<double>(x * s), static_cast<double>(y * s), static_cast<double>(z * s)});
  }
  const WingedEdge W = WingedEdge::from(P);
  for (std::uint32_t v = 0; v < P.vertices.size(); ++v) D.faces.push_back(W.vertex_faces(v));
  return D;
}

//> platonic
Polyhedron platonic(Platonic s) {
  std::vector<Point3> X;
  switch (s) {
    case Platonic::tetrahedron:
      X = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
      break;
    case Platonic::cube:
      for (double x : {-1, 1})
        for (double y : {-1, 1})
          for (double z : {-1, 1}) X.push_back({x, y, z});
      break;
    case Platonic::octahedron:
      X = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      break;
    case Platonic::icosahedron:  // (0, ±1, ±φ) and cyclic, with φ ≈ 34/21, scaled by 21
      for (double a : {-21, 21})
        for (double b : {-34, 34}) X.insert(X.end(), {{0, a, b}, {a, b, 0}, {b, 0, a}});
      break;
    case Platonic::dodecahedron:
      X = polar_dual(platonic(Platonic::icosahedron)).vertices;
      break;
  }
  return hull_polyhedron(X);
}
//< platonic

}  // namespace t2
