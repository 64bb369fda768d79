// The Voronoi diagram of T² as the dual of the Delaunay complex (t2/voronoi/voronoi.hpp).
#include "t2/voronoi/voronoi.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "t2/kernel/incircle.hpp"
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
  // A pair p → q on one side; with three, one holding the middle.
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (s[i] == ZERO || s[i] != s[j]) continue;
    if (one_side && between(*v[i], *v[k], *v[j])) continue;  // p → q is the long edge
    return pole(e[i], e[j]);
  }
  throw std::runtime_error("voronoi: the vertex of the face " + to_string(a) + ", " +
                           to_string(b) + ", " + to_string(c) +
                           " (no two proper sites on one side) is not built yet"
                           " (issue 24)");
}
//< circumcentre

//> voronoi-dual
namespace {

/// The boundary of the polygon of vertex x of the faces (their vertex in `vx`), from the
/// half-edge h on it: each site once, counter-clockwise around x (u → v, then around v inside
/// the polygon to the next boundary half-edge).
void polygon(const DelaunayComplex& dc, const std::vector<Index>& vx, Index h, std::vector<Index>& out) {
  const Index x = vx[h / 3], start = h;
  do {
    out.push_back(dc.faces[h / 3][(h + 1) % 3]);  // the origin of h
    h = h - h % 3 + (h + 1) % 3;  // the next half-edge of its face, from the destination of h
    while (vx[dc.twins[h] / 3] == x) {
      const Index e = dc.twins[h];
      h = e - e % 3 + (e + 1) % 3;
    }
  } while (h != start);
}

/// The diagram of the complex `dc` whose sites `sites` (dc.points, or moved from it).
VoronoiDiagram dual(const DelaunayComplex& dc, std::vector<Point> sites) {
  VoronoiDiagram vd;
  vd.sites = std::move(sites);
  vd.duplicates = dc.duplicates;
  if (dc.faces.empty()) {
    if (dc.dimension == 1) {  // two distinct sites: their bisector
      std::vector<char> dropped(vd.sites.size(), 0);
      for (auto [d, k] : dc.duplicates) dropped[d] = 1;
      std::vector<Index> s;
      for (Index k = 0; k < vd.sites.size(); ++k)
        if (!dropped[k]) s.push_back(k);
      vd.lines.emplace_back(s.at(0), s.at(1));
    }
    return vd;
  }
  const auto& F = dc.faces;
  const auto& P = vd.sites;
  const auto& turn = dc.turns;
  const Index nf = static_cast<Index>(F.size());
  std::unordered_map<Index, ExactPoint> centre;  // of the faces that are not proper
  for (Index f = 0; f < nf; ++f)
    if (turn[f] == ZERO) centre.emplace(f, circumcentre(P[F[f][0]], P[F[f][1]], P[F[f][2]]));
  std::vector<std::pair<Index, Index>> merge;  // adjacent faces with one centre (file comment)
  // While no faces merge, each face is a vertex: its cells and edges are written in this pass.
  vd.cells.reserve(3 * std::size_t(nf));
  vd.edges.reserve(3 * std::size_t(nf) / 2);
  constexpr Index ahead = 16;  // the sites are in input order: fetch those of later faces early
  for (Index f = 0; f < nf; ++f) {
    if (f + ahead < nf)
      for (int i = 0; i < 3; ++i) {
        __builtin_prefetch(&P[F[f + ahead][i]]);
        __builtin_prefetch(&F[dc.twins[3 * (f + ahead) + i] / 3]);
      }
    if (f + ahead / 2 < nf)
      for (int i = 0; i < 3; ++i) {
        const Index e = dc.twins[3 * (f + ahead / 2) + i];
        __builtin_prefetch(&P[F[e / 3][e % 3]]);
      }
    if (merge.empty()) {
      vd.cells.insert(vd.cells.end(), F[f].begin(), F[f].end());
      for (int i = 0; i < 3; ++i) {  // u → v in f, from the vertex of f to its twin's
        const Index u = F[f][(i + 1) % 3], v = F[f][(i + 2) % 3];
        if (u < v) vd.edges.push_back({f, dc.twins[3 * f + i] / 3, u, v});
      }
    }
    //> voronoi-merge
    for (int i = 0; i < 3; ++i) {  // f and its neighbour g across slot i, once per edge
      const Index h = 3 * f + i, e = dc.twins[h], g = e / 3;
      if (e < h || turn[f] != turn[g]) continue;
      const Point& d = P[F[g][e % 3]];  // the site of g across the edge
      if (turn[f] != ZERO ? in_circle(P[F[f][0]], P[F[f][1]], P[F[f][2]], d) == ZERO
                          : centre.at(f) == centre.at(g))
        merge.emplace_back(f, g);
    }
    //< voronoi-merge
  }
  if (merge.empty()) return vd;  // one vertex per face, its cells the face (`first` stays empty)
  vd.cells.clear();
  vd.edges.clear();
  std::vector<Index> vx(nf);  // the vertex of each face
  vd.first.push_back(0);
  {
    std::vector<Index> up(nf);  // union-find: the faces of one vertex
    std::iota(up.begin(), up.end(), Index(0));
    for (auto [f, g] : merge) up[find(up, f)] = find(up, g);
    std::vector<Index> rep(nf, Triangulation::none);  // root → vertex
    std::vector<Index> face;  // vertex → its first face
    for (Index f = 0; f < nf; ++f) {
      const Index r = find(up, f);
      if (rep[r] == Triangulation::none) {
        rep[r] = static_cast<Index>(face.size());
        face.push_back(f);
      }
      vx[f] = rep[r];
    }
    std::vector<Index> border(face.size(), Triangulation::none);  // a half-edge on its boundary
    std::vector<char> fan(face.size(), 0);
    for (Index h = 0; h < 3 * nf; ++h) {
      const Index x = vx[h / 3];
      if (vx[dc.twins[h] / 3] == x) fan[x] = 1;
      else if (border[x] == Triangulation::none) border[x] = h;
    }
    for (Index x = 0; x < face.size(); ++x) {
      if (border[x] == Triangulation::none)
        throw std::logic_error("voronoi: a vertex without an edge (one circumcentre for all faces)");
      polygon(dc, vx, border[x], vd.cells);
      vd.first.push_back(static_cast<Index>(vd.cells.size()));
      if (fan[x]) vd.fans.emplace_back(x, F[face[x]]);
    }
  }
  for (Index h = 0; h < 3 * nf; ++h) {  // u → v in f, between the vertices of f and its twin's
    const Index f = h / 3, g = dc.twins[h] / 3;
    const Index u = F[f][(h + 1) % 3], v = F[f][(h + 2) % 3];
    if (u < v && vx[f] != vx[g]) vd.edges.push_back({vx[f], vx[g], u, v});
  }
  return vd;
}

}  // namespace
//< voronoi-dual

