// What the registry's entries share (answer.hpp).
#include "algorithms/answer.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "t2/kernel/error.hpp"
#include "t2/trace/recording.hpp"

namespace t2cli::algorithms {

t2::Scene polygons_scene(const Points& P, const std::vector<std::vector<std::size_t>>& polygons) {
  t2::Scene s;
  for (const auto& poly : polygons) {
    t2::ScenePolygon g;
    for (std::size_t i : poly) g.vertices.push_back(t2::ScenePoint{P[i], 0, {}, {}});
    s.polygons.push_back(std::move(g));
  }
  return s;
}

t2::Scene triangles_scene(const Points& P, const t2::Triangulation& t) {
  std::vector<std::vector<std::size_t>> tris;
  for (const auto& f : t.finite_triangles()) tris.push_back({f[0], f[1], f[2]});
  std::sort(tris.begin(), tris.end());
  return polygons_scene(P, tris);
}

std::size_t finite_count(const t2::Triangulation& t) {
  std::size_t finite = 0;
  for (t2::Triangulation::Index k = 0; k < t.size(); ++k) finite += !t.is_infinite(k);
  return finite;
}

t2::trace::Step make_step(const char* kind, std::string text, const char* structure) {
  t2::trace::Step s;
  s.kind = kind;
  s.text = std::move(text);
  s.structure = structure;
  return s;
}

std::string point_list(const std::vector<std::size_t>& v) {
  std::string s;
  for (std::size_t i : v) s += (s.empty() ? "p" : ", p") + std::to_string(i);
  return s;
}

void record_hull_answer(const std::vector<std::size_t>& h, t2::trace::Recording& rec) {
  t2::trace::Step s = make_step(
      "answer",
      h.empty() ? "No point: the hull is empty."
                : fmt::format("The hull: {} ({} vertices, counter-clockwise).", point_list(h), h.size()),
      "hull");
  s.chain = h;
  s.closed = true;
  rec.add(std::move(s));
}

void record_triangles_answer(const t2::Triangulation& t, const std::string& what, t2::trace::Recording& rec) {
  t2::trace::Step s = make_step("answer", "", "triangles");
  for (const auto& f : t.finite_triangles()) s.triangles.push_back({f[0], f[1], f[2]});  // input indices
  std::sort(s.triangles.begin(), s.triangles.end());
  s.text = t.dimension() < 2 ? "Fewer than three points off one line: no triangle."
                             : fmt::format("The {}: {} triangles, {} hull edges, {} duplicate points merged.", what,
                                           s.triangles.size(), t.hull_edges().size(), t.duplicates().size());
  rec.add(std::move(s));
}

void require_front(const Points& P, const std::string& name, const std::string& algo) {
  if (!std::all_of(P.begin(), P.end(), [](const t2::Point& p) { return p.w() > 0; }))
    throw t2::BadInput(fmt::format("{}: t2 animate {} takes front points only (w > 0): the triangulation of T2 input "
                                   "(delaunay_t2.hpp: each side apart, then merged along Omega) is not animated",
                                   name, algo));
}

}  // namespace t2cli::algorithms
