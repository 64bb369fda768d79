// t2 ann: the nearest neighbour of each of a scene's points in T²
// (t2/proximity/nearest_neighbors.hpp, seed 000 Algorithm 14).
#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "proximity_answer.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/error.hpp"
#include "t2/proximity/nearest_neighbors.hpp"

namespace t2cli {
namespace cmd_ann {

struct Options {
  std::string file;       ///< the scene file, - for standard input
  AnswerDrawing drawing;  ///< --svg, --model and --scene
};

int run(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  if (P.size() < 2) throw t2::BadInput(fmt::format("{}: nearest neighbours need at least two points", scene.name));
  std::vector<t2::Triangulation::Index> nn;
  try {
    nn = t2::all_nearest_neighbors(P);
  } catch (const t2::UndefinedNearest& e) {
    throw t2::Undefined(fmt::format("{}:{}: {}", scene.name, scene.points[e.site].line, e.what()));
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t i = 0; i < nn.size(); ++i) pairs.emplace_back(i, nn[i]);
  print_pairs(o.drawing, scene, P, pairs,
              fmt::format("t2 ann {}: each point's nearest (draw it over its input: t2 draw FILE THIS)", scene.name));
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the nearest other point of each point of the scene file FILE (- for standard\n"
      "input) under the distances of T2, seen from that point: its own side first, then the\n"
      "points of Omega (by their angle with it), then the other side (the farther apart as\n"
      "drawn, the nearer). From a point of Omega: the directions under 90 degrees, then the\n"
      "points of one side (the furthest towards it), then the directions beyond 90 degrees.");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  add_drawing_options(app, o->drawing, "the points and their nearest");
  app.footer(
      "Output: one line 'i j' per point i, in order: j is i's nearest (0-based indices of the\n"
      "scene's points); among equally near points the smallest j; an equal point is at\n"
      "distance 0.\n"
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong; fewer than two\n"
      "points); 3 undefined in T2 (file:line of a point of Omega whose nearest points are a\n"
      "front one and a back one, which no distance of T2 orders).");
  return [o] { return run(*o); };
}

}  // namespace cmd_ann

T2_COMMAND({"ann", "the nearest neighbour of each of a scene's points in T2 ('i j' a line)", cmd_ann::setup});

}  // namespace t2cli