ExactPoint VoronoiDiagram::vertex(Index v) const {
  const auto it = std::lower_bound(fans.begin(), fans.end(), v, [](const auto& p, Index x) { return p.first < x; });
  if (it != fans.end() && it->first == v) return circumcentre(sites[it->second[0]], sites[it->second[1]], sites[it->second[2]]);
  const auto c = vertex_sites(v);
  return circumcentre(sites[c[0]], sites[c[1]], sites[c[2]]);
}

//> voronoi-cell
std::vector<Index> VoronoiDiagram::cell(Index s) const {
  // At vertex v, s is followed by a and preceded by b (counter-clockwise around v): the face
  // (s, a, b) of the complex. The next face counter-clockwise around s is across s–b, the
  // vertex where s is followed by b.
  std::unordered_map<Index, Index> after;   // the site after s at a vertex → that vertex
  std::unordered_map<Index, Index> before;  // vertex → the site before s there
  const auto visit = [&](Index v) {
    const auto c = vertex_sites(v);
    for (std::size_t k = 0; k < c.size(); ++k)
      if (c[k] == s) {
        after[c[(k + 1) % c.size()]] = v;
        before[v] = c[(k + c.size() - 1) % c.size()];
      }
  };
  if (site_first.empty()) {
    for (Index v = 0; v < size(); ++v) visit(v);
  } else if (s + 1 < site_first.size()) {
    for (Index k = site_first[s]; k < site_first[s + 1]; ++k) visit(site_vertices[k]);
  }
  std::vector<Index> out;
  if (before.empty()) return out;
  const Index start = before.begin()->first;
  Index v = start;
  do {
    out.push_back(v);
    v = after.at(before.at(v));
  } while (v != start && out.size() < before.size());
  return out;
}
//< voronoi-cell

namespace {
// site_first and site_vertices (voronoi.hpp): each vertex listed under each of its cells, by a
// counting sort of `cells`. O(cells.size()).
VoronoiDiagram indexed(VoronoiDiagram vd) {
  vd.site_first.assign(vd.sites.size() + 1, 0);
  for (const Index s : vd.cells) ++vd.site_first[s + 1];
  for (std::size_t s = 0; s < vd.sites.size(); ++s) vd.site_first[s + 1] += vd.site_first[s];
  vd.site_vertices.resize(vd.cells.size());
  std::vector<Index> at(vd.site_first.begin(), vd.site_first.end() - 1);
  for (Index v = 0; v < vd.size(); ++v)
    for (const Index s : vd.vertex_sites(v)) vd.site_vertices[at[s]++] = v;
  return vd;
}
}  // namespace

VoronoiDiagram voronoi(const DelaunayComplex& dc) { return indexed(dual(dc, dc.points)); }

VoronoiDiagram voronoi(std::span<const Point> sites) {
  DelaunayComplex dc = delaunay_complex(sites);
  std::vector<Point> p = std::move(dc.points);
  return indexed(dual(dc, std::move(p)));
}

}  // namespace t2
