// t2 layers: the convex layers of a scene's points (t2/hull/layers.hpp), one line per layer.
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "model_picture.hpp"
#include "scene_argument.hpp"
#include "t2/hull/layers.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli {
namespace cmd_layers {

namespace dr = t2::draw;

struct Options {
  std::string file, method = "jarvis";
  AnswerDrawing drawing;
};

// The layers as a scene: one polygon (a segment, a point) per layer, outermost first, in the
// colours of the palette in turn, labelled L1, L2, ...
t2::Scene answer(const std::vector<t2::Point>& P, const std::vector<std::vector<std::size_t>>& L) {
  static const char* colours[] = {"blue", "orange", "green", "red", "purple", "brown"};
  t2::Scene s;
  for (std::size_t j = 0; j < L.size(); ++j) {
    std::vector<t2::ScenePoint> h;
    for (std::size_t i : L[j]) h.push_back(scene_point(P[i]));
    t2::SceneStyle st = style_of(fmt::format("color={} layer=0", colours[j % 6]));
    st.label = fmt::format("L{}", j + 1);
    if (h.size() >= 3) {
      st.width = 2, st.fill = "";
      s.polygons.push_back(t2::ScenePolygon{h, 0, st});
    } else if (h.size() == 2) {
      st.width = 2;
      s.segments.push_back(t2::SceneSegment{h[0], h[1], 0, st});
    } else {
      st.size = 4.5;
      s.points.push_back(scene_point(h[0].point, st));
    }
  }
  return s;
}

int layers(const Options& o) {
  const t2::Scene scene = read_scene_argument(o.file);
  const std::vector<t2::Point> P = scene_points(scene);
  std::vector<std::vector<std::size_t>> L;
  try {
    L = t2::convex_layers(P, o.method == t2::name(t2::LayersMethod::graham) ? t2::LayersMethod::graham
                                                                            : t2::LayersMethod::jarvis);
  } catch (const t2::NoHull& e) {
    throw t2::Undefined(fmt::format("{}: no convex layers: {}", scene.name, e.what()));
  }
  write_answer(o.drawing, scene, answer(P, L),
               fmt::format("t2 layers {}: {} convex layers (draw them over their input: t2 draw FILE THIS)",
                           scene.name, L.size()));
  std::string out;
  for (const auto& layer : L) {
    for (std::size_t k = 0; k < layer.size(); ++k) out += (k ? " " : "") + std::to_string(layer[k]);
    out += '\n';
  }
  fmt::print("{}", out);
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Prints the convex layers of the points of the scene file FILE (- for standard input):\n"
      "one line per layer, outermost first, each the 0-based indices of its strict hull\n"
      "vertices among the scene's points (bare and labelled, in file order), counter-clockwise\n"
      "in T2, separated by spaces. Layer j+1 is the hull of what layer j left: a point inside\n"
      "a hull edge goes one layer deeper; equal points leave together (one index is printed).");
  app.add_option("FILE", o->file, "the scene file, - for standard input")->required();
  app.add_option("--method", o->method,
                 "jarvis (default: repeated Jarvis marches, O(n^2)) or graham (repeated Graham\n"
                 "scans, O(n^2 log n)): the two ways of seed 003, with the same answer")
      ->type_name("M")
      ->check(IsMember(names_of(t2::layers_methods)));
  add_drawing_options(app, o->drawing, "the points and the layers");
  app.footer(
      "Exit status: 0 done; 2 bad usage or bad input (file:line: what is wrong); 3 the\n"
      "points lie in no open hemisphere, so not even the outer layer exists (the message\n"
      "names points that prove it, e.g. 'p3 and p7 are antipodal').");
  return [o] { return layers(*o); };
}

}  // namespace cmd_layers

T2_COMMAND({"layers", "the convex layers of a scene's points (one line per layer)", cmd_layers::setup});

}  // namespace t2cli
