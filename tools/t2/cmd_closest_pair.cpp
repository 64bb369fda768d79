// t2 closest-pair: the closest pair of a scene's points in T² (t2/proximity/closest_pair.hpp),
// by brute force, from the Delaunay edges or by divide and conquer.
#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "proximity_answer.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/error.hpp"
#include "t2/proximity/closest_pair.hpp"

namespace t2cli {
namespace cmd_closest_pair {

struct Options {
  std::string file;                   ///< the scene file, - for standard input
  std::string algorithm = "delaunay";  ///< brute, delaunay or divide
  AnswerDrawing drawing;              ///< --svg, --model and --scene
};

int run(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  if (P.size() < 2) throw t2::BadInput(fmt::format("{}: the closest pair needs at least two points", scene.name));
  const auto pair = o.algorithm == "brute"    ? t2::closest_pair_brute(P)
                    : o.algorithm == "divide" ? t2::closest_pair_divide(P)
                                              : t2::closest_pair(P);
  print_pairs(o.drawing, scene, P, {pair},
              fmt::format("t2 closest-pair {}: p{} p{} (draw it over its input: t2 draw FILE THIS)", scene.name,
                          pair.first, pair.second));
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the closest pair of the points of the scene file FILE (- for standard input)\n"
      "under the distances of T2 (see t2 help emst): equal points first (distance 0), then the\n"
      "nearest pair of one side, then a pair with a point on Omega (+infinity, all level), then\n"
      "a front and a back point (the pair farthest apart as drawn).");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("--algorithm", o->algorithm, "brute (all pairs), delaunay (the edges of each side) or divide\n"
                 "(Shamos-Hoey divide and conquer on each side)")
      ->check(IsMember({"brute", "delaunay", "divide"}));
  add_drawing_options(app, o->drawing, "the points and the pair");
  app.footer(
      "Output: one line 'i j', 0-based indices of the scene's points, i < j; among equally\n"
      "close pairs the smallest (i, j). The three algorithms give the same pair.\n"
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong; fewer than two\n"
      "points).");
  return [o] { return run(*o); };
}

}  // namespace cmd_closest_pair

T2_COMMAND({"closest-pair", "the closest pair of a scene's points in T2 ('i j')", cmd_closest_pair::setup});

}  // namespace t2cli
