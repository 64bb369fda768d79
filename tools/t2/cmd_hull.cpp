// t2 hull: the convex hull of a scene's points (t2/hull.hpp), as indices, optionally drawn.
#include <CLI/CLI.hpp>
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
#include "t2/io.hpp"
#include "t2/scene.hpp"

namespace t2cli {
namespace {

namespace dr = t2::draw;

struct Options {
  std::string file;
  std::string algorithm = "automatic";
  AnswerDrawing drawing;
};

t2::HullAlgorithm algorithm_of(const std::string& s) {
  for (auto a : {t2::HullAlgorithm::automatic, t2::HullAlgorithm::merge, t2::HullAlgorithm::jarvis,
                 t2::HullAlgorithm::graham, t2::HullAlgorithm::quickhull, t2::HullAlgorithm::monotone})
    if (s == t2::name(a)) return a;
  throw UsageError(fmt::format("unknown algorithm '{}'", s));
}

// The input points in grey, the hull in green (a polygon, a segment or a point).
dr::Figure picture(const std::vector<t2::Point>& P, const std::vector<std::size_t>& hull) {
  dr::Figure f;
  std::vector<t2::Point> h;
  for (std::size_t i : hull) h.push_back(P[i]);
  const dr::Style green = dr::Style().color("#2ca02c").width(2).layer(0);
  if (h.size() >= 3) f.add(h, dr::Style(green).fill("#2ca02c"));
  if (h.size() == 2) f.segment(h[0], h[1], green);
  for (const auto& p : P) f.add(p, dr::Style().color("#7f7f7f").layer(1));
  for (std::size_t k = 0; k < hull.size(); ++k)
    f.add(P[hull[k]], dr::Style().color("#000000").label(fmt::format("p{}", hull[k])).layer(2));
  return f;
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
  if (!o.drawing.svg.empty()) write_drawing(o.drawing, picture(P, h), fit_plane(P));
  std::string out;
  for (std::size_t i : h) out += fmt::format("{}\n", i);
  fmt::print("{}", out);
  return kOk;
}

Action setup(CLI::App& app) {
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
                 "merge), merge, jarvis, graham, quickhull or monotone")
      ->type_name("A")
      ->check(CLI::IsMember({"automatic", "merge", "jarvis", "graham", "quickhull", "monotone"}));
  add_drawing_options(app, o->drawing, "the points and the hull");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 the\n"
      "points have no hull: the message names points that lie in no open hemisphere\n"
      "(p3 = the point of index 3), e.g. 'p3 and p7 are antipodal'.");
  return [o] { return hull(*o); };
}

}  // namespace

T2_COMMAND({"hull", "the convex hull of a scene's points (indices, counter-clockwise)", setup});

}  // namespace t2cli
