// t2 kernel: the kernel of a scene's polygon block (t2/hull/polygon_kernel.hpp), the points that
// see all of the polygon. "Kernel" here is the polygon's, not the predicate kernel of the library.
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/hull/polygon_kernel.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli {
namespace cmd_kernel {

namespace dr = t2::draw;

struct Options {
  std::string file;
  AnswerDrawing drawing;
};

// The kernel as a scene: a red polygon, segment or point (the input polygon, drawn under it,
// is green by default). Two consecutive corners on Ω that are antipodes have no segment of T²
// between them: that edge (along Ω) is left out, the others are drawn as segments.
t2::Scene answer(const std::vector<t2::Point>& corners) {
  t2::Scene s;
  const t2::SceneStyle red = style_of("color=red width=2 layer=0");
  std::vector<t2::ScenePoint> c;
  for (const auto& p : corners) c.push_back(scene_point(p));
  const std::size_t n = c.size();
  bool antipodal = false;
  for (std::size_t i = 0; n >= 3 && i < n; ++i) antipodal |= c[i].point == t2::antipode(c[(i + 1) % n].point);
  if (n >= 3 && !antipodal) s.polygons.push_back(t2::ScenePolygon{c, 0, style_of("color=red width=2 fill=red layer=0")});
  for (std::size_t i = 0; antipodal && i < n; ++i)
    if (!(c[i].point == t2::antipode(c[(i + 1) % n].point))) s.segments.push_back(t2::SceneSegment{c[i], c[(i + 1) % n], 0, red});
  if (n == 2) s.segments.push_back(t2::SceneSegment{c[0], c[1], 0, red});
  if (n == 1) {
    t2::SceneStyle st = style_of("color=red size=4.5 layer=3");
    st.label = "kernel";
    s.points.push_back(scene_point(c[0].point, st));
  }
  return s;
}

int polygon_kernel(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  if (scene.polygons.empty()) throw t2::BadInput(fmt::format("{}: t2 kernel needs a polygon block, the file has none", scene.name));
  if (scene.polygons.size() > 1)
    throw t2::ParseError(scene.name, scene.polygons[1].line, "t2 kernel takes one polygon block, this is a second one");
  const t2::ScenePolygon& block = scene.polygons[0];
  std::vector<t2::Point> V;
  for (const auto& v : block.vertices) V.push_back(v.point);
  t2::PolygonKernel K;
  try {
    K = t2::polygon_kernel(V);
  } catch (const t2::BadInput& e) {
    throw t2::ParseError(scene.name, block.line, e.what());
  }
  std::vector<t2::Point> corners;
  for (const auto& v : K.vertices) corners.push_back(t2::normalized(t2::to_double(v)));
  const char* kind = K.empty()                  ? "empty"
                     : K.vertices.size() == 1   ? "point"
                     : K.vertices.size() == 2   ? "segment"
                     : K.bounded()              ? "bounded"
                                                : "unbounded";
  std::string out = fmt::format("{}\n", kind);
  for (const auto& c : corners) out += fmt::format("{} {} {}\n", t2::to_string(c.w()), t2::to_string(c.x()), t2::to_string(c.y()));
  write_answer(o.drawing, scene, answer(corners),
               fmt::format("t2 kernel {}: the kernel of the polygon of line {}, {} (draw it over its input: t2 draw "
                           "FILE THIS)",
                           scene.name, block.line, kind));
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the kernel of the polygon block of the scene file FILE (- for standard input):\n"
      "the points of the polygon that see every point of it. The polygon's vertices are front\n"
      "points or points of Omega (an unbounded polygon), its interior on the left of its edges\n"
      "(a front-only polygon given clockwise is read backwards). First line: empty, point,\n"
      "segment, bounded or unbounded; then the kernel's corners counter-clockwise from the\n"
      "least in the wxy order (Omega first, then by x, then by y), one per line as 'w x y'\n"
      "(normalized, rounded once from the exact corner). Corners with w = 0\n"
      "are points of Omega: there the kernel runs off to infinity, and consecutive corners on\n"
      "Omega are joined along Omega.");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  add_drawing_options(app, o->drawing, "the polygon and its kernel");
  app.footer(
      "Exit status: 0 done (an empty kernel too); 2 bad usage or bad input (file:line: what\n"
      "is wrong), e.g. no polygon block or more than one, a vertex on the back side, or an\n"
      "edge clockwise along Omega.");
  return [o] { return polygon_kernel(*o); };
}

}  // namespace cmd_kernel

T2_COMMAND({"kernel", "the kernel of a scene's polygon (the points that see all of it)", cmd_kernel::setup});

}  // namespace t2cli
