// t2 emst: the minimum spanning tree of a scene's points in T² (t2/proximity/spanning_tree.hpp,
// seed 000 Algorithm 12).
#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "proximity_answer.hpp"
#include "scene_argument.hpp"
#include "t2/proximity/spanning_tree.hpp"

namespace t2cli {
namespace cmd_emst {

struct Options {
  std::string file;       ///< the scene file, - for standard input
  AnswerDrawing drawing;  ///< --svg, --model and --scene
};

int run(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  const auto tree = t2::minimum_spanning_tree(P);
  print_pairs(o.drawing, scene, P, tree,
              fmt::format("t2 emst {}: the minimum spanning tree, {} edges (draw it over its input: t2 draw FILE THIS)",
                          scene.name, tree.size()));
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the minimum spanning tree of the points of the scene file FILE (- for standard\n"
      "input) under the distances of T2: finite between points of one side, +infinity when a\n"
      "point is on Omega, 'beyond infinity' between a front and a back point (the farther apart\n"
      "as drawn, the nearer). Kruskal on the Delaunay edges of each side (Algorithm 12).");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  add_drawing_options(app, o->drawing, "the points and the tree");
  app.footer(
      "Output: n - 1 lines 'i j' (0-based indices of the scene's points, i < j), in the order\n"
      "Kruskal takes them. Ties: the tree is Kruskal's on all pairs ordered by distance, then\n"
      "by (i, j); equal points are joined first, each to the first of them; all pairs with a\n"
      "point on Omega weigh the same (+infinity), so those are taken by index.\n"
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong).");
  return [o] { return run(*o); };
}

}  // namespace cmd_emst

T2_COMMAND({"emst", "the minimum spanning tree of a scene's points in T2 (one edge 'i j' a line)", cmd_emst::setup});

}  // namespace t2cli
