// The figure of a scene file (see t2/draw/scene_figure.hpp).
#include "t2/draw/scene_figure.hpp"

namespace t2::draw {

SceneStyles SceneStyles::in(const std::string& colour) {
  SceneStyles s;
  s.point = Style().color(colour);
  s.segment = Style().color(colour).width(2);
  s.polygon = Style().color(colour).width(2).fill(colour);
  s.line = Style().color(colour).width(1.5).arrow();
  s.circle = Style().color(colour).width(2);
  return s;
}

void add_scene(Figure& f, const Scene& s, const SceneStyles& styles) {
  for (const auto& g : s.polygons) f.add(g.polygon(), styles.polygon);
  for (const auto& g : s.circles) {
    try {
      f.add(g.circle(), styles.circle);
    } catch (const BadInput& e) {  // a circle too large for double coordinates
      throw ParseError(s.name, g.line, e.what());
    }
  }
  for (const auto& g : s.lines) f.add(g.join(), styles.line);
  for (const auto& g : s.segments) f.add(g.segment(), styles.segment);
  for (const auto& p : s.points) f.add(p.point, Style(styles.point).label(p.label));
}

Figure figure_of(const Scene& s, const SceneStyles& styles) {
  Figure f;
  add_scene(f, s, styles);
  return f;
}

}  // namespace t2::draw
