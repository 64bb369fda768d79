// t2 voronoi: the Voronoi diagram of T² of a scene's points (t2/voronoi/voronoi.hpp, the dual
// of the Delaunay complex, Algorithm 11), or its front half by Fortune's sweep
// (t2/voronoi/fortune.hpp): exact vertices, edges and bisector lines, for scripts.
#include <fmt/format.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/voronoi.hpp"
#include "command.hpp"
#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/voronoi/fortune.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace t2cli {
namespace cmd_voronoi {

using Index = t2::VoronoiDiagram::Index;

struct Options {
  std::string file;       ///< the scene file, - for standard input
  std::string algorithm = "dual";  ///< dual (t2::voronoi) or fortune (t2::fortune)
  AnswerDrawing drawing;  ///< --svg, --model and --scene
};

/// The vertex with its coordinates divided by their (positive) greatest common divisor.
t2::ExactPoint reduced(const t2::ExactPoint& v) {
  t2::Integer g;
  mpz_gcd(g.get_mpz_t(), v.w().get_mpz_t(), v.x().get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), v.y().get_mpz_t());
  if (g == 0) return v;
  return t2::ExactPoint(t2::Integer(v.w() / g), t2::Integer(v.x() / g), t2::Integer(v.y() / g));
}

/// The `vertex W X Y  s1 s2 ...` lines and the `edge A B  s t` lines of a diagram (either kind).
template <class Diagram>
std::string vertices_and_edges(const Diagram& d) {
  std::string out;
  for (Index v = 0; v < d.size(); ++v) {
    const t2::ExactPoint p = reduced(d.vertex(v));
    out += fmt::format("vertex {} {} {} ", p.w().get_str(), p.x().get_str(), p.y().get_str());
    for (Index s : d.vertex_sites(v)) out += fmt::format(" {}", s);
    out += '\n';
  }
  for (const auto& e : d.edges) out += fmt::format("edge {} {}  {} {}\n", e.a, e.b, e.s, e.t);
  return out;
}

std::string listing(const t2::VoronoiDiagram& vd) {
  std::string out = vertices_and_edges(vd);
  for (auto [s, t] : vd.lines) out += fmt::format("line {} {}\n", s, t);
  return out;
}

/// The diagram as a scene: the edges in red, the vertices as red dots, the bisector lines.
t2::Scene answer(const std::vector<t2::Point>& P, const t2::VoronoiDiagram& vd) {
  return algorithms::voronoi_scene(P, vd, style_of("color=red width=2 layer=1"),
                                   style_of("color=red marker=dot layer=2"));
}

std::string listing(const t2::FortuneDiagram& fd) {
  std::string out = vertices_and_edges(fd);
  for (const auto& r : fd.rays) {
    const t2::ExactPoint q = reduced(r.end);
    out += fmt::format("ray {}  0 {} {}  {} {}\n", r.a, q.x().get_str(), q.y().get_str(), r.s, r.t);
  }
  for (auto [s, t] : fd.lines) out += fmt::format("line {} {}\n", s, t);
  return out;
}

/// Fortune's front half as a scene: edges and rays (to their point of Ω) in red, vertices, lines.
t2::Scene answer(const std::vector<t2::Point>& P, const t2::FortuneDiagram& fd) {
  t2::Scene s;
  const t2::SceneStyle st = style_of("color=red width=2 layer=1");
  for (const auto& e : fd.edges)
    s.segments.push_back(t2::SceneSegment{scene_point(t2::to_double(fd.vertex(e.a))),
                                          scene_point(t2::to_double(fd.vertex(e.b))), 0, st});
  for (const auto& r : fd.rays)
    s.segments.push_back(t2::SceneSegment{scene_point(t2::to_double(fd.vertex(r.a))),
                                          scene_point(t2::to_double(reduced(r.end))), 0, st});
  const t2::SceneStyle dot = style_of("color=red marker=dot layer=2");
  for (Index v = 0; v < fd.size(); ++v) s.points.push_back(scene_point(t2::to_double(fd.vertex(v)), dot));
  algorithms::add_bisector_lines(P, fd.lines, style_of("color=red width=2 layer=1"), s);
  return s;
}

