// The output of `t2 triangulate` and `t2 delaunay` (see triangles_command.hpp).
#include "triangles_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/draw.hpp"
#include "t2/error.hpp"
#include "t2/io.hpp"
#include "t2/scene.hpp"

namespace t2cli {
namespace {

namespace dr = t2::draw;
using Index = t2::Triangulation::Index;

// The finite triangles sorted, then with --infinite the infinite ones, each rotated so that v∞
// comes last (`b a inf` for the hull edge a → b), sorted.
std::string listing(const t2::Triangulation& tr, bool infinite) {
  auto tris = tr.finite_triangles();
  std::sort(tris.begin(), tris.end());
  std::string out;
  for (const auto& t : tris) out += fmt::format("{} {} {}\n", t[0], t[1], t[2]);
  if (!infinite || tr.dimension() < 2) return out;
  std::vector<std::pair<Index, Index>> inf;
  for (Index t = 0; t < tr.size(); ++t) {
    const int k = tr.slot(t, t2::Triangulation::infinite);
    if (k >= 0) inf.emplace_back(tr.vertex(t, (k + 1) % 3), tr.vertex(t, (k + 2) % 3));
  }
  std::sort(inf.begin(), inf.end());
  for (auto [a, b] : inf) out += fmt::format("{} {} inf\n", a, b);
  return out;
}

// The triangles in light blue with their edges, the hull in green, the points labelled pK.
dr::Figure picture(const std::vector<t2::Point>& P, const t2::Triangulation& tr) {
  dr::Figure f;
  const dr::Style tri = dr::Style().color("#1f77b4").width(1).fill("#1f77b4").fill_opacity(0.12).layer(0);
  for (const auto& t : tr.finite_triangles()) {
    const t2::Point &a = P[t[0]], &b = P[t[1]], &c = P[t[2]];
    if (!(a == t2::antipode(b)) && !(b == t2::antipode(c)) && !(c == t2::antipode(a))) {
      f.add(std::vector<t2::Point>{a, b, c}, tri);
      continue;
    }
    // A flat face of T² input (two antipodal vertices): its segment between the antipodes is
    // not defined by its endpoints, so only its other edges are drawn.
    for (int k = 0; k < 3; ++k)
      if (!(P[t[k]] == t2::antipode(P[t[(k + 1) % 3]]))) f.segment(P[t[k]], P[t[(k + 1) % 3]], tri);
  }
  for (auto [a, b] : tr.hull_edges()) f.segment(P[a], P[b], dr::Style().color("#2ca02c").width(2).layer(1));
  const bool labels = P.size() <= 60;
  for (std::size_t k = 0; k < P.size(); ++k) {
    dr::Style s = dr::Style().color("#000000").layer(2);
    if (labels) s.label(fmt::format("p{}", k)); else s.size(1.5);
    f.add(P[k], s);
  }
  return f;
}

int run(const TrianglesOptions& o, const std::string& command, const TriangulationBuilder& build) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  t2::Triangulation tr;
  try {
    tr = build(P, o);
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", scene.name, e.what()));
  }
  for (auto [dropped, kept] : tr.duplicates())
    fmt::print(stderr, "t2 {}: {}:{}: p{} equals p{} (line {}): merged\n", command, scene.name,
               scene.points[dropped].line, dropped, kept, scene.points[kept].line);
  if (tr.dimension() < 2 && P.size() >= 3)
    fmt::print(stderr, "t2 {}: {}: no triangle: the points are collinear\n", command, scene.name);
  if (!o.drawing.svg.empty()) write_drawing(o.drawing, picture(P, tr), fit_plane(P));
  fmt::print("{}", listing(tr, o.infinite));
  return kOk;
}

}  // namespace

Action triangles_setup(CLI::App& app, std::shared_ptr<TrianglesOptions> o, const std::string& command,
                       TriangulationBuilder build) {
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_flag("--infinite", o->infinite,
               "also print the infinite triangles, one per hull edge a -> b, as 'b a inf'");
  add_drawing_options(app, o->drawing, "the points and the triangles");
  app.footer(
      "Output: one triangle per line, 'i j k', the 0-based indices of the scene's points (bare\n"
      "and labelled, in file order; blocks are ignored), counter-clockwise, smallest index\n"
      "first, the lines sorted. Equal points are merged (stderr names them) and the smallest\n"
      "index is the vertex; collinear points give no triangle.\n"
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 undefined\n"
      "in T2 or not implemented: t2 triangulate and --algorithm flip take front points only,\n"
      "t2 delaunay takes points on both sides, or all on Omega, but not points on Omega\n"
      "together with others.");
  return [o, command, build] { return run(*o, command, build); };
}

}  // namespace t2cli
