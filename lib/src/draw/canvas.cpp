// The canvas of the painters (see canvas.hpp).
#include "canvas.hpp"

#include <algorithm>
#include <cmath>

#include "sphere_math.hpp"
#include "t2/draw/palette.hpp"

namespace t2::draw {

Point drawable(const Point& p) {
  if (p.w() != 0 && (!std::isfinite(p.x() / p.w()) || !std::isfinite(p.y() / p.w())))
    return normalized(Point(0, p.x(), p.y()));
  return normalized(p);
}

double back_opacity(const Style& st) { return std::min(1.0, st.fill_opacity() * 2.5); }

void Canvas::label(Vec2 at, const std::string& t, double angle, double gap, const std::string& colour, bool halo) {
  if (!t.empty()) pending.push_back({at, t, angle, gap, colour, halo});
}

Shape& Canvas::path(const std::vector<Vec2>& pts, Part part, const Style& st, bool closed) {
  Shape s;
  s.kind = ShapeKind::path;
  s.part = part;
  for (const auto& p : pts) s.pts.push_back(px(p));
  s.closed = closed;
  s.stroke = st.color();
  s.width = st.width();
  s.dash = st.dash();
  if (part == Part::back) s.dash = {5 * std::max(1.0, st.width() / 1.6), 4 * std::max(1.0, st.width() / 1.6)};
  shapes.push_back(std::move(s));
  return shapes.back();
}

Shape& Canvas::fill(const std::vector<Vec2>& pts, Part part, const std::string& colour, double opacity, bool hatch) {
  Shape s;
  s.kind = ShapeKind::path;
  s.part = part;
  for (const auto& p : pts) s.pts.push_back(px(p));
  s.closed = true;
  s.fill = colour;
  s.fill_opacity = opacity;
  s.hatch = hatch;
  shapes.push_back(std::move(s));
  return shapes.back();
}

Shape& Canvas::marker(Vec2 at, Part part, const Style& st, bool hollow) {
  Shape s;
  s.kind = ShapeKind::marker;
  s.part = part;
  s.pts = {px(at)};
  s.marker = st.marker();
  // A back point is a dashed ring, a little larger than a front dot and not filled, so that
  // p and ¬p, drawn at the same spot, are both seen: a dot inside a dashed ring.
  s.radius = hollow ? st.size() + 1.5 : st.size();
  s.stroke = st.color();
  s.width = 1.3;
  s.hollow = hollow;
  s.fill = hollow ? "" : st.color();
  if (hollow) s.dash = {2.2, 1.6};
  shapes.push_back(std::move(s));
  return shapes.back();
}

Shape& Canvas::text(Vec2 at, const std::string& t, double deg, double gap, const std::string& colour, double size) {
  const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
  Shape sh;
  sh.kind = ShapeKind::text;
  sh.part = Part::decoration;
  sh.text = t;
  sh.font_size = size;
  sh.stroke = colour;
  sh.halign = c > 0.35 ? -1 : (c < -0.35 ? 1 : 0);
  // Reference point: the text's vertical middle sits gap pixels away, plus half a line
  // height when the label is above or below, so that the glyphs never reach the anchor.
  const double x = at.x + gap * c;
  const double y = at.y - gap * s - 0.45 * size * s + 0.36 * size;
  sh.pts = {{x, y}};
  shapes.push_back(std::move(sh));
  return shapes.back();
}

void Canvas::arrowhead(Vec2 tip, Vec2 dir, const Style& st, Part part, bool hollow) {
  const Vec2 t = px(tip);
  const double dx = dir.x, dy = -dir.y, m = std::hypot(dx, dy);
  if (m == 0) return;
  const double ux = dx / m, uy = dy / m, L = 9 + 1.5 * st.width(), W = 4 + 0.6 * st.width();
  Shape s;
  s.kind = ShapeKind::path;
  s.part = part;
  s.pts = {{t.x, t.y}, {t.x - L * ux - W * uy, t.y - L * uy + W * ux}, {t.x - L * ux + W * uy, t.y - L * uy - W * ux}};
  s.closed = true;
  s.stroke = st.color();
  s.width = 1;
  s.fill = hollow ? palette::white : st.color();
  shapes.push_back(std::move(s));
}

void add_title(Canvas& c, const Figure& f, double width) {
  if (f.title().empty()) return;
  for (Shape& s : c.shapes)
    for (Vec2& p : s.pts) p.y += title_band;
  c.text({width / 2.0, title_band / 2}, f.title(), 0, 0, palette::black, 14).halign = 0;
}

}  // namespace t2::draw
