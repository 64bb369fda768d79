// Point location (chapter 14, t2/location/), timed by `t2 bench locate`: the walk of seed
// 000's Algorithm 15 on the Delaunay triangulation of the input points, each query starting at
// the last query found inside a face (before there is one, at a vertex of the last answer's
// face). The triangulation and the queries are made before the clock starts (the worker's peers
// get the same queries: locate_queries). `locate-build` times what each method builds from the
// points: here the Delaunay triangulation and the half-edges (walk-build); CGAL's is its
// triangulation. The trapezoidal map's entries are in location_trapezoid.cpp.
#include "algorithms/location.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <random>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "t2/kernel/error.hpp"
#include "t2/location/walk.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/trace/recording.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/spatial_sort.hpp"

namespace t2cli::algorithms {

std::vector<t2::Point> locate_queries(std::span<const t2::Point> points, bool sorted) {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  if (!points.empty()) {
    x0 = x1 = points[0].x() / points[0].w();
    y0 = y1 = points[0].y() / points[0].w();
  }
  for (const auto& p : points) {
    x0 = std::min(x0, p.x() / p.w()), x1 = std::max(x1, p.x() / p.w());
    y0 = std::min(y0, p.y() / p.w()), y1 = std::max(y1, p.y() / p.w());
  }
  std::mt19937_64 rng(0x1414);
  std::uniform_real_distribution<double> X(x0, x1), Y(y0, y1);
  std::vector<t2::Point> Q;
  Q.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double x = X(rng), y = Y(rng);  // in this order (a call's arguments have none)
    Q.push_back(t2::Point::cartesian(x, y));
  }
  if (sorted) {
    const auto order = t2::spatial_order(Q);
    std::vector<t2::Point> S;
    S.reserve(Q.size());
    for (const auto i : order) S.push_back(Q[i]);
    Q.swap(S);
  }
  return Q;
}

