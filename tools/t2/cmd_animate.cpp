// t2 animate: records an algorithm's steps through its trace (t2/trace/*), then writes one
// self-contained HTML page that plays them back (tools/t2/animate/).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "animate/page.hpp"
#include "command.hpp"
#include "scene_argument.hpp"
#include "t2/hull.hpp"
#include "t2/io.hpp"
#include "t2/scene.hpp"
#include "t2/trace/delaunay_recorder.hpp"
#include "t2/trace/hull_recorder.hpp"
#include "t2/trace/recording.hpp"
#include "t2/triangulation/delaunay.hpp"

namespace t2cli {
namespace {

namespace tr = t2::trace;

// Every step is drawn twice (both models) into the page: beyond this many points the page
// grows past what a browser steps through comfortably, and the picture is unreadable anyway.
constexpr std::size_t kMaxPoints = 200;

struct Options {
  std::string algo;
  std::string file;
  std::string out;
};

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
      tr::HullRecorder r(tr::HullAlgo::merge, P, t2::lex_chart(), rec);
      h = t2::merge_hull(std::span<const t2::Point>(P), r);
    } else {
      const t2::Chart chart = t2::chart_for(std::span<const t2::Point>(P), h);  // throws when no hull
      if (h.size() != 1) {
        std::vector<std::size_t> idx(P.size());
        std::iota(idx.begin(), idx.end(), std::size_t{0});
        tr::HullRecorder r(algo == "jarvis" ? tr::HullAlgo::jarvis : tr::HullAlgo::graham, P, chart, rec);
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

// Runs the Delaunay insertion (or the plain incremental triangulation) with a recorder.
void triangulate(bool plain, const std::vector<t2::Point>& P, const std::string& name, tr::Recording& rec) {
  tr::DelaunayRecorder k(P, rec, plain);
  if (!k.recording())
    throw t2::BadInput(fmt::format("{}: t2 animate {} takes front points only (w > 0): the triangulation of T2 input "
                                   "(delaunay_t2.hpp: each side apart, then merged along Omega) is not animated",
                                   name, plain ? "triangulate" : "delaunay"));
  t2::Triangulation t;
  try {
    t = t2::delaunay_with(std::span<const t2::Point>(P), k);
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", name, e.what()));
  }
  tr::Step s = step("answer", "", "triangles");
  for (const auto& f : t.finite_triangles()) s.triangles.push_back({f[0], f[1], f[2]});  // input indices
  std::sort(s.triangles.begin(), s.triangles.end());
  const std::string what = plain ? "incremental triangulation" : "Delaunay triangulation";
  s.text = t.dimension() < 2 ? "Fewer than three points off one line: no triangle."
                             : fmt::format("The {}: {} triangles, {} hull edges, {} duplicate points merged.", what,
                                           s.triangles.size(), t.hull_edges().size(), t.duplicates().size());
  rec.add(std::move(s));
}

int animate(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  std::vector<t2::Point> P;
  for (const auto& p : scene.points) P.push_back(p.point);
  if (P.size() > kMaxPoints)
    throw t2::BadInput(fmt::format("{}: {} points: t2 animate draws every step, so at most {} points", scene.name,
                                   P.size(), kMaxPoints));
  static const char* const names[][2] = {{"jarvis", "Jarvis's march"},
                                        {"graham", "Graham's scan"},
                                        {"merge-hull", "the hemisphere-merge hull"},
                                        {"triangulate", "incremental triangulation"},
                                        {"delaunay", "randomized incremental Delaunay"}};
  std::string title;
  for (const auto& n : names)
    if (o.algo == n[0]) title = fmt::format("{} of {} ({} points)", n[1], scene.name, P.size());
  tr::Recording rec;
  const std::string range = P.empty() ? "no point" : fmt::format("{} points, p0 to p{}", P.size(), P.size() - 1);
  rec.add(step("input", fmt::format("The input: {}. Next: {}.", range, title.substr(0, title.find(" of "))), ""));
  if (o.algo == "triangulate" || o.algo == "delaunay")
    triangulate(o.algo == "triangulate", P, scene.name, rec);
  else
    hull(o.algo, P, scene.name, rec);
  t2::write_file_atomically(o.out, animate::page(title, P, rec.steps()));
  fmt::print("{}: {} steps ({} at the lecture level)\n", o.out, rec.size(), rec.at(tr::Depth::lecture).size());
  return kOk;
}

Action setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Runs the algorithm ALGO on the points of the scene file FILE (- for standard input),\n"
      "recording every step, and writes OUT, one self-contained HTML page (no network) that\n"
      "plays the steps back: the planar and the spherical model of each step, the data\n"
      "structure beside them (Graham's stack, the hull so far, the triangles of a flip), the\n"
      "explanation, and controls: previous/next (arrow keys), play/pause (space), speed, a\n"
      "timeline, and the level of detail (lecture: the steps that change the structure;\n"
      "debugging: every test as well). The page starts paused at the first step; its URL\n"
      "fragment #step=N (or last) and &level=debugging open it elsewhere.\n"
      "ALGO: jarvis, graham, merge-hull (hulls of points of T2), triangulate (incremental\n"
      "insertion, flips only where the new point sees hull edges; not the sweep of\n"
      "t2 triangulate), delaunay (the same with Lawson flips: the library's randomized\n"
      "incremental Delaunay). The triangulations are animated for front points only.");
  app.add_option("ALGO", o->algo, "jarvis, graham, merge-hull, triangulate or delaunay")
      ->required()
      ->check(CLI::IsMember({"jarvis", "graham", "merge-hull", "triangulate", "delaunay"}));
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("-o,--output", o->out, "the HTML page to write (atomically)")->required()->type_name("OUT");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong; more than 200\n"
      "points; a triangulation of points off the front side); 3 undefined: the points have\n"
      "no hull (no open hemisphere holds them).");
  return [o] { return animate(*o); };
}

}  // namespace

T2_COMMAND({"animate", "step-through animation of an algorithm, as one HTML page", setup});

}  // namespace t2cli
