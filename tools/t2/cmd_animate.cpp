// t2 animate: records an algorithm's steps through its trace (t2/trace/*), then writes one
// self-contained HTML page that plays them back (tools/t2/animate/run.cpp).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>
#include <string>

#include "animate/run.hpp"
#include "command.hpp"
#include "scene_argument.hpp"

namespace t2cli {
namespace {

struct Options {
  std::string algo;
  std::string file;
  std::string out;
};

int animate(const Options& o) {
  fmt::print("{}\n", animate::write_animation(o.algo, read_scene_argument(o.file), o.out));
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
      "insertion in spatial order, flips only where the new point sees hull edges; on input\n"
      "with points behind or on Omega, Algorithm 9 on T2 as t2 triangulate runs it: one step\n"
      "per point, the faces where it takes the place of v-infinity when the hull goes), sweep\n"
      "(the sweep of t2 triangulate, chapter 09: the points in (x, y) order, each joined to\n"
      "the hull edges it sees; lecture: one step per point, its new fan; debugging: each\n"
      "flip of step 35 too), delaunay (the insertion with Lawson flips: the library's\n"
      "randomized incremental Delaunay). sweep and delaunay are animated for front points\n"
      "only.");
  app.add_option("ALGO", o->algo, "jarvis, graham, merge-hull, triangulate, sweep or delaunay")
      ->required()
      ->check([](const std::string& a) {
        for (const auto& x : animate::algorithms())
          if (a == x.name) return std::string();
        return fmt::format("'{}': not an algorithm of t2 animate", a);
      });
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("-o,--output", o->out, "the HTML page to write (atomically)")->required()->type_name("OUT");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong; more than 200\n"
      "points; sweep or delaunay of points off the front side); 3 undefined: the points have\n"
      "no hull (no open hemisphere holds them), or no triangulation of T2 (t2 triangulate).");
  return [o] { return animate(*o); };
}

}  // namespace

T2_COMMAND({"animate", "step-through animation of an algorithm, as one HTML page", setup});

}  // namespace t2cli