std::vector<t2::Point> animation_queries(std::span<const t2::Point> points) {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool any = false;
  for (const auto& p : points) {
    if (p.w() == 0) continue;
    const double x = p.x() / p.w(), y = p.y() / p.w();
    if (!any) x0 = x1 = x, y0 = y1 = y, any = true;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  std::mt19937_64 rng(0x1427);
  std::uniform_real_distribution<double> X(x0, x1), Y(y0, y1);
  std::vector<t2::Point> Q;
  for (int k = 0; k < 4; ++k) {
    const double x = X(rng);
    Q.push_back(t2::Point::cartesian(x, Y(rng)));
  }
  if (!points.empty()) Q.push_back(points[points.size() / 2]);
  Q.push_back(t2::antipode(Q[0]));
  Q.push_back(t2::Point(0, 1, 0));
  return Q;
}

namespace tr = t2::trace;
using t2::Location;
using t2::Subdivision;

std::shared_ptr<const t2::Subdivision> delaunay_map(const std::vector<t2::Point>& points) {
  const t2::Triangulation T = t2::delaunay(points);
  std::vector<std::vector<t2::Subdivision::Index>> F;
  for (const auto& t : T.finite_triangles()) F.push_back({t[0], t[1], t[2]});
  return std::make_shared<const t2::Subdivision>(points, F);
}


std::shared_ptr<const Subdivision> animation_map(const std::vector<t2::Point>& P, const std::string& name) {
  try {
    auto S = delaunay_map(P);
    if (S->faces() == 0)
      throw t2::Undefined(fmt::format("{}: the Delaunay triangulation of the points has no triangle (fewer than three "
                                      "points off one line): no map to locate in",
                                      name));
    return S;
  } catch (const t2::Undefined& e) {
    if (std::string(e.what()).rfind(name + ":", 0) == 0) throw;
    throw t2::Undefined(fmt::format("{}: {}", name, e.what()));
  } catch (const t2::BadInput& e) {
    throw t2::BadInput(fmt::format("{}: {}", name, e.what()));
  }
}

std::vector<tr::Tri> map_triangles(const Subdivision& S) {
  std::vector<tr::Tri> out;
  for (Subdivision::Index f = 0; f < S.faces(); ++f)
    out.push_back({S.org(S.first(f)), S.org(S.first(f) + 1), S.org(S.first(f) + 2)});
  return out;
}

tr::Tri face_triangle(const Subdivision& S, Subdivision::Index f) {
  return {S.org(S.first(f)), S.org(S.first(f) + 1), S.org(S.first(f) + 2)};
}

std::string tri_text(const tr::Tri& t) { return fmt::format("p{} p{} p{}", t[0], t[1], t[2]); }

std::string query_text(const t2::Point& q) {
  if (q.w() == 0) return fmt::format("[0, {}, {}] on Omega", q.x(), q.y());
  return fmt::format("({:.4g}, {:.4g}){}", q.x() / q.w(), q.y() / q.w(), q.w() < 0 ? " on the back" : "");
}

std::string answer_text(const Subdivision& S, const Location& l, tr::Step& s) {
  if (l.kind == Location::Kind::outside) return "outside the map";
  const tr::Tri t = face_triangle(S, l.face);
  if (l.kind == Location::Kind::face) {
    s.touched.push_back(t);
    s.edges.insert(s.edges.end(), {{t[0], t[1]}, {t[1], t[2]}, {t[2], t[0]}});
    s.points.insert(s.points.end(), t.begin(), t.end());
    return fmt::format("inside triangle {}", tri_text(t));
  }
  if (l.kind == Location::Kind::edge) {
    s.edges.push_back({t[l.k], t[(l.k + 1) % 3]});
    s.points.insert(s.points.end(), {t[l.k], t[(l.k + 1) % 3]});
    return fmt::format("on the edge p{} p{}", t[l.k], t[(l.k + 1) % 3]);
  }
  s.points.push_back(t[l.k]);
  return fmt::format("at the vertex p{}", t[l.k]);
}

namespace {

T2_PROBLEM({"locate", "queries in a face", Input::plane});
T2_PROBLEM({"locate-build", "faces", Input::plane});

// The timed run: every query walked, from the last query inside a face.
Timed walk_run(BenchInput& in, bool sorted) {
  auto S = delaunay_map(in.points);
  auto Q = std::make_shared<const std::vector<t2::Point>>(locate_queries(in.points, sorted));
  return [S, Q] {
    std::size_t inside = 0;
    t2::Subdivision::Index from = S->org(0);
    const t2::Point* last = nullptr;  // the last query strictly inside a face, and that face
    t2::Subdivision::Index face = 0;
    for (const auto& q : *Q) {
      const t2::Location l = last ? t2::walk(*S, q, *last, face) : t2::walk(*S, q, from);
      if (l.kind == t2::Location::Kind::outside) continue;
      ++inside;
      from = S->org(S->first(l.face) + l.k);
      if (l.kind == t2::Location::Kind::face) last = &q, face = l.face;
    }
    return inside;
  };
}


// The overlay of query k: the query point and the walk's segment from vertex v (when defined).
t2::Scene query_overlay(const Points& P, const t2::Point& q, std::size_t k, Subdivision::Index v) {
  t2::Scene o;
  if (q != P[v] && q != t2::antipode(P[v])) tr::add_segment(o, P[v], q);
  tr::add_point(o, q, fmt::format("q{}", k));
  return o;
}

}  // namespace

t2::Scene answers_scene(const Points& P, const Locate& locate) {
  const auto S = animation_map(P, "points");
  const std::vector<t2::Point> Q = animation_queries(P);
  t2::Scene out;
  for (std::size_t k = 0; k < Q.size(); ++k) {
    const Location l = locate(*S, Q[k]);
    if (l.kind == Location::Kind::face) {
      t2::ScenePolygon g;
      for (const std::size_t i : face_triangle(*S, l.face)) g.vertices.push_back(tr::overlay_point(P[i]));
      out.polygons.push_back(std::move(g));
    }
    tr::add_point(out, Q[k], fmt::format("q{}", k));
  }
  return out;
}

namespace {

// The walk (Algorithm 15) recorded: the map and the queries (lecture), each region entered and
// each vertex stood at (debugging), each query's path and answer (lecture), all the answers.
void record_walk(const Points& P, const std::string& name, tr::Recording& rec) {
  const auto S = animation_map(P, name);
  const std::vector<t2::Point> Q = animation_queries(P);
  const Subdivision::Index start = S->org(0);
  const std::vector<tr::Tri> T = map_triangles(*S);
  tr::Step m = make_step(
      "map",
      fmt::format("The map: the Delaunay triangulation of the points ({} triangles). The queries: q0 to q3 drawn "
                  "uniformly in the bounding box of the points (a fixed seed), q4 = p{}, q5 = the antipode of q0 (on "
                  "the back) and q6 on Omega. Each walk starts at the vertex p{}.",
                  T.size(), P.size() / 2, start),
      "triangles");
  m.triangles = T;
  for (std::size_t k = 0; k < Q.size(); ++k) tr::add_point(m.overlay, Q[k], fmt::format("q{}", k));
  rec.add(m);
  tr::Step last = make_step("answer", "", "triangles");  // its triangles: those holding a query
  for (std::size_t k = 0; k < Q.size(); ++k) {
    const t2::Point& q = Q[k];
    std::vector<tr::Tri> path;
    std::size_t at = start;
    const auto hook = [&](const tr::Report& r) {
      tr::Step s = make_step("", "", "triangles");
      s.depth = tr::Depth::debugging;
      s.triangles = T;
      s.overlay = query_overlay(P, q, k, start);
      if (r.event == tr::Event::reach_vertex) {
        at = r.at[0];
        s.kind = "vertex";
        s.text = fmt::format("q{}: the walk stands at the vertex p{} of its segment.", k, at);
        s.points = {at};
      } else if (r.event == tr::Event::enter_region) {
        const bool out = r.faces[0] == Subdivision::outside;
        const std::string into = out ? std::string("the outside of the map")
                                     : "the triangle " + tri_text(face_triangle(*S, r.faces[0]));
        if (!out) path.push_back(face_triangle(*S, r.faces[0]));
        if (r.at[0] != tr::Report::none) {
          s.kind = "cross";
          s.text = fmt::format("q{}: the segment crosses the edge p{} p{} into {}.", k, r.at[0], r.at[1], into);
          s.edges = {{r.at[0], r.at[1]}};
        } else {
          s.kind = "leave";
          s.text = fmt::format("q{}: from the vertex p{}, the segment runs into {}.", k, r.at[2], into);
          s.points = {r.at[2]};
        }
        s.touched = path;  // the path so far, the triangle entered last
      } else {
        return;
      }
      rec.add(std::move(s));
    };
    const Location l = t2::walk(*S, q, start, hook);
    tr::Step s = make_step("located", "", "triangles");
    s.triangles = T;
    s.overlay = query_overlay(P, q, k, start);
    const std::string where = answer_text(*S, l, s);
    s.text = fmt::format("q{} = {} lies {}: the walk from p{} entered {} triangles (t2 locate: {}).", k, query_text(q),
                         where, start, path.size(), t2::to_string(l));
    s.touched.insert(s.touched.end(), path.begin(), path.end());
    rec.add(std::move(s));
    tr::add_point(last.overlay, q, fmt::format("q{}", k));
    last.text += fmt::format("{}q{}: {}", k ? "; " : "The answers: ", k, answer_text(*S, l, last));
    if (l.kind == Location::Kind::face) last.triangles.push_back(face_triangle(*S, l.face));
  }
  last.text += ".";
  rec.add(std::move(last));
}

T2_ALGORITHM({.name = "walk",
              .problem = "locate",
              .summary = "t2::walk: seed 000's Algorithm 15 on the Delaunay triangulation, queries in random order",
              .title = "point location by walking (Algorithm 15) in the points' Delaunay triangulation",
              .run = [](const Points& P) {
                return answers_scene(P, [](const Subdivision& S, const t2::Point& q) { return t2::walk(S, q, S.org(0)); });
              },
              .record = record_walk,
              .time = [](BenchInput& in) -> Timed { return walk_run(in, false); },
              .peers = {"cgal", "walk-sorted", "cgal-sorted"}});

T2_ALGORITHM({.name = "walk-build",
              .problem = "locate-build",
              .summary = "what the walk needs: t2::delaunay of the points and the t2::Subdivision of its triangles",
              .title = "the walk's preprocessing",
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return delaunay_map(P)->faces(); };
              }});

T2_ALGORITHM({.name = "walk-sorted",
              .problem = "locate",
              .summary = "t2::walk with the queries in spatial order (each starts near the last answer)",
              .title = "point location by walking, spatially sorted queries",
              .time = [](BenchInput& in) -> Timed { return walk_run(in, true); }});

}  // namespace
}  // namespace t2cli::algorithms
