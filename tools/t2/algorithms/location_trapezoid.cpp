// Point location by trapezoidal maps (chapter 14, t2/location/trapezoid_locate.hpp): timed by
// `t2 bench locate` (the maps built before the clock) and `locate-build`, and animated by
// `t2 animate trapezoid`: the map of each closed side grows segment by segment (the trapezoids
// each segment destroys and makes, the DAG's size and depth), then each query descends the DAG,
// node by node, to its trapezoid. The map to locate in is the Delaunay triangulation of the
// points, as for the walk (location.cpp), and so are the queries.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/answer.hpp"
#include "algorithms/location.hpp"
#include "algorithms/registry.hpp"
#include "t2/location/trapezoid_locate.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/trace/recording.hpp"

namespace t2cli::algorithms {
namespace {

namespace tr = t2::trace;
using t2::Location;
using t2::Subdivision;
using t2::TrapezoidMap;
using Index = TrapezoidMap::Index;

// ---- The picture of a trapezoid: doubles, a drawing, never a decision ----

const char* const kWall = "#7f7f7f";
const char* const kNew = "#ff7f0e";
const char* const kSegment = "#1f77b4";

using H3 = std::array<double, 3>;  // a point [w, x, y], or a line's coefficients [W, X, Y]

double dot(const H3& a, const H3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

H3 unit(const H3& a) {
  const double n = std::hypot(a[0], a[1], a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}

// a × b: the line a ∨ b of two points (L·p = orient(a, b, p)), or the point of two lines.
H3 cross(const H3& a, const H3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Point i of the map M, as a unit vector.
H3 at(const TrapezoidMap& M, Index i) { return unit({M.point(i).w(), M.point(i).x(), M.point(i).y()}); }

// The part of the convex region C of the front hemisphere (its corners in order) where L·v ≥ 0
// (Sutherland–Hodgman). Where an edge u v crosses the line, the corner |L·u| v + |L·v| u: a
// positive combination of its ends, so a point of the segment of T² between them. Two corners
// on Ω that are more than a right angle apart can only be the line's own two points at infinity,
// which are antipodal (no segment joins them): its front point `on` goes between them.
std::vector<H3> cut(const std::vector<H3>& C, const H3& L, const H3& on) {
  std::vector<H3> out;
  for (std::size_t k = 0; k < C.size(); ++k) {
    const H3 &u = C[k], &v = C[(k + 1) % C.size()];
    const double lu = dot(L, u), lv = dot(L, v);
    if (lu >= 0) out.push_back(u);
    if ((lu > 0 && lv < 0) || (lu < 0 && lv > 0)) {
      const double a = std::abs(lu), b = std::abs(lv);
      out.push_back(unit({a * v[0] + b * u[0], a * v[1] + b * u[1], a * v[2] + b * u[2]}));
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    const H3 &u = out[k], &v = out[(k + 1) % out.size()];
    if (u[0] == 0 && v[0] == 0 && dot(u, v) < 0) {
      out.insert(out.begin() + static_cast<std::ptrdiff_t>(k + 1), unit(on));
      break;
    }
  }
  return out;
}

// Trapezoid t of the map M as a polygon of T², for the picture: the front hemisphere (its
// boundary Ω, four corners) cut by the half-planes above its bottom segment, below its top one,
// right of the vertical through its left point and left of the vertical through its right point.
// A side without a bound reaches Ω. On the back side (`back`: the map's points are antipodes of
// the input's) the antipodes of the corners. Empty for the first trapezoid (the whole side).
std::vector<t2::Point> trapezoid_polygon(const TrapezoidMap& M, Index t, bool back) {
  const TrapezoidMap::Trapezoid& z = M.trapezoids()[t];
  std::vector<H3> C{{0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {0, 0, -1}};
  bool bounded = false;
  if (z.bottom != TrapezoidMap::none) {
    const auto [a, b] = M.segment(z.bottom);
    C = cut(C, cross(at(M, a), at(M, b)), at(M, a)), bounded = true;
  }
  if (z.top != TrapezoidMap::none) {
    const auto [a, b] = M.segment(z.top);
    C = cut(C, cross(at(M, b), at(M, a)), at(M, a)), bounded = true;
  }
  if (z.leftp != TrapezoidMap::none) {  // x·w_l − x_l·w ≥ 0
    const H3 l = at(M, z.leftp);
    C = cut(C, {-l[1], l[0], 0}, l), bounded = true;
  }
  if (z.rightp != TrapezoidMap::none) {
    const H3 r = at(M, z.rightp);
    C = cut(C, {r[1], -r[0], 0}, r), bounded = true;
  }
  std::vector<t2::Point> out;
  if (!bounded) return out;
  for (const H3& c : C) {
    const t2::Point p = back ? t2::Point(-c[0], -c[1], -c[2]) : t2::Point(c[0], c[1], c[2]);
    if (out.empty() || out.back() != p) out.push_back(p);
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  if (out.size() < 3) out.clear();
  return out;
}

// The left wall of trapezoid t of M, for the picture: the vertical through its left point, from
// its bottom segment (or Ω below) to its top segment (or Ω above); nothing when it has no left
// point or the wall is degenerate (a vertical segment). The walls of all trapezoids draw the map:
// those right of a point cover its vertical extensions up and down. Antipodes on the back.
void add_wall(t2::Scene& o, const TrapezoidMap& M, Index t, bool back) {
  const TrapezoidMap::Trapezoid& z = M.trapezoids()[t];
  if (z.leftp == TrapezoidMap::none) return;
  const H3 l = at(M, z.leftp), V{-l[1], l[0], 0};
  const auto end = [&](Index s, double up) -> std::optional<H3> {  // the wall meets s, or Ω
    if (s == TrapezoidMap::none) return H3{0, 0, up};
    const auto [a, b] = M.segment(s);
    H3 m = cross(cross(at(M, a), at(M, b)), V);
    if (!(std::abs(m[0]) > 0)) return std::nullopt;
    if (m[0] < 0) m = {-m[0], -m[1], -m[2]};
    return unit(m);
  };
  const auto lo = end(z.bottom, -1), hi = end(z.top, 1);
  if (!lo || !hi) return;
  const double s = back ? -1 : 1;
  const auto point = [&](const H3& c) { return t2::Point(s * c[0], s * c[1], s * c[2]); };
  const auto add = [&](const H3& a, const H3& b) {
    const t2::Point p = point(a), q = point(b);
    if (p == q || p == t2::antipode(q)) return;
    tr::add_segment(o, p, q);
    o.segments.back().style.color = kWall;
    o.segments.back().style.width = 0.7;
  };
  if ((*lo)[0] == 0 && (*hi)[0] == 0) {  // the whole vertical: through the left point
    add(*lo, l), add(l, *hi);
  } else {
    add(*lo, *hi);
  }
}

// ---- The recording ----


// One map as the recorder hears it: the map, its points' input indices, its side, and the
// segments inserted so far (input indices).
struct Seen {
  const TrapezoidMap* map = nullptr;
  std::span<const std::uint32_t> input_of;
  bool back = false;
  std::vector<tr::Edge> inserted;
};

// The trapezoid with these corners, filled.
void add_filled(t2::Scene& o, const std::vector<t2::Point>& corners) {
  if (corners.empty()) return;
  t2::ScenePolygon g;
  for (const t2::Point& c : corners) g.vertices.push_back(tr::overlay_point(c));
  g.style.color = kNew, g.style.width = 1.4, g.style.fill = kNew, g.style.opacity = 0.3;
  o.polygons.push_back(std::move(g));
}

// Every map heard so far: the walls of its live trapezoids and its segments; the trapezoids
// [fill_from, fill_to) of the last map filled.
t2::Scene maps_overlay(const std::vector<Seen>& maps, const Points& P, Index fill_from, Index fill_to) {
  t2::Scene o;
  for (std::size_t m = 0; m < maps.size(); ++m) {
    const TrapezoidMap& M = *maps[m].map;
    for (Index t = 0; t < M.trapezoids().size(); ++t) {
      if (M.trapezoids()[t].node == TrapezoidMap::none) continue;
      add_wall(o, M, t, maps[m].back);
      if (m + 1 == maps.size() && t >= fill_from && t < fill_to) add_filled(o, trapezoid_polygon(M, t, maps[m].back));
    }
    for (const tr::Edge& e : maps[m].inserted) {
      tr::add_segment(o, P[e[0]], P[e[1]]);
      o.segments.back().style.color = kSegment;
      o.segments.back().style.width = 1.6;
    }
  }
  return o;
}

// "the trapezoid below p3 p8 and above p1 p2, between the verticals of p4 and p7"
std::string trapezoid_text(const Seen& s, Index t) {
  const TrapezoidMap::Trapezoid& z = s.map->trapezoids()[t];
  const auto p = [&](Index i) { return fmt::format("p{}", s.input_of[i]); };
  const auto seg = [&](Index i) {
    const auto [a, b] = s.map->segment(i);
    return p(a) + " " + p(b);
  };
  std::string out = fmt::format("trapezoid {}", t);
  out += z.top == TrapezoidMap::none ? " (nothing above" : " (below " + seg(z.top);
  out += z.bottom == TrapezoidMap::none ? ", nothing below" : ", above " + seg(z.bottom);
  out += z.leftp == TrapezoidMap::none ? ", open to the left" : ", right of " + p(z.leftp);
  out += z.rightp == TrapezoidMap::none ? ", open to the right)" : ", left of " + p(z.rightp) + ")";
  return out;
}

Seen& seen(std::vector<Seen>& maps, const tr::Report& r, const Points& P) {
  if (maps.empty() || maps.back().map != r.trapezoids) {
    for (Seen& s : maps)
      if (s.map == r.trapezoids) return s;
    maps.push_back({r.trapezoids, r.input_of, !r.input_of.empty() && P[r.input_of[0]].w() < 0, {}});
  }
  return maps.back();
}

// The construction: each insertion a lecture step (the new trapezoids filled).
void record_build(const Points& P, const Subdivision& S, std::vector<Seen>& maps,
                  std::unique_ptr<const t2::TrapezoidLocator>& L, tr::Recording& rec) {
  std::size_t count = 0;
  L = std::make_unique<const t2::TrapezoidLocator>(S, 0x7A9E201D, [&](const tr::Report& r) {
    if (r.event != tr::Event::trapezoid_split) return;
    Seen& s = seen(maps, r, P);
    s.inserted.push_back({r.at[0], r.at[1]});
    tr::Step st = make_step("insert", "", "trapezoids");
    st.edges = {{r.at[0], r.at[1]}};
    st.points = {r.at[0], r.at[1]};
    st.overlay = maps_overlay(maps, P, r.faces[0], r.faces[1]);
    const std::size_t made = r.faces[1] - r.faces[0];
    st.text = fmt::format(
        "Segment {} of the {} map: p{} p{} crosses {} trapezoid{}, left to right; they are destroyed and "
        "{} new ones take their place (filled). The DAG has {} nodes and depth {}.",
        ++count, s.back ? "back" : "front", r.at[0], r.at[1], r.face_list.size(), r.face_list.size() == 1 ? "" : "s",
        made, r.trapezoids->nodes(), r.trapezoids->depth());
    std::size_t live = 0;
    for (const auto& z : r.trapezoids->trapezoids()) live += z.node != TrapezoidMap::none;
    st.entries = {fmt::format("DAG: {} nodes, depth {}", r.trapezoids->nodes(), r.trapezoids->depth()),
                  fmt::format("trapezoids: {}", live), fmt::format("inserted: p{} p{}", r.at[0], r.at[1])};
    rec.add(std::move(st));
  });
}

// One query: each DAG node a debugging step, the answer a lecture step.
Location record_query(const Points& P, const Subdivision& S, const t2::TrapezoidLocator& L, std::vector<Seen>& maps,
                      const t2::Point& q, std::size_t k, tr::Step& last, tr::Recording& rec) {
  std::size_t nodes = 0, walked = 0;
  std::vector<std::string> path;  // the DAG nodes met, in words
  Index leaf = TrapezoidMap::none;
  const Seen* in = nullptr;
  const auto hook = [&](const tr::Report& r) {
    if (r.event != tr::Event::dag_x && r.event != tr::Event::dag_y && r.event != tr::Event::dag_leaf) {
      ++walked;  // the walk's reports: a side without a map, or Ω
      return;
    }
    ++nodes;
    in = &seen(maps, r, P);
    tr::Step st = make_step("node", "", "trapezoids");
    st.depth = tr::Depth::debugging;
    st.overlay = maps_overlay(maps, P, 0, 0);
    if (r.event == tr::Event::dag_x) {
      tr::add_line(st.overlay, P[r.at[0]], t2::Point(0, 0, 1));  // the vertical through it
      st.points = {r.at[0]};
      const char* go = r.sign == t2::ZERO ? "equal to" : r.sign == t2::NEGATIVE ? "left of" : "right of";
      st.text = fmt::format("q{}: x-node p{}: q{} is {} it.", k, r.at[0], k, go);
      path.push_back(fmt::format("x p{}: {}", r.at[0], go));
    } else if (r.event == tr::Event::dag_y) {
      st.edges = {{r.at[0], r.at[1]}};
      const char* go = r.sign == t2::ZERO ? "on" : r.sign == t2::POSITIVE ? "above" : "below";
      st.text = fmt::format("q{}: y-node p{} p{}: q{} is {} it.", k, r.at[0], r.at[1], k, go);
      path.push_back(fmt::format("y p{} p{}: {}", r.at[0], r.at[1], go));
    } else {
      leaf = r.faces[0];
      add_filled(st.overlay, trapezoid_polygon(*in->map, leaf, in->back));
      st.text = fmt::format("q{}: a leaf: q{} lies in {}.", k, k, trapezoid_text(*in, leaf));
      path.push_back(fmt::format("leaf: trapezoid {}", leaf));
    }
    st.entries = path;
    tr::add_point(st.overlay, q, fmt::format("q{}", k));
    rec.add(std::move(st));
  };
  const Location l = L.locate(q, hook);
  tr::Step st = make_step("located", "", "trapezoids");
  st.overlay = maps_overlay(maps, P, 0, 0);
  if (leaf != TrapezoidMap::none) add_filled(st.overlay, trapezoid_polygon(*in->map, leaf, in->back));
  tr::add_point(st.overlay, q, fmt::format("q{}", k));
  const std::string where = answer_text(S, l, st);
  const std::string how =
      nodes ? fmt::format("the query descended {} nodes of the {} map's DAG", nodes, in->back ? "back" : "front")
            : fmt::format("no map holds it (on Omega, or a side whose edges cross Omega): the walk answered, in {} "
                          "steps",
                          walked);
  st.text = fmt::format("q{} = {} lies {}: {} (t2 locate: {}).", k, query_text(q), where, how, t2::to_string(l));
  st.entries = path;
  st.entries.push_back(t2::to_string(l));
  rec.add(std::move(st));
  tr::add_point(last.overlay, q, fmt::format("q{}", k));
  last.text += fmt::format("{}q{}: {}", k ? "; " : "The answers: ", k, answer_text(S, l, last));
  if (l.kind == Location::Kind::face) last.triangles.push_back(face_triangle(S, l.face));
  return l;
}

// The trapezoidal maps recorded: the map and the queries, each insertion (lecture), the maps
// built; each query's descent (debugging) and answer (lecture); all the answers.
void record_trapezoid(const Points& P, const std::string& name, tr::Recording& rec) {
  const auto S = animation_map(P, name);
  const std::vector<t2::Point> Q = animation_queries(P);
  const std::vector<tr::Tri> T = map_triangles(*S);
  tr::Step m = make_step(
      "map",
      fmt::format("The map: the Delaunay triangulation of the points ({} triangles). Each side whose edges stay on "
                  "it gets a trapezoidal map of its edges, inserted in a random order; it starts as one trapezoid, "
                  "the whole side. The queries: q0 to q3 uniform in the bounding box of the points, q4 = p{}, q5 = "
                  "the antipode of q0 (on the back) and q6 on Omega.",
                  T.size(), P.size() / 2),
      "triangles");
  m.triangles = T;
  for (std::size_t k = 0; k < Q.size(); ++k) tr::add_point(m.overlay, Q[k], fmt::format("q{}", k));
  rec.add(m);
  std::vector<Seen> maps;
  std::unique_ptr<const t2::TrapezoidLocator> L;
  record_build(P, *S, maps, L, rec);
  tr::Step built = make_step("built", "", "trapezoids");
  built.overlay = maps_overlay(maps, P, 0, 0);
  for (const auto side : {t2::TrapezoidLocator::front, t2::TrapezoidLocator::back}) {
    const TrapezoidMap* M = L->chart(side);
    const char* word = side == t2::TrapezoidLocator::front ? "front" : "back";
    if (!M) {
      built.text += fmt::format("The {} side has no map (an edge leaves it, or it has no point): the walk answers "
                                "there. ",
                                word);
      continue;
    }
    std::size_t live = 0;
    for (const auto& z : M->trapezoids()) live += z.node != TrapezoidMap::none;
    built.text += fmt::format("The {} map: {} segments, {} trapezoids (at most 3n + 1), a DAG of {} nodes and "
                              "depth {}. ",
                              word, M->segments(), live, M->nodes(), M->depth());
  }
  rec.add(std::move(built));
  tr::Step last = make_step("answer", "", "triangles");  // its triangles: those holding a query
  for (std::size_t k = 0; k < Q.size(); ++k) record_query(P, *S, *L, maps, Q[k], k, last, rec);
  last.text += ".";
  rec.add(std::move(last));
}

// The timed run: every query answered by the trapezoidal maps (built before the clock).
Timed trapezoid_run(BenchInput& in) {
  auto S = delaunay_map(in.points);
  auto L = std::make_shared<const t2::TrapezoidLocator>(*S);
  auto Q = std::make_shared<const std::vector<t2::Point>>(locate_queries(in.points, false));
  return [S, L, Q] {
    std::size_t inside = 0;
    for (const auto& q : *Q) inside += L->locate(q).kind != t2::Location::Kind::outside;
    return inside;
  };
}

T2_ALGORITHM({.name = "trapezoid",
              .problem = "locate",
              .summary = "t2::TrapezoidLocator: the trapezoidal map and its history DAG (randomized incremental) "
                         "on the Delaunay triangulation, queries in random order",
              .title = "point location by a trapezoidal map and its history DAG",
              .run = [](const Points& P) {
                std::shared_ptr<const t2::TrapezoidLocator> L;  // built at the first query
                return answers_scene(P, [L](const Subdivision& S, const t2::Point& q) mutable {
                  if (!L) L = std::make_shared<const t2::TrapezoidLocator>(S);
                  return L->locate(q);
                });
              },
              .record = record_trapezoid,
              .time = [](BenchInput& in) -> Timed { return trapezoid_run(in); },
              .peers = {"walk", "cgal"}});

T2_ALGORITHM({.name = "trapezoid-build",
              .problem = "locate-build",
              .summary = "walk-build, then t2::TrapezoidLocator's trapezoidal maps on the triangles",
              .title = "the trapezoidal map's preprocessing",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] {
                  const auto S = delaunay_map(P);
                  const t2::TrapezoidLocator L(*S);
                  return S->faces();
                };
              },
              .peers = {"walk-build", "cgal"}});

}  // namespace
}  // namespace t2cli::algorithms
