// t2 locate: where each point of a scene lies in a subdivision of T² whose faces are the
// polygons of another scene (t2/location/: the walk of seed 000's Algorithm 15, the trapezoidal
// maps of trapezoid_locate.hpp, or every face tested).
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/location/trapezoid_locate.hpp"
#include "t2/location/walk.hpp"

namespace t2cli {
namespace cmd_locate {

struct Options {
  std::string map, queries;
  std::string algorithm = "walk";
  AnswerDrawing drawing;  ///< --svg, --model and --scene
};

// The subdivision of the polygon blocks of `scene`; a map error names the line of its face.
t2::Subdivision read_map(const t2::Scene& scene) {
  if (scene.polygons.empty()) throw t2::ParseError(scene.name, 1, "the map has no polygon block (its faces)");
  std::vector<t2::Polygon> faces;
  for (const auto& f : scene.polygons) faces.push_back(f.polygon());
  try {
    return t2::Subdivision(faces);
  } catch (const t2::MapError& e) {
    throw t2::ParseError(scene.name, scene.polygons[e.face()].line,
                         fmt::format("face {}: {}", e.face(), e.what()));
  }
}

int locate(const Options& o) {
  const t2::Scene map = read_scene_argument(o.map);
  const t2::Subdivision S = read_map(map);
  const t2::Scene queries = read_scene_argument(o.queries);
  const std::vector<t2::Point> Q = scene_points(queries);
  std::string out;
  t2::Scene answer;
  t2::Subdivision::Index from = 0;
  std::optional<t2::TrapezoidLocator> trapezoids;
  if (o.algorithm == "trapezoid") {
    try {
      trapezoids.emplace(S);
    } catch (const t2::MapError& e) {
      throw t2::ParseError(map.name, map.polygons[e.face()].line, fmt::format("face {}: {}", e.face(), e.what()));
    }
  }
  for (const auto& p : Q) {
    const t2::Location l = o.algorithm == "brute"       ? t2::locate_brute(S, p)
                           : o.algorithm == "trapezoid" ? trapezoids->locate(p)
                                                        : t2::walk(S, p, from);
    out += t2::to_string(l) + "\n";
    answer.points.push_back(scene_point(p, style_of(l.kind == t2::Location::Kind::outside ? "color=grey"
                                                                                          : "color=red")));
  }
  write_answer(o.drawing, map, answer,
               fmt::format("t2 locate {} {}: the queries (red in the map, grey outside)", map.name, queries.name));
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints, for each point of the scene file QUERIES, where it lies in the subdivision of T2\n"
      "whose faces are the polygon blocks of the scene file MAP (numbered from 0 in file order;\n"
      "each a simple polygon, counter-clockwise: the face is on the left of its edges; an edge\n"
      "shared by two faces is given once in each, in opposite directions; the complement of the\n"
      "faces is outside). One line a query: 'face F' (inside face F), 'edge F K' (inside the\n"
      "edge from vertex K of face F to vertex K+1), 'vertex F K' (vertex K of face F) or\n"
      "'outside'; for a point on an edge or a vertex, F is the least face that has it.");
  app.add_option("MAP", o->map, "the scene file of the faces, - for standard input")->required();
  app.add_option("QUERIES", o->queries, "the scene file of the query points")->required();
  app.add_option("--algorithm", o->algorithm,
                 "walk (default: seed 000's Algorithm 15, from vertex 0 along the segment to\n"
                 "the query), trapezoid (a trapezoidal map with its history DAG per side of\n"
                 "T2, built once; the walk for queries on Omega and on a side that an edge\n"
                 "leaves) or brute (every face tested in order)")
      ->type_name("A")
      ->check(IsMember({"walk", "trapezoid", "brute"}));
  add_drawing_options(app, o->drawing, "the map and the queries");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong, a face that is\n"
      "not simple or that overlaps another at a vertex or along an edge; with trapezoid,\n"
      "also edges of a side that cross, or a vertex inside another face's edge).");
  return [o] { return locate(*o); };
}

}  // namespace cmd_locate

T2_COMMAND({"locate", "where points lie in a subdivision of T2 (faces given as polygons)", cmd_locate::setup});

}  // namespace t2cli
