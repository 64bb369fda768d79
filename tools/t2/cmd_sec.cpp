// t2 sec: the smallest enclosing circle of a scene's points in T² (t2/proximity/enclosing_circle.hpp,
// Welzl's algorithm; enclosing_circle_voronoi.hpp, Shamos's and Bhattacharya–Toussaint's).
#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "proximity_answer.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/error.hpp"
#include "t2/proximity/enclosing_circle.hpp"
#include "t2/proximity/enclosing_circle_voronoi.hpp"

namespace t2cli {
namespace cmd_sec {

struct Options {
  std::string file;                ///< the scene file, - for standard input
  std::string algorithm = "welzl";  ///< welzl, shamos or bt
  AnswerDrawing drawing;           ///< --svg, --model and --scene
};

int run(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  if (P.empty()) throw t2::BadInput(fmt::format("{}: the smallest enclosing circle needs at least one point", scene.name));
  t2::EnclosingCircle c;
  try {
    c = o.algorithm == "shamos" ? t2::smallest_enclosing_circle_shamos(P)
        : o.algorithm == "bt"   ? t2::smallest_enclosing_circle_bt(P)
                                : t2::smallest_enclosing_circle(P);
  } catch (const t2::UndefinedEnclosing& e) {
    const int line = scene.points[e.site].line, other = scene.points[e.other].line;
    throw t2::Undefined(e.site == e.other ? fmt::format("{}:{}: {}", scene.name, line, e.what())
                                          : fmt::format("{}:{} and line {}: {}", scene.name, line, other, e.what()));
  }
  std::string out = fmt::format("{} {} {}\n", c.center.w().get_str(), c.center.x().get_str(), c.center.y().get_str());
  for (std::size_t k = 0; k < c.on_circle.size(); ++k) out += fmt::format("{}{}", k ? " " : "", c.on_circle[k]);
  out += "\n";
  t2::Scene s;
  const t2::Point z = t2::to_double(c.center);
  if (c.support.size() > 1)
    s.circles.push_back(t2::SceneCircle{scene_point(z), scene_point(P[c.support[0]]), 0,
                                        style_of("color=red width=2 layer=1")});
  s.points.push_back(scene_point(z, style_of("color=red layer=1")));
  write_answer(o.drawing, scene, std::move(s),
               fmt::format("t2 sec {}: the smallest enclosing circle and its centre (draw it over its input: t2 draw "
                           "FILE THIS)",
                           scene.name));
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the smallest enclosing circle of the points of the scene file FILE (- for\n"
      "standard input) by Welzl's randomized algorithm (expected linear time, exact predicates),\n"
      "or on the farthest-point Voronoi diagram (Shamos; Bhattacharya-Toussaint, on the hull).\n"
      "In T2 a circle has a proper centre z and a radius in T1 (the distances of t2 help emst);\n"
      "the smallest one minimizes the largest distance from z to a point. For points all on\n"
      "one side it is the classic circle of their drawn positions, centred on that side; with a\n"
      "point on Omega, or points on both sides, no circle is the smallest (exit 3).");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("--algorithm", o->algorithm, "welzl (randomized, expected O(n); the default), shamos\n"
                 "(the farthest-point diagram of all the points) or bt (Bhattacharya-Toussaint:\n"
                 "the hull, its diameter, the farthest-point diagram of its corners)")
      ->type_name("A")
      ->check(IsMember({"welzl", "shamos", "bt"}));
  add_drawing_options(app, o->drawing, "the points, the circle and its centre");
  app.footer(
      "Output: a line 'W X Y', the exact centre as integer homogeneous coordinates with no\n"
      "common factor (W > 0 for front points, W < 0 for back points), then a line with the\n"
      "0-based indices of every point on the circle, ascending (equal points all listed). One\n"
      "point, or equal points only: the centre is that point, all are on the circle. The three\n"
      "algorithms give the same output.\n"
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong; no points);\n"
      "3 undefined in T2 (file:line of a point on Omega, or of a front and a back point).");
  return [o] { return run(*o); };
}

}  // namespace cmd_sec

T2_COMMAND({"sec", "the smallest enclosing circle of a scene's points in T2 ('W X Y', the points on it)", cmd_sec::setup});

}  // namespace t2cli
