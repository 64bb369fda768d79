// t2 animate: records an algorithm's steps through its trace (t2/trace/*), then writes one
// self-contained HTML page that plays them back (tools/t2/animate/run.cpp).
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "animate/run.hpp"
#include "command.hpp"
#include "scene_argument.hpp"

namespace t2cli {
namespace cmd_animate {

struct Options {
  std::string algo;
  std::string file;
  std::string out;
};

int animate(const Options& o) {
  fmt::print("{}\n", animate::write_animation(o.algo, read_scene_argument(o.file), o.out));
  return kOk;
}

// "  NAME  summary" for each algorithm t2 animate shows.
std::string algo_list() {
  std::string s;
  for (const auto* a : algorithms::animated()) s += fmt::format("  {:<15} {}\n", a->name, a->summary);
  return s;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Runs the algorithm ALGO on the points of the scene file FILE (- for standard input;\n"
      "on its segment blocks for intersect and intersect-circular), recording every step, and writes OUT, one self-contained HTML page (no network) that\n"
      "plays the steps back: the planar and the spherical model of each step, the data\n"
      "structure beside them (Graham's stack, the hull so far, the triangles of a flip, a\n"
      "sweep's status with its sweep line), the\n"
      "explanation, and controls: previous/next (arrow keys), play/pause (space), speed, a\n"
      "timeline, and the level of detail (lecture: the steps that change the structure;\n"
      "debugging: every test as well). The page starts paused at the first step; its URL\n"
      "fragment #step=N (or last) and &level=debugging open it elsewhere.\n"
      "ALGO (each name means one algorithm everywhere in t2: t2 hull --algorithm, t2 bench,\n"
      "t2 triangulate, t2 intersect):\n" +
      algo_list() +
      "\nWhat the queries are, when the scene has only points: walk locates seven queries in the\n"
      "Delaunay triangulation of the points, each walk from the same vertex: q0 to q3 drawn\n"
      "uniformly in the points' bounding box (a fixed seed), q4 the middle point of the file,\n"
      "q5 the antipode of q0 (on the back) and q6 = [0, 1, 0] on Omega; trapezoid builds the\n"
      "trapezoidal map of each side of that triangulation, one edge a step (the DAG's size and\n"
      "depth beside it), then locates the same queries, one DAG node a step; kdtree builds the tree of\n"
      "the points and reports those in one window, the middle half of the bounding box of the\n"
      "front points (of the back points when none is in front).");
  std::vector<std::string> names;
  for (const auto* a : algorithms::animated()) names.push_back(a->name);
  app.add_option("ALGO", o->algo, algorithms::words(names))
      ->required()
      ->check([](const std::string& a) {
        const algorithms::Algorithm* x = algorithms::find(a);
        return x != nullptr && x->animates() ? std::string()
                                         : fmt::format("'{}': not an algorithm of t2 animate", a);
      });
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("-o,--output", o->out, "the HTML page to write (atomically)")->required()->type_name("OUT");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong; more than 200\n"
      "points or 100 segments; delaunay or sec given points off the front side); 3 undefined:\n"
      "the points have no hull (no open hemisphere holds them), or no triangulation of T2\n"
      "(t2 triangulate), or intersect (Bentley-Ottmann) was given a segment not in front; walk,\n"
      "trapezoid: no triangle to locate in; kdtree: every point on Omega.");
  return [o] { return animate(*o); };
}

}  // namespace cmd_animate

T2_COMMAND({"animate", "step-through animation of an algorithm, as one HTML page", cmd_animate::setup});

}  // namespace t2cli
