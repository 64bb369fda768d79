// The output of `t2 triangulate` and `t2 delaunay` (see triangles_command.hpp).
#include "triangles_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/draw.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/scene.hpp"

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

// The triangulation as a scene: the triangles in light blue with their edges, the hull edges in
// green, and (up to 60 points) the labels pK of the points, without markers: the input has them.
t2::Scene answer(const std::vector<t2::Point>& P, const t2::Triangulation& tr) {
  t2::Scene s;
  const t2::SceneStyle tri = style_of("color=blue width=1 fill=blue opacity=0.12 layer=0");
  const t2::SceneStyle edge = style_of("color=blue width=1 layer=0");
  for (const auto& t : tr.finite_triangles()) {
    const t2::Point &a = P[t[0]], &b = P[t[1]], &c = P[t[2]];
    if (!(a == t2::antipode(b)) && !(b == t2::antipode(c)) && !(c == t2::antipode(a))) {
      s.polygons.push_back(t2::ScenePolygon{{scene_point(a), scene_point(b), scene_point(c)}, 0, tri});
      continue;
    }
    // A flat face of T² input (two antipodal vertices): its segment between the antipodes is
    // not defined by its endpoints, so only its other edges are drawn.
    for (int k = 0; k < 3; ++k)
      if (!(P[t[k]] == t2::antipode(P[t[(k + 1) % 3]])))
        s.segments.push_back(t2::SceneSegment{scene_point(P[t[k]]), scene_point(P[t[(k + 1) % 3]]), 0, edge});
  }
  for (auto [a, b] : tr.hull_edges())
    s.segments.push_back(t2::SceneSegment{scene_point(P[a]), scene_point(P[b]), 0, style_of("color=green width=2 layer=1")});
  if (P.size() <= 60)
    for (std::size_t k = 0; k < P.size(); ++k) {
      t2::SceneStyle st = style_of("color=black marker=none layer=2");
      st.label = fmt::format("p{}", k);
      s.points.push_back(scene_point(P[k], st));
    }
  return s;
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
  write_answer(o.drawing, scene, answer(P, tr),
               fmt::format("t2 {} {}: {} triangles (draw them over their input: t2 draw FILE THIS)", command,
                           scene.name, tr.finite_triangles().size()));
  fmt::print("{}", listing(tr, o.infinite));
  return kOk;
}

}  // namespace

Action triangles_setup(Arguments& app, std::shared_ptr<TrianglesOptions> o, const std::string& command,
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
      "in T2 or not implemented: --algorithm flip and divide take front points only; t2\n"
      "triangulate refuses points all on one great circle and around it, and a point whose\n"
      "antipode lies inside a hull edge of all the others (the face beyond would be a\n"
      "hemisphere); t2 delaunay refuses an empty side with points on Omega all around it.");
  return [o, command, build] { return run(*o, command, build); };
}

}  // namespace t2cli
