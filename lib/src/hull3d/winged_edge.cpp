// The winged-edge structure: construction from a face list, walks, and the pointer checks.
#include "t2/hull3d/winged_edge.hpp"

#include <algorithm>
#include <map>

#include "t2/kernel/error.hpp"

namespace t2 {

WingedEdge WingedEdge::from(const Polyhedron& P) {
  if (const std::string why = validate_surface(P); !why.empty()) throw BadInput("winged edge: " + why);
  WingedEdge W;
  const std::vector<Edge3> E = t2::edges(P);
  std::map<Edge3, std::uint32_t> index;
  for (std::uint32_t k = 0; k < E.size(); ++k) index[E[k]] = k;
  W.edges.resize(E.size());
  W.vertices.resize(P.vertices.size());
  W.faces.resize(P.faces.size());
  for (std::uint32_t k = 0; k < E.size(); ++k) {
    W.edges[k].v1 = E[k][0];
    W.edges[k].v2 = E[k][1];
  }
  for (std::uint32_t v = 0; v < P.vertices.size(); ++v) W.vertices[v].p = P.vertices[v];
  for (std::uint32_t f = 0; f < P.faces.size(); ++f) {
    const auto& F = P.faces[f];
    const std::size_t m = F.size();
    auto edge_at = [&](std::size_t k) {  // the edge F[k] -> F[k+1]
      const std::uint32_t a = F[k % m], b = F[(k + 1) % m];
      return index.at({std::min(a, b), std::max(a, b)});
    };
    W.faces[f].af = edge_at(0);
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t e = edge_at(k), prev = edge_at(k + m - 1), next = edge_at(k + 1);
      Edge& x = W.edges[e];
      W.vertices[F[k]].av = e;
      if (x.v1 == F[k]) {  // f traverses e from v1 to v2: f is on its left
        x.fccw = f, x.pccw = prev, x.nccw = next;
      } else {
        x.fcw = f, x.pcw = prev, x.ncw = next;
      }
    }
  }
  return W;
}

std::vector<std::uint32_t> WingedEdge::face_edges(std::uint32_t f) const {
  std::vector<std::uint32_t> out;
  std::uint32_t e = faces[f].af;
  do {
    out.push_back(e);
    e = edges[e].fccw == f ? edges[e].nccw : edges[e].ncw;
  } while (e != faces[f].af && out.size() <= edges.size());
  return out;
}

std::vector<std::uint32_t> WingedEdge::face_vertices(std::uint32_t f) const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t e : face_edges(f)) out.push_back(edges[e].fccw == f ? edges[e].v1 : edges[e].v2);
  return out;
}

//> vertex-faces
std::vector<std::uint32_t> WingedEdge::vertex_faces(std::uint32_t v) const {
  std::vector<std::uint32_t> out;
  std::uint32_t e = vertices[v].av;
  // the face in which e leaves v
  std::uint32_t f = (v == edges[e].v1) ? edges[e].fccw : edges[e].fcw;
  // f is the next face counter-clockwise around v across the edge by which f enters v
  do {
    out.push_back(f);
    // the edge before e in f: it enters v
    e = (f == edges[e].fccw) ? edges[e].pccw : edges[e].pcw;
    // across it, e leaves v again
    f = (edges[e].fccw == f) ? edges[e].fcw : edges[e].fccw;
  } while (e != vertices[v].av && out.size() <= faces.size());
  return out;
}
//< vertex-faces

Polyhedron WingedEdge::to_polyhedron() const {
  Polyhedron P;
  for (const Vertex& v : vertices) P.vertices.push_back(v.p);
  for (std::uint32_t f = 0; f < faces.size(); ++f) P.faces.push_back(face_vertices(f));
  return P;
}

std::string WingedEdge::validate() const {
  const auto E = static_cast<std::uint32_t>(edges.size());
  auto fail = [](const std::string& s) { return s; };
  for (std::uint32_t e = 0; e < E; ++e) {
    const Edge& x = edges[e];
    for (std::uint32_t w : {x.pccw, x.nccw, x.pcw, x.ncw})
      if (w >= E) return fail("edge " + std::to_string(e) + " has a wing that does not exist");
    if (x.fccw >= faces.size() || x.fcw >= faces.size() || x.fccw == x.fcw)
      return fail("edge " + std::to_string(e) + " has bad faces");
    // next(prev(e)) = e in both faces
    auto next_in = [&](std::uint32_t d, std::uint32_t f) { return edges[d].fccw == f ? edges[d].nccw : edges[d].ncw; };
    auto prev_in = [&](std::uint32_t d, std::uint32_t f) { return edges[d].fccw == f ? edges[d].pccw : edges[d].pcw; };
    if (next_in(x.pccw, x.fccw) != e || prev_in(x.nccw, x.fccw) != e || next_in(x.pcw, x.fcw) != e ||
        prev_in(x.ncw, x.fcw) != e)
      return fail("the wings of edge " + std::to_string(e) + " do not point back to it");
    // head of e in fccw is v2 = tail of nccw in fccw; in fcw the head is v1
    auto tail_in = [&](std::uint32_t d, std::uint32_t f) { return edges[d].fccw == f ? edges[d].v1 : edges[d].v2; };
    auto head_in = [&](std::uint32_t d, std::uint32_t f) { return edges[d].fccw == f ? edges[d].v2 : edges[d].v1; };
    if (tail_in(x.nccw, x.fccw) != x.v2 || head_in(x.pccw, x.fccw) != x.v1 || tail_in(x.ncw, x.fcw) != x.v1 ||
        head_in(x.pcw, x.fcw) != x.v2)
      return fail("edge " + std::to_string(e) + " does not meet its wings at its vertices");
    for (std::uint32_t w : {x.pccw, x.nccw})
      if (edges[w].fccw != x.fccw && edges[w].fcw != x.fccw)
        return fail("a ccw wing of edge " + std::to_string(e) + " is not on its face fccw");
    for (std::uint32_t w : {x.pcw, x.ncw})
      if (edges[w].fccw != x.fcw && edges[w].fcw != x.fcw)
        return fail("a cw wing of edge " + std::to_string(e) + " is not on its face fcw");
  }
  for (std::uint32_t v = 0; v < vertices.size(); ++v) {
    const std::uint32_t a = vertices[v].av;
    if (a >= E || (edges[a].v1 != v && edges[a].v2 != v))
      return fail("av of vertex " + std::to_string(v) + " is not incident to it");
  }
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    const std::uint32_t a = faces[f].af;
    if (a >= E || (edges[a].fccw != f && edges[a].fcw != f))
      return fail("af of face " + std::to_string(f) + " is not on its boundary");
    if (face_edges(f).size() > E) return fail("the boundary of face " + std::to_string(f) + " does not close");
  }
  return "";
}

}  // namespace t2
