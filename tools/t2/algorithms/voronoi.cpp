// The front half of the Voronoi diagram by Fortune's sweep (chapter 11, t2/voronoi/fortune.hpp):
// timed by `t2 bench` on points of the plane and animated (trace/fortune_recorder.hpp); the
// diagram of T² (t2/voronoi/voronoi.hpp), its problem "voronoi", is in voronoi_dual.cpp. Fortune's answer is the front half only (its vertices are the dual's front vertices),
// so it is a problem of its own, "voronoi-front": the sizes `t2 bench` compares would differ.
// Boost.Polygon's sweep is its peer `boost` (algorithms/peers.cpp), on the worker's doubles
// rounded to integers; bench/bench_voronoi.cpp times it and CGAL's Delaunay dual on the same
// integer points.
#include <fmt/format.h>

#include "algorithms/registry.hpp"
#include "t2/kernel/error.hpp"
#include "t2/trace/fortune_recorder.hpp"
#include "t2/trace/overlay.hpp"
#include "t2/voronoi/fortune.hpp"

namespace t2cli::algorithms {
namespace {

namespace tr = t2::trace;

// The bisector of the front sites a and b: the line through their midpoint and the point of Ω
// perpendicular to a b (exact: GMP, then the nearest doubles).
void add_bisector(t2::Scene& s, const t2::Point& a, const t2::Point& b) {
  const t2::ExactPoint p = t2::to_exact(a), q = t2::to_exact(b);
  const t2::ExactPoint m(t2::Integer(2 * p.w() * q.w()), t2::Integer(p.x() * q.w() + q.x() * p.w()),
                         t2::Integer(p.y() * q.w() + q.y() * p.w()));
  const t2::ExactPoint o(t2::Integer(0), t2::Integer(p.y() * q.w() - q.y() * p.w()),
                         t2::Integer(q.x() * p.w() - p.x() * q.w()));
  tr::add_line(s, t2::to_double(m), t2::to_double(o));
}

// Fortune's diagram as a scene: its edges, its rays to their point of Ω, its bisector lines and
// its vertices, each in the order of `fd`.
t2::Scene fortune_scene(const Points& P, const t2::FortuneDiagram& fd) {
  t2::Scene s;
  for (const auto& e : fd.edges) tr::add_segment(s, t2::to_double(fd.vertex(e.a)), t2::to_double(fd.vertex(e.b)));
  for (const auto& ray : fd.rays) tr::add_segment(s, t2::to_double(fd.vertex(ray.a)), t2::to_double(ray.end));
  for (const auto& [a, b] : fd.lines) add_bisector(s, P[a], P[b]);
  for (std::size_t v = 0; v < fd.size(); ++v) tr::add_point(s, t2::to_double(fd.vertex(v)));
  return s;
}

// Fortune's sweep with its recorder (trace/fortune_recorder.hpp); the last step is the diagram
// t2::fortune returns: its vertices, its edges, its rays to Ω and its bisector lines.
void record_fortune(const Points& P, const std::string& name, tr::Recording& rec) {
  tr::FortuneRecorder r(P, rec);
  t2::FortuneDiagram fd;
  try {
    fd = t2::fortune(std::span<const t2::Point>(P), std::ref(r));
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", name, e.what()));  // as t2 voronoi --algorithm fortune: exit 3
  }
  r.finish();
  tr::Step s;
  s.kind = "answer";
  s.structure = "Voronoi diagram";
  s.text = fmt::format("The Voronoi diagram (its front half): {} vertices, {} edges, {} rays to Omega, {} bisector "
                       "lines{}.",
                       fd.size(), fd.edges.size(), fd.rays.size(), fd.lines.size(),
                       fd.duplicates.empty() ? "" : fmt::format("; {} duplicate sites merged", fd.duplicates.size()));
  s.overlay = fortune_scene(P, fd);
  rec.add(std::move(s));
}

T2_PROBLEM({"voronoi-front", "front vertices", Input::plane});

T2_ALGORITHM({.name = "fortune",  // what `t2 voronoi --algorithm fortune` runs
              .problem = "voronoi-front",
              .summary = "t2::fortune: Fortune's sweep, the front half of the Voronoi diagram, exact (seed 001; animated on "
                         "front points)",
              .title = "Fortune's sweep",
              .run = [](const Points& P) { return fortune_scene(P, t2::fortune(std::span<const t2::Point>(P))); },
              .record = record_fortune,
              .time = [](BenchInput& in) -> Timed {
                return [&P = in.points] { return t2::fortune(std::span<const t2::Point>(P)).size(); };
              },
              .peers = {"boost"}});

}  // namespace
}  // namespace t2cli::algorithms
