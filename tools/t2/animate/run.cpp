// What `t2 animate` does (run.hpp): each algorithm run with its recorder, the steps written as
// the page of page.hpp.
#include "animate/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "animate/page.hpp"
#include "t2/kernel/error.hpp"
#include "t2/hull.hpp"
#include "t2/kernel/io.hpp"
#include "t2/trace/delaunay_recorder.hpp"
#include "t2/trace/hull_recorder.hpp"
#include "t2/trace/recording.hpp"
#include "t2/trace/sweep_recorder.hpp"
#include "t2/trace/triangulate_t2_recorder.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/insert_t2.hpp"
#include "t2/triangulation/triangulate.hpp"

namespace t2cli::animate {
namespace {

namespace tr = t2::trace;

// Every step is drawn twice (both models) into the page: beyond this many points the page
// grows past what a browser steps through comfortably, and the picture is unreadable anyway.
constexpr std::size_t kMaxPoints = 200;

std::string list(const std::vector<std::size_t>& v) {
  std::string s;
  for (std::size_t i : v) s += (s.empty() ? "p" : ", p") + std::to_string(i);
  return s;
}

tr::Step step(const char* kind, std::string text, const char* structure) {
  tr::Step s;
  s.kind = kind;
  s.text = std::move(text);
  s.structure = structure;
  return s;
}

// Runs a hull algorithm with a recorder; the last step is the algorithm's answer.
void hull(const std::string& algo, const std::vector<t2::Point>& P, const std::string& name, tr::Recording& rec) {
  std::vector<std::size_t> h;
  try {
    if (algo == "merge-hull") {
      tr::HullRecorder r(tr::HullAlgo::merge, P, rec);
      h = t2::merge_hull(std::span<const t2::Point>(P), r);
    } else {
      const t2::Chart chart = t2::chart_for(std::span<const t2::Point>(P), h);  // throws when no hull
      if (h.size() != 1) {
        std::vector<std::size_t> idx(P.size());
        std::iota(idx.begin(), idx.end(), std::size_t{0});
        tr::HullRecorder r(algo == "jarvis" ? tr::HullAlgo::jarvis : tr::HullAlgo::graham, P, rec);
        h = algo == "jarvis" ? t2::jarvis(std::span<const t2::Point>(P), idx, chart, r)
                             : t2::graham(std::span<const t2::Point>(P), idx, chart, r);
      }
    }
  } catch (const t2::NoHull& e) {
    throw t2::Undefined(fmt::format("{}: no convex hull: {}", name, e.what()));
  }
  tr::Step s = step("answer",
                    h.empty() ? "No point: the hull is empty."
                              : fmt::format("The hull: {} ({} vertices, counter-clockwise).", list(h), h.size()),
                    "hull");
  s.chain = h;
  s.closed = true;
  rec.add(std::move(s));
}

// The triangulations are animated for front points only.
void front_only(const std::vector<t2::Point>& P, const std::string& name, const std::string& algo) {
  if (!std::all_of(P.begin(), P.end(), [](const t2::Point& p) { return p.w() > 0; }))
    throw t2::BadInput(fmt::format("{}: t2 animate {} takes front points only (w > 0): the triangulation of T2 input "
                                   "(delaunay_t2.hpp: each side apart, then merged along Omega) is not animated",
                                   name, algo));
}

// The last step of a triangulation: the algorithm's answer `t` (`what` it is).
void answer(const t2::Triangulation& t, const std::string& what, tr::Recording& rec) {
  tr::Step s = step("answer", "", "triangles");
  for (const auto& f : t.finite_triangles()) s.triangles.push_back({f[0], f[1], f[2]});  // input indices
  std::sort(s.triangles.begin(), s.triangles.end());
  s.text = t.dimension() < 2 ? "Fewer than three points off one line: no triangle."
                             : fmt::format("The {}: {} triangles, {} hull edges, {} duplicate points merged.", what,
                                           s.triangles.size(), t.hull_edges().size(), t.duplicates().size());
  rec.add(std::move(s));
}

// Runs what `t2 triangulate` runs, with a recorder: the sweep for front points, Algorithm 9 on
// T² for any other input.
void triangulate(const std::vector<t2::Point>& P, const std::string& name, tr::Recording& rec) {
  const bool front = std::all_of(P.begin(), P.end(), [](const t2::Point& p) { return p.w() > 0; });
  t2::Triangulation t;
  try {
    if (front) {
      tr::SweepRecorder r(rec);
      t = t2::triangulate(std::span<const t2::Point>(P), r);
    } else {
      tr::TriangulateT2Recorder r(rec);
      t = t2::triangulate(std::span<const t2::Point>(P), r);
    }
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", name, e.what()));
  }
  answer(t, front ? "sweep triangulation (t2 triangulate)" : "triangulation of T2 (Algorithm 9, t2 triangulate)",
         rec);
}

// Runs the Delaunay insertion with a recorder (front points only).
void delaunay(const std::vector<t2::Point>& P, const std::string& name, tr::Recording& rec) {
  front_only(P, name, "delaunay");
  tr::DelaunayRecorder k(P, rec);
  t2::Triangulation t;
  try {
    t = t2::delaunay_with(std::span<const t2::Point>(P), t2::DelaunayTraits{}, k);
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", name, e.what()));
  }
  answer(t, "Delaunay triangulation", rec);
}

// Runs the sweep of t2 triangulate (chapter 09) with a recorder.
void sweep(const std::vector<t2::Point>& P, const std::string& name, tr::Recording& rec) {
  front_only(P, name, "sweep");
  tr::SweepRecorder r(rec);
  const t2::Triangulation t = t2::triangulate(std::span<const t2::Point>(P), r);
  answer(t, "sweep triangulation (t2 triangulate)", rec);
}

}  // namespace

const std::vector<Algorithm>& algorithms() {
  static const std::vector<Algorithm> all = {{"jarvis", "Jarvis's march"},
                                             {"graham", "Graham's scan"},
                                             {"merge-hull", "the hemisphere-merge hull"},
                                             {"triangulate", "the triangulation of t2 triangulate"},
                                             {"sweep", "the sweep triangulation"},
                                             {"delaunay", "randomized incremental Delaunay"}};
  return all;
}

std::string write_animation(const std::string& algo, const t2::Scene& scene, const std::filesystem::path& out) {
  std::vector<t2::Point> P;
  for (const auto& p : scene.points) P.push_back(p.point);
  if (P.size() > kMaxPoints)
    throw t2::BadInput(fmt::format("{}: {} points: t2 animate draws every step, so at most {} points", scene.name,
                                   P.size(), kMaxPoints));
  std::string title;
  for (const auto& a : algorithms())
    if (algo == a.name) title = fmt::format("{} of {} ({} points)", a.title, scene.name, P.size());
  if (title.empty()) throw std::invalid_argument(fmt::format("'{}': not an algorithm of t2 animate", algo));
  tr::Recording rec;
  const std::string range = P.empty() ? "no point" : fmt::format("{} points, p0 to p{}", P.size(), P.size() - 1);
  rec.add(step("input", fmt::format("The input: {}. Next: {}.", range, title.substr(0, title.find(" of "))), ""));
  if (algo == "sweep")
    sweep(P, scene.name, rec);
  else if (algo == "triangulate")
    triangulate(P, scene.name, rec);
  else if (algo == "delaunay")
    delaunay(P, scene.name, rec);
  else
    hull(algo, P, scene.name, rec);
  t2::write_file_atomically(out, page(title, P, rec.steps()));
  return fmt::format("{}: {} steps ({} at the lecture level)", out.string(), rec.size(),
                     rec.at(tr::Depth::lecture).size());
}

}  // namespace t2cli::animate