/// `--algorithm fortune`: front points only (else exit 3 with the reason).
int run_fortune(const Options& o, const t2::Scene& scene, const std::vector<t2::Point>& P) {
  t2::FortuneDiagram fd;
  try {
    fd = t2::fortune(P);
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", scene.name, e.what()));
  }
  for (auto [dropped, kept] : fd.duplicates)
    fmt::print(stderr, "t2 voronoi: {}:{}: p{} equals p{} (line {}): merged\n", scene.name,
               scene.points[dropped].line, dropped, kept, scene.points[kept].line);
  write_answer(o.drawing, scene, answer(P, fd),
               fmt::format("t2 voronoi --algorithm fortune {}: {} vertices, {} edges, {} rays (draw them over their "
                           "input: t2 draw FILE THIS)",
                           scene.name, fd.size(), fd.edges.size(), fd.rays.size()));
  fmt::print("{}", listing(fd));
  return kOk;
}

int run(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  if (o.algorithm == "fortune") return run_fortune(o, scene, P);
  t2::VoronoiDiagram vd;
  try {
    vd = t2::voronoi(P);
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", scene.name, e.what()));
  } catch (const std::runtime_error& e) {  // not built yet (complex.hpp, voronoi.hpp)
    throw t2::Undefined(fmt::format("{}: not implemented: {}", scene.name, e.what()));
  }
  for (auto [dropped, kept] : vd.duplicates)
    fmt::print(stderr, "t2 voronoi: {}:{}: p{} equals p{} (line {}): merged\n", scene.name,
               scene.points[dropped].line, dropped, kept, scene.points[kept].line);
  const bool drawn = !o.drawing.svg.empty() || !o.drawing.scene.empty();  // else no scene to build
  write_answer(o.drawing, scene, drawn ? answer(P, vd) : t2::Scene{},
               fmt::format("t2 voronoi {}: {} vertices, {} edges (draw them over their input: t2 draw FILE THIS)",
                           scene.name, vd.size(), vd.edges.size()));
  fmt::print("{}", listing(vd));
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the Voronoi diagram of T2 of the points of the scene file FILE (- for standard\n"
      "input): the dual of the Delaunay complex, one cell per point covering the whole sphere.\n"
      "For points in front only, its back half is the farthest-point Voronoi diagram.");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("--algorithm", o->algorithm,
                 "dual (default: the dual of the Delaunay complex, the whole sphere) or fortune\n"
                 "(Fortune's sweep: the front half only, for points in front only)")
      ->type_name("A")
      ->check(IsMember({"dual", "fortune"}));
  add_drawing_options(app, o->drawing, "the points and the diagram");
  app.footer(
      "Output: one line per Voronoi vertex, 'vertex W X Y  s1 s2 s3 ...': its exact homogeneous\n"
      "coordinates as integers without a common factor (W > 0 front, W < 0 back, W = 0 on\n"
      "Omega), then the 0-based indices of the points whose cells meet there, counter-\n"
      "clockwise around it (four or more for cocircular points). Then one line per edge,\n"
      "'edge A B  s t': vertex numbers in output order and the two points it separates. Two\n"
      "points have no vertex: 'line s t', their bisector. Equal points are merged (stderr).\n"
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 undefined in\n"
      "T2 (a side without points while two or more points lie on Omega; a tie on Omega) or\n"
      "not implemented (collinear points on both sides; a vertex at the middle of two points of\n"
      "Omega; --algorithm fortune: a point not in front).\n"
      "--algorithm fortune prints the front half only: the same front vertices and the edges\n"
      "between them, then one line per unbounded edge, 'ray A  0 X Y  s t': from vertex A to\n"
      "the point [0, X, Y] of Omega where the edge of the dual leaves the front side.");
  return [o] { return run(*o); };
}

}  // namespace cmd_voronoi

T2_COMMAND({"voronoi", "the Voronoi diagram of T2 of a scene's points (exact vertices, edges)", cmd_voronoi::setup});

}  // namespace t2cli
