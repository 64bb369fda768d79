// t2 intersect: the intersection points of a scene's segments (t2/intersect/intersections.hpp).
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/intersect/intersections.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/scene.hpp"

namespace t2cli {
namespace cmd_intersect {

struct Options {
  std::string file;
  std::string algorithm = "sweep";
  AnswerDrawing drawing;
};

// The answer as a scene: each point in red, labelled with the segments through it.
t2::Scene answer(const std::vector<t2::IntersectionPoint>& points) {
  t2::Scene s;
  for (const auto& p : points) {
    t2::SceneStyle st = style_of("color=red size=4 layer=3");
    std::string label;
    for (std::size_t i : p.segments) label += fmt::format("{}s{}", label.empty() ? "" : ",", i);
    st.label = label;
    s.points.push_back(scene_point(t2::to_double(p.point), st));
  }
  return s;
}

int intersect(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  std::vector<t2::Segment> segments;
  segments.reserve(scene.segments.size());
  for (const auto& s : scene.segments) segments.push_back(s.segment());
  const auto algorithm = o.algorithm == "brute"      ? t2::IntersectAlgorithm::brute
                         : o.algorithm == "circular" ? t2::IntersectAlgorithm::circular
                                                     : t2::IntersectAlgorithm::sweep;
  std::vector<t2::IntersectionPoint> points;
  try {
    points = t2::intersections(segments, algorithm);
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", scene.name, e.what()));
  }
  write_answer(o.drawing, scene, answer(points),
               fmt::format("t2 intersect {}: {} intersection points (draw it over its input: t2 draw FILE THIS)",
                           scene.name, points.size()));
  std::string out;
  for (const auto& p : points) out += t2::to_line(p) + "\n";
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the intersection points of the segment blocks of the scene file FILE (- for\n"
      "standard input; the segments are numbered from 0 in file order, other objects are\n"
      "ignored), one line per point: 'W X Y  i j ...', the exact point as integers without\n"
      "common factor, then the ascending indices of every segment through it. Points are in\n"
      "the wxy order (back, Omega, front; then x, then y). A point is reported when it lies on\n"
      "two segments and is an endpoint of one of the segments through it, or lies on two\n"
      "segments of different lines: so collinear overlapping segments give the two ends of\n"
      "their common piece, not its inner points.");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("--algorithm", o->algorithm,
                 "sweep (default: Bentley-Ottmann, front segments only), brute (every pair,\n"
                 "every segment of T2: front, back, crossing Omega, on Omega) or circular (the\n"
                 "circular sweep of T2 around a point, O((n + k) log n), every segment of T2)")
      ->type_name("A")
      ->check(IsMember({"brute", "sweep", "circular"}));
  add_drawing_options(app, o->drawing, "the segments and the intersection points");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 the sweep\n"
      "was given a segment with an endpoint behind or on Omega (the message names it; the\n"
      "brute force and the circular sweep take it).");
  return [o] { return intersect(*o); };
}

}  // namespace cmd_intersect

T2_COMMAND({"intersect", "the intersection points of a scene's segments (exact, with the segments through them)",
            cmd_intersect::setup});

}  // namespace t2cli
