// The figure of a scene file (see t2/draw/scene_figure.hpp).
#include "t2/draw/scene_figure.hpp"

#include <initializer_list>

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

namespace {

Marker marker_named(const std::string& m) {
  if (m == "square") return Marker::square;
  if (m == "diamond") return Marker::diamond;
  if (m == "cross") return Marker::cross;
  if (m == "none") return Marker::none;
  return Marker::dot;
}

}  // namespace

Style styled(Style base, const SceneStyle& a) {
  // A filled kind (the polygon) keeps its fill in its own colour unless `fill` says otherwise.
  if (a.color && !a.fill && !base.fill().empty()) base.fill(*a.color);
  if (a.color) base.color(*a.color);
  if (a.width) base.width(*a.width);
  if (a.dash) base.dash(*a.dash);
  if (a.fill) base.fill(*a.fill);
  if (a.opacity) base.fill_opacity(*a.opacity);
  if (a.marker) base.marker(marker_named(*a.marker));
  if (a.size) base.size(*a.size);
  if (a.label) base.label(*a.label);
  if (a.label_angle) base.label_angle(*a.label_angle);
  if (a.layer) base.layer(*a.layer);
  if (a.arrow) base.arrow(*a.arrow);
  if (a.shade) base.shade(*a.shade);
  return base;
}

namespace {

// GeoLab's handles: a small square at each point that defines the object, in its colour.
void add_handles(Figure& f, const SceneStyle& a, const Style& st, std::initializer_list<const ScenePoint*> pts) {
  if (!a.handles.value_or(false)) return;
  for (const ScenePoint* p : pts)
    f.add(p->point, Style().color(st.color()).marker(Marker::square).size(2.5).layer(st.layer()));
}

}  // namespace

void add_scene(Figure& f, const Scene& s, const SceneStyles& styles) {
  for (const auto& g : s.polygons) {
    const Style st = styled(styles.polygon, g.style);
    f.add(g.polygon(), st);
    if (g.style.handles.value_or(false))
      for (const auto& v : g.vertices) add_handles(f, g.style, st, {&v});
  }
  for (const auto& g : s.circles) {
    const Style st = styled(styles.circle, g.style);
    try {
      f.add(g.circle(), st);
    } catch (const BadInput& e) {  // a circle too large for double coordinates
      throw ParseError(s.name, g.line, e.what());
    }
    add_handles(f, g.style, st, {&g.center, &g.through});
  }
  for (const auto& g : s.lines) {
    const Style st = styled(styles.line, g.style);
    f.add(g.join(), st);
    add_handles(f, g.style, st, {&g.a, &g.b});
  }
  for (const auto& g : s.segments) {
    const Style st = styled(styles.segment, g.style);
    f.add(g.segment(), st);
    add_handles(f, g.style, st, {&g.a, &g.b});
  }
  for (const auto& p : s.points) f.add(p.point, styled(Style(styles.point).label(p.label), p.style));
}

Figure figure_of(const Scene& s, const SceneStyles& styles) {
  Figure f;
  add_scene(f, s, styles);
  return f;
}

}  // namespace t2::draw
