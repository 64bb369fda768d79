// t2 voronoi: the Voronoi diagram of T² of a scene's points (t2/voronoi/voronoi.hpp, the dual
// of the Delaunay complex, Algorithm 11), or its front half by Fortune's sweep
// (t2/voronoi/fortune.hpp): exact vertices, edges and bisector lines, for scripts.
#include <fmt/format.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "command.hpp"
#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/distance.hpp"
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

/// The edge from a to b between the cells of s and t, drawn: the segment of T² from a to b when
/// a point of it, a + b, has no site nearer than s; otherwise the other arc, through ¬(a + b).
/// Only the sites of a and b need a test: each site d ≠ s, t leaves s nearest on a closed half
/// H_d of the bisector's great circle, and the edge is the arc ∩ H_d from a to b. For d at a,
/// H_d ends at a (d, s, t are equidistant there), and likewise at b; so the arc ∩ H_d over
/// those d alone, which holds the edge, already ends at a and at b: it is the edge. O(1) a
/// vertex of three sites, where a scan of all n sites made the drawing O(n²).
void draw_edge(const std::vector<t2::Point>& P, const t2::VoronoiDiagram& vd, const t2::VoronoiDiagram::Edge& e,
               t2::Scene& s) {
  const t2::SceneStyle st = style_of("color=red width=2 layer=1");
  const t2::ExactPoint a = vd.vertex(e.a), b = vd.vertex(e.b);
  if (a == t2::antipode(b)) return;  // either half of the bisector: not drawn
  const t2::ExactPoint m(t2::Integer(a.w() + b.w()), t2::Integer(a.x() + b.x()), t2::Integer(a.y() + b.y()));
  bool other = false;
  const t2::ExactPoint se = t2::to_exact(P[e.s]);
  for (const Index v : {e.a, e.b})
    for (const Index k : vd.vertex_sites(v)) {
      try {
        other = other || t2::compare_distance(t2::to_exact(P[k]), se, m) == t2::NEGATIVE;
      } catch (const t2::Undefined&) {  // m on Ω between a front and a back site: no order
      }
    }
  const t2::Point pa = t2::to_double(a), pb = t2::to_double(b);
  if (!other) {
    s.segments.push_back(t2::SceneSegment{scene_point(pa), scene_point(pb), 0, st});
    return;
  }
  const t2::Point pm = t2::to_double(t2::antipode(m));
  s.segments.push_back(t2::SceneSegment{scene_point(pa), scene_point(pm), 0, st});
  s.segments.push_back(t2::SceneSegment{scene_point(pm), scene_point(pb), 0, st});
}

/// The bisector lines (no vertex) of the pairs `lines`, drawn into `s`.
void draw_lines(const std::vector<t2::Point>& P, const std::vector<std::pair<Index, Index>>& lines, t2::Scene& s) {
  for (auto [i, j] : lines) {
    const t2::Point &a = P[i], &b = P[j];
    t2::Point p(0, 1, 0), q(0, 0, 1);  // sites on different sides: Ω
    if (t2::sign_of(a.w()) == t2::sign_of(b.w()) && a.w() != 0) {  // the perpendicular bisector
      const double ax = a.x() / a.w(), ay = a.y() / a.w(), bx = b.x() / b.w(), by = b.y() / b.w();
      p = t2::Point(a.w() > 0 ? 1 : -1, (ax + bx) / 2 * (a.w() > 0 ? 1 : -1), (ay + by) / 2 * (a.w() > 0 ? 1 : -1));
      q = t2::Point(0, ay - by, bx - ax);
    }
    s.lines.push_back(t2::SceneLine{scene_point(p), scene_point(q), 0, style_of("color=red width=2 layer=1")});
  }
}

/// The diagram as a scene: the edges in red, the vertices as red dots, the bisector lines.
t2::Scene answer(const std::vector<t2::Point>& P, const t2::VoronoiDiagram& vd) {
  t2::Scene s;
  for (const auto& e : vd.edges) draw_edge(P, vd, e, s);
  for (Index v = 0; v < vd.size(); ++v)
    s.points.push_back(scene_point(t2::to_double(vd.vertex(v)), style_of("color=red marker=dot layer=2")));
  draw_lines(P, vd.lines, s);
  return s;
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
  draw_lines(P, fd.lines, s);
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
