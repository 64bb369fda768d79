// t2 hull: the convex hull of a scene's points (t2/hull.hpp), as indices, optionally drawn.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/draw.hpp"
#include "t2/hull.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/scene.hpp"

namespace t2cli {
namespace cmd_hull {

namespace dr = t2::draw;

struct Options {
  std::string file;
  std::string algorithm = "automatic";
  AnswerDrawing drawing;
};

t2::HullAlgorithm algorithm_of(const std::string& s) {
  for (auto a : t2::hull_algorithms)
    if (s == t2::name(a)) return a;
  throw UsageError(fmt::format("unknown algorithm '{}'", s));
}

// The hull as a scene: a green polygon (a segment, a point), its vertices labelled pK.
t2::Scene answer(const std::vector<t2::Point>& P, const std::vector<std::size_t>& hull) {
  t2::Scene s;
  std::vector<t2::ScenePoint> h;
  for (std::size_t i : hull) {
    t2::SceneStyle st = style_of("color=black size=4.5 layer=3");
    st.label = fmt::format("p{}", i);
    s.points.push_back(scene_point(P[i], st));
    h.push_back(scene_point(P[i]));
  }
  const t2::SceneStyle green = style_of("color=green width=2 layer=0");
  if (h.size() >= 3) s.polygons.push_back(t2::ScenePolygon{h, 0, style_of("color=green width=2 fill=green layer=0")});
  if (h.size() == 2) s.segments.push_back(t2::SceneSegment{h[0], h[1], 0, green});
  return s;
}

int hull(const Options& o) {
  const t2::HullAlgorithm a = algorithm_of(o.algorithm);
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  std::vector<std::size_t> h;
  try {
    h = t2::convex_hull(P, a);
  } catch (const t2::NoHull& e) {
    throw t2::Undefined(fmt::format("{}: no convex hull: {}", scene.name, e.what()));
  }
  write_answer(o.drawing, scene, answer(P, h),
               fmt::format("t2 hull {}: the convex hull, {} vertices (draw it over its input: t2 draw FILE THIS)",
                           scene.name, h.size()));
  std::string out;
  for (std::size_t i : h) out += fmt::format("{}\n", i);
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the convex hull of the points of the scene file FILE (- for standard input): the\n"
      "0-based indices of the strict hull vertices among the scene's points (bare and labelled,\n"
      "in file order; blocks are ignored), one per line, counter-clockwise in T2, starting at\n"
      "any vertex. Points inside hull edges are no vertices; of equal points one is given.\n"
      "One point gives one line, collinear points the two ends of their segment, no point\n"
      "nothing. Points on both sides of T2 and at infinity are fine as long as they lie in an\n"
      "open hemisphere; otherwise there is no hull.");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("--algorithm", o->algorithm,
                 "automatic (default: Akl-Toussaint + monotone chain on front-only input, else\n"
                 "merge), merge, jarvis, graham, quickhull, monotone or chan")
      ->type_name("A")
      ->check(IsMember(names_of(t2::hull_algorithms)));
  add_drawing_options(app, o->drawing, "the points and the hull");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 the\n"
      "points have no hull: the message names points that lie in no open hemisphere\n"
      "(p3 = the point of index 3), e.g. 'p3 and p7 are antipodal'.");
  return [o] { return hull(*o); };
}

}  // namespace cmd_hull

T2_COMMAND({"hull", "the convex hull of a scene's points (indices, counter-clockwise)", cmd_hull::setup});

}  // namespace t2cli
