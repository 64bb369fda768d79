// The Voronoi diagram of T² as the dual of the Delaunay complex (chapter 11,
// t2/voronoi/voronoi.hpp): what `t2 voronoi` runs and draws, timed by `t2 bench voronoi`, and
// animated by `t2 animate voronoi`: the complex, its faces' circumcentres (in front, behind, on
// Ω), the edges, two cells, the diagram.
#include "algorithms/voronoi.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/kernel/error.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/trace/recording.hpp"
#include "t2/voronoi/complex.hpp"

namespace t2cli::algorithms {

using Index = t2::VoronoiDiagram::Index;

namespace {
t2::ScenePoint point(const t2::Point& p, const t2::SceneStyle& style = {}) { return {p, 0, {}, style}; }
}  // namespace

// The edge from a to b between the cells of s and t, drawn: the segment of T² from a to b when
// a point of it, a + b, has no site nearer than s; otherwise the other arc, through ¬(a + b).
// Only the sites of a and b need a test: each site d ≠ s, t leaves s nearest on a closed half
// H_d of the bisector's great circle, and the edge is the arc ∩ H_d from a to b. For d at a,
// H_d ends at a (d, s, t are equidistant there), and likewise at b; so the arc ∩ H_d over
// those d alone, which holds the edge, already ends at a and at b: it is the edge. O(1) a
// vertex of three sites, where a scan of all n sites made the drawing O(n²).
void add_voronoi_edge(const std::vector<t2::Point>& P, const t2::VoronoiDiagram& vd,
                      const t2::VoronoiDiagram::Edge& e, const t2::SceneStyle& st, t2::Scene& s) {
  const t2::ExactPoint a = vd.vertex(e.a), b = vd.vertex(e.b);
  if (a == t2::antipode(b)) return;  // either half of the bisector: not drawn
  const t2::ExactPoint m(t2::Integer(a.w() + b.w()), t2::Integer(a.x() + b.x()), t2::Integer(a.y() + b.y()));
  bool other = false;
  const t2::ExactPoint se = t2::to_exact(P[e.s]);
  for (const Index v : {e.a, e.b})
    for (const Index k : vd.vertex_sites(v)) {
      try {
        other = other || t2::compare_distance(t2::to_exact(P[k]), se, m) == t2::NEGATIVE;
      } catch (const t2::Undefined&) {  // m on Ω between a front and a back site: no order
      }
    }
  const t2::Point pa = t2::to_double(a), pb = t2::to_double(b);
  if (!other) {
    s.segments.push_back(t2::SceneSegment{point(pa), point(pb), 0, st});
    return;
  }
  const t2::Point pm = t2::to_double(t2::antipode(m));
  s.segments.push_back(t2::SceneSegment{point(pa), point(pm), 0, st});
  s.segments.push_back(t2::SceneSegment{point(pm), point(pb), 0, st});
}

// The bisector lines (no vertex) of the pairs `lines`, drawn into `s`.
void add_bisector_lines(const std::vector<t2::Point>& P, const std::vector<std::pair<Index, Index>>& lines,
                        const t2::SceneStyle& style, t2::Scene& s) {
  for (auto [i, j] : lines) {
    const t2::Point &a = P[i], &b = P[j];
    t2::Point p(0, 1, 0), q(0, 0, 1);  // sites on different sides: Ω
    if (t2::sign_of(a.w()) == t2::sign_of(b.w()) && a.w() != 0) {  // the perpendicular bisector
      const double ax = a.x() / a.w(), ay = a.y() / a.w(), bx = b.x() / b.w(), by = b.y() / b.w();
      p = t2::Point(a.w() > 0 ? 1 : -1, (ax + bx) / 2 * (a.w() > 0 ? 1 : -1), (ay + by) / 2 * (a.w() > 0 ? 1 : -1));
      q = t2::Point(0, ay - by, bx - ax);
    }
    s.lines.push_back(t2::SceneLine{point(p), point(q), 0, style});
  }
}

t2::Scene voronoi_scene(const std::vector<t2::Point>& P, const t2::VoronoiDiagram& vd, const t2::SceneStyle& edge,
                        const t2::SceneStyle& vertex) {
  t2::Scene s;
  for (const auto& e : vd.edges) add_voronoi_edge(P, vd, e, edge, s);
  for (Index v = 0; v < vd.size(); ++v) s.points.push_back(point(t2::to_double(vd.vertex(v)), vertex));
  add_bisector_lines(P, vd.lines, edge, s);
  return s;
}

namespace {

namespace tr = t2::trace;

t2::SceneStyle style(const char* color, double width) {
  t2::SceneStyle s;
  s.color = color, s.width = width;
  return s;
}

const char* const kEdge = "#d62728";
const char* const kCell = "#ff7f0e";

// The side of a point: 1 front, -1 back, 0 on Ω.
int side(const t2::Point& p) { return p.w() > 0 ? 1 : p.w() < 0 ? -1 : 0; }

// The three sites whose circumcentre vertex v is (a face of the complex at v).
tr::Tri face_of(const t2::VoronoiDiagram& vd, Index v) {
  const auto sites = vd.vertex_sites(v);
  if (sites.size() == 3) return {sites[0], sites[1], sites[2]};
  for (const auto& [u, f] : vd.fans)
    if (u == v) return {f[0], f[1], f[2]};
  return {sites[0], sites[1], sites[2]};
}

// Adds the vertices of `drawn` (indices of V) to the overlay as dots.
void add_vertices(t2::Scene& o, const std::vector<t2::Point>& V, const std::vector<Index>& drawn) {
  t2::SceneStyle dot = style(kEdge, 1);
  dot.marker = "dot";
  for (const Index v : drawn) o.points.push_back(point(V[v], dot));
}

// The words for a group of vertices.
const char* group_text(int s, bool front_sites) {
  if (s > 0) return "in front (w > 0): the centres of the faces that turn counter-clockwise on the front";
  if (s < 0)
    return front_sites ? "behind (w < 0): the centres of the clockwise faces of front sites, the farthest-point "
                         "Voronoi vertices: behind Ω the nearest site is the farthest one as drawn"
                       : "behind (w < 0): the centres of the faces whose circle is centred on the back";
  return "on Ω: the centres of the faces with sites on both sides or on Ω, where cells meet at infinity";
}

// The Voronoi diagram recorded: the complex (lecture); each vertex with its face and circle
// (debugging), each side's vertices (lecture); the edges; two cells; the diagram.
void record_voronoi(const Points& P, const std::string& name, tr::Recording& rec) {
  t2::DelaunayComplex dc;
  t2::VoronoiDiagram vd;
  try {
    dc = t2::delaunay_complex(P);
    vd = t2::voronoi(dc);
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", name, e.what()));
  } catch (const t2::BadInput& e) {
    throw t2::BadInput(fmt::format("{}: {}", name, e.what()));
  } catch (const std::runtime_error& e) {  // not built yet (complex.hpp, voronoi.hpp)
    throw t2::Undefined(fmt::format("{}: not implemented: {}", name, e.what()));
  }
  std::vector<t2::Point> V;  // the vertices, rounded once for the picture
  for (Index v = 0; v < vd.size(); ++v) V.push_back(t2::to_double(vd.vertex(v)));
  std::vector<tr::Tri> faces;
  for (const auto& f : dc.faces) faces.push_back({f[0], f[1], f[2]});
  const bool front_sites = std::all_of(P.begin(), P.end(), [](const t2::Point& p) { return p.w() > 0; });
  int count[3] = {0, 0, 0};
  for (const t2::Point& c : V) ++count[side(c) + 1];
  tr::Step m = make_step("complex",
                         fmt::format("The Delaunay complex of the {} sites: {} faces covering the whole sphere, each the "
                                     "dual of one Voronoi vertex, its circumcentre: {} in front, {} behind, {} on "
                                     "Omega{}.",
                                     P.size(), dc.faces.size(), count[2], count[0], count[1],
                                     vd.size() < dc.faces.size() ? " (cocircular faces share a vertex)" : ""),
                         "Delaunay complex");
  if (front_sites && count[0] > 0)
    m.text += " The faces that turn clockwise are the farthest-point triangles of the hull's vertices: their edges "
              "cross the others in the plane, and as faces of the sphere each is the large triangle that goes "
              "round behind.";
  m.triangles = faces;
  rec.add(m);
  std::vector<Index> drawn;
  for (const int s : {1, -1, 0}) {
    for (Index v = 0; v < vd.size(); ++v) {
      if (side(V[v]) != s) continue;
      const tr::Tri f = face_of(vd, v);
      tr::Step st = make_step("vertex", "", "Delaunay complex");
      st.depth = tr::Depth::debugging;
      st.triangles = faces;
      st.touched = {f};
      st.points = {f[0], f[1], f[2]};
      add_vertices(st.overlay, V, drawn);
      if (s != 0) st.overlay.circles.push_back({point(V[v]), point(P[f[0]]), 0, style(kEdge, 1.4)});
      tr::add_point(st.overlay, V[v], fmt::format("v{}", v));
      st.text = fmt::format("The face p{} p{} p{}: its circumcentre v{} is {}.", f[0], f[1], f[2], v,
                            s > 0 ? "in front" : s < 0 ? "behind" : "on Omega");
      if (s < 0 && front_sites)
        st.text += " The face turns clockwise: on the sphere it is all but the small triangle drawn, and its "
                   "circle holds every site.";
      drawn.push_back(v);
      rec.add(std::move(st));
    }
    tr::Step g = make_step("vertices", fmt::format("The {} Voronoi vertices {}.", count[s + 1], group_text(s, front_sites)),
                           "Delaunay complex");
    g.triangles = faces;
    add_vertices(g.overlay, V, drawn);
    rec.add(std::move(g));
  }
  const t2::Scene diagram = voronoi_scene(P, vd, style(kEdge, 2), [] {
    t2::SceneStyle d = style(kEdge, 1);
    d.marker = "dot";
    return d;
  }());
  tr::Step e = make_step("edges",
                         fmt::format("The {} Voronoi edges, each dual to an edge of the complex between two faces of "
                                     "different centres, on the bisector of its two sites{}.",
                                     vd.edges.size(),
                                     vd.lines.empty() ? "" : fmt::format("; {} bisector lines", vd.lines.size())),
                         "Delaunay complex");
  e.triangles = faces;
  e.overlay = diagram;
  rec.add(std::move(e));
  // Two cells: the middle site's, and the first whose cell has a vertex on another side.
  std::vector<Index> shown{Index(P.size() / 2)};
  for (Index s = 0; s < P.size() && shown.size() < 2; ++s) {
    const auto c = vd.cell(s);
    if (s != shown[0] && std::any_of(c.begin(), c.end(), [&](Index v) { return side(V[v]) != side(P[s]); }))
      shown.push_back(s);
  }
  for (const Index s : shown) {
    const auto c = vd.cell(s);
    if (c.empty()) continue;
    int on[3] = {0, 0, 0};
    for (const Index v : c) ++on[side(V[v]) + 1];
    tr::Step st = make_step("cell", "", "Voronoi diagram");
    st.overlay = diagram;
    for (const auto& ed : vd.edges)
      if (ed.s == s || ed.t == s) add_voronoi_edge(P, vd, ed, style(kCell, 3.5), st.overlay);
    st.points = {s};
    for (const Index v : c)
      st.entries.push_back(fmt::format("v{}: {}", v, side(V[v]) > 0 ? "front" : side(V[v]) < 0 ? "back" : "Omega"));
    st.text = fmt::format("The cell of p{}: {} vertices, {} in front, {} behind, {} on Omega.", s, c.size(), on[2],
                          on[0], on[1]);
    if (front_sites && on[0] > 0)
      st.text += fmt::format(" It crosses Omega: its part behind is where p{} is the farthest site.", s);
    rec.add(std::move(st));
  }
  tr::Step a = make_step("answer",
                         fmt::format("The Voronoi diagram of T2: {} vertices, {} edges{}.", vd.size(), vd.edges.size(),
                                     vd.duplicates.empty()
                                         ? ""
                                         : fmt::format("; {} duplicate sites merged", vd.duplicates.size())),
                         "Voronoi diagram");
  a.overlay = diagram;
  rec.add(std::move(a));
}

}  // namespace

namespace {

T2_PROBLEM({"voronoi", "vertices", Input::plane});

T2_ALGORITHM({.name = "voronoi",  // what `t2 voronoi` runs
              .problem = "voronoi",
              .summary = "t2::voronoi: the dual of the Delaunay complex of T2, front and back vertices (Algorithm 11)",
              .title = "the Voronoi diagram of T2 (the dual)",
              .run = [](const Points& P) {
                return voronoi_scene(P, t2::voronoi(std::span<const t2::Point>(P)), style(kEdge, 2), {});
              },
              .record = record_voronoi,
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return t2::voronoi(std::span<const t2::Point>(P)).size(); };
              }});

}  // namespace
}  // namespace t2cli::algorithms
