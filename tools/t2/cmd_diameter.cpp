// t2 diameter: a farthest pair of a scene's points (t2/hull/diameter.hpp) and, for points of one
// side, the width (t2/hull/calipers.hpp).
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/hull/calipers.hpp"
#include "t2/hull/diameter.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/line.hpp"

namespace t2cli {
namespace cmd_diameter {

namespace dr = t2::draw;

struct Options {
  std::string file;
  AnswerDrawing drawing;
};

bool one_side(const std::vector<t2::Point>& P) {
  for (const auto& p : P)
    if (p.w() == 0 || (p.w() < 0) != (P[0].w() < 0)) return false;
  return true;
}

// d²(a, b) as "[w, x]" scaled to |w| = 1 (or x = 1 on Ω), from the exact value, rounded once.
std::string squared(const t2::Point& a, const t2::Point& b) {
  const t2::ExactT1 d = t2::squared_distance(t2::to_exact(a), t2::to_exact(b));
  if (d.w() == 0) return "[0, 1]";
  const t2::Rational x = t2::Rational(d.x()) / t2::Rational(abs(d.w()));
  return fmt::format("[{}, {}]", d.w() > 0 ? 1 : -1, t2::to_string(x.get_d()));
}

// The answer as a scene: the farthest pair in red (its segment and its points, labelled pK) and,
// when there is one, the narrowest strip: the edge's line and its parallel through the vertex
// (through the same point of Ω), in blue.
t2::Scene answer(const std::vector<t2::Point>& P, std::size_t a, std::size_t b, const t2::Width* w) {
  t2::Scene s;
  if (w) {
    const auto edge = t2::join(P[w->from], P[w->to]);
    const t2::SceneStyle blue = style_of("color=blue width=1 arrow=no layer=0");
    s.lines.push_back(t2::SceneLine{scene_point(P[w->from]), scene_point(P[w->to]), 0, blue});
    s.lines.push_back(t2::SceneLine{scene_point(P[w->vertex]), scene_point(t2::meet(edge, t2::omega<double>())), 0, blue});
  }
  if (!(P[a] == P[b]) && !(P[a] == t2::antipode(P[b])))
    s.segments.push_back(t2::SceneSegment{scene_point(P[a]), scene_point(P[b]), 0, style_of("color=red width=2.5 layer=1")});
  for (std::size_t i : {a, b}) {
    t2::SceneStyle st = style_of("color=red size=4.5 layer=3");
    st.label = fmt::format("p{}", i);
    s.points.push_back(scene_point(P[i], st));
  }
  if (a == b) s.points.pop_back();
  return s;
}

int diameter(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  std::optional<std::pair<std::size_t, std::size_t>> d;
  try {
    d = t2::diameter(P);
  } catch (const t2::Undefined& e) {
    throw t2::Undefined(fmt::format("{}: {}", scene.name, e.what()));
  }
  if (!d) return kOk;  // no point, no answer
  const auto [a, b] = *d;
  const bool same = P[a] == P[b];
  const std::optional<t2::Width> w = !P.empty() && one_side(P) ? t2::width(P) : std::nullopt;
  std::string out = fmt::format("{} {}\nsquared-distance {}\n", a, b, same ? "[1, 0]" : squared(P[a], P[b]));
  if (w) out += fmt::format("width {} {} {}\n", w->from, w->to, w->vertex);
  write_answer(o.drawing, scene, answer(P, a, b, w ? &*w : nullptr),
               fmt::format("t2 diameter {}: the farthest pair p{} p{}{} (draw it over its input: t2 draw FILE THIS)",
                           scene.name, a, b, w ? " and the narrowest strip" : ""));
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints a farthest pair of the points of the scene file FILE (- for standard input), as\n"
      "'a b' (0-based indices of the scene's points, bare and labelled, in file order), then\n"
      "'squared-distance [w, x]': the squared distance as a point of T1 (rounded once from the\n"
      "exact value): [1, d2] on one side, [0, 1] = +infinity from a point of Omega, [-1, d2]\n"
      "'beyond infinity' between a front and a back point (the farthest such pair is the one\n"
      "nearest as drawn; a point and its antipode, [-1, 0], are the farthest of all). For\n"
      "proper points of one side with a hull of 3 or more vertices, a third line 'width i j k':\n"
      "the narrowest strip holding the points has one side along the hull edge i -> j and the\n"
      "other through point k. No point: nothing.");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  add_drawing_options(app, o->drawing, "the points, the pair and the strip");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 two\n"
      "different points lie on Omega: their distance is an angle, not a value of T1, so\n"
      "there is no largest distance.");
  return [o] { return diameter(*o); };
}

}  // namespace cmd_diameter

T2_COMMAND({"diameter", "a farthest pair of a scene's points (and the width)", cmd_diameter::setup});

}  // namespace t2cli
