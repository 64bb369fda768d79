// The Voronoi diagram of T² as the dual of the Delaunay complex (t2/voronoi/voronoi.hpp).
#include "t2/voronoi/voronoi.hpp"

#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"

namespace t2 {

namespace {

using Index = Triangulation::Index;

Integer det3(const Integer& a1, const Integer& a2, const Integer& a3, const Integer& b1, const Integer& b2,
             const Integer& b3, const Integer& c1, const Integer& c2, const Integer& c3) {
  return a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1);
}

/// The pole [0, ℓ_x, ℓ_y] of ℓ = p ∨ q: the point of Ω to the left of p → q.
ExactPoint pole(const ExactPoint& p, const ExactPoint& q) {
  return ExactPoint(Integer(0), Integer(p.y() * q.w() - p.w() * q.y()), Integer(p.w() * q.x() - p.x() * q.w()));
}

/// Is m strictly between a and b on their line (one side, collinear)?
bool between(const Point& a, const Point& m, const Point& b) {
  const Sign s = compare_xy(a, m);
  return s != ZERO && s == compare_xy(m, b);
}

/// Union-find over faces.
Index find(std::vector<Index>& up, Index f) {
  while (up[f] != f) f = up[f] = up[up[f]];
  return f;
}

}  // namespace

//> circumcentre
ExactPoint circumcentre(const Point& a, const Point& b, const Point& c) {
  const Point* v[3] = {&a, &b, &c};
  const ExactPoint e[3] = {to_exact(a), to_exact(b), to_exact(c)};
  const Sign s[3] = {sign_of(a.w()), sign_of(b.w()), sign_of(c.w())};
  const bool one_side = s[0] != ZERO && s[0] == s[1] && s[1] == s[2];
  if (one_side && orient(a, b, c) != ZERO) {  // the circle through the drawn positions
    Integer P[3], X[3], Y[3], W[3];
    for (int i = 0; i < 3; ++i) {
      P[i] = e[i].x() * e[i].x() + e[i].y() * e[i].y();
      X[i] = e[i].w() * e[i].x();
      Y[i] = e[i].w() * e[i].y();
      W[i] = e[i].w() * e[i].w();
    }
    const Integer A = det3(X[0], Y[0], W[0], X[1], Y[1], W[1], X[2], Y[2], W[2]);
    const Integer B = -det3(P[0], Y[0], W[0], P[1], Y[1], W[1], P[2], Y[2], W[2]);
    const Integer C = det3(P[0], X[0], W[0], P[1], X[1], W[1], P[2], X[2], W[2]);
    return ExactPoint(Integer(2 * A), Integer(-B), Integer(-C));
  }
  for (int i = 0; i < 3; ++i) {  // a pair p → q on one side; with three, one holding the middle
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (s[i] == ZERO || s[i] != s[j]) continue;
    if (one_side && between(*v[i], *v[k], *v[j])) continue;  // p → q is the long edge
    return pole(e[i], e[j]);
  }
  throw std::runtime_error("voronoi: the vertex of the face " + to_string(a) + ", " + to_string(b) + ", " +
                           to_string(c) + " (no two proper sites on one side) is not built yet (issue 24)");
}
//< circumcentre

//> voronoi-dual
VoronoiDiagram voronoi(const DelaunayComplex& dc) {
  VoronoiDiagram vd;
  vd.duplicates = dc.duplicates;
  if (dc.faces.empty()) {
    if (dc.dimension == 1) {  // two distinct sites: their bisector
      std::vector<char> dropped(dc.points.size(), 0);
      for (auto [d, k] : dc.duplicates) dropped[d] = 1;
      std::vector<Index> s;
      for (Index k = 0; k < dc.points.size(); ++k)
        if (!dropped[k]) s.push_back(k);
      vd.lines.emplace_back(s.at(0), s.at(1));
    }
    return vd;
  }
  const Index nf = static_cast<Index>(dc.faces.size());
  std::unordered_map<std::uint64_t, Index> half;  // directed edge u → v: 3·face + slot of u
  auto key = [](Index u, Index v) { return (std::uint64_t(u) << 32) | v; };
  for (Index f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) half[key(dc.faces[f][i], dc.faces[f][(i + 1) % 3])] = 3 * f + i;
  auto twin = [&](Index h) {
    const auto& t = dc.faces[h / 3];
    return half.at(key(t[(h % 3 + 1) % 3], t[h % 3]));
  };
  std::vector<ExactPoint> centre;
  centre.reserve(nf);
  for (const auto& t : dc.faces) centre.push_back(circumcentre(dc.points[t[0]], dc.points[t[1]], dc.points[t[2]]));
  std::vector<Index> up(nf);  // faces with one circumcentre, across their common edges
  std::iota(up.begin(), up.end(), Index(0));
  for (Index h = 0; h < 3 * nf; ++h) {
    const Index g = twin(h) / 3, f = h / 3;
    if (f < g && centre[f] == centre[g]) up[find(up, f)] = find(up, g);
  }
  std::vector<Index> vertex(nf, Triangulation::none);
  for (Index f = 0; f < nf; ++f) {
    const Index r = find(up, f);
    if (vertex[r] == Triangulation::none) {
      vertex[r] = static_cast<Index>(vd.vertices.size());
      vd.vertices.push_back(centre[r]);
    }
    vertex[f] = vertex[r];
  }
  // The sites around each vertex: the boundary of its polygon, u → v with the next edge from v.
  std::vector<std::unordered_map<Index, Index>> next(vd.vertices.size());
  for (Index h = 0; h < 3 * nf; ++h) {
    const Index f = h / 3, g = twin(h) / 3;
    const auto& t = dc.faces[f];
    const Index u = t[h % 3], v = t[(h % 3 + 1) % 3];
    if (vertex[f] == vertex[g]) continue;
    next[vertex[f]][u] = v;
    if (u < v) vd.edges.push_back({vertex[f], vertex[g], u, v});
  }
  vd.vertex_sites.resize(vd.vertices.size());
  for (Index x = 0; x < vd.vertices.size(); ++x) {
    if (next[x].empty()) throw std::logic_error("voronoi: a vertex without an edge (one circumcentre for all faces)");
    Index u = next[x].begin()->first;
    for (std::size_t m = 0; m < next[x].size(); ++m) {
      vd.vertex_sites[x].push_back(u);
      u = next[x].at(u);
    }
  }
  return vd;
}
//< voronoi-dual

VoronoiDiagram voronoi(std::span<const Point> sites) { return voronoi(delaunay_complex(sites)); }

}  // namespace t2
