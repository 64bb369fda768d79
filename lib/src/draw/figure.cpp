// Figures: the list of styled items (see t2/draw/figure.hpp).
#include "t2/draw/figure.hpp"

#include <cmath>
#include <numbers>

namespace t2::draw {

Figure& Figure::push(ItemKind k, std::vector<Point> pts, Style s) {
  const std::size_t n = pts.size();
  const bool chain = k == ItemKind::segment || k == ItemKind::polygon || k == ItemKind::polyline;
  if (chain) {
    for (std::size_t i = 0; i + 1 < n || (k == ItemKind::polygon && n > 2 && i < n); ++i) {
      const Point& a = pts[i];
      const Point& b = pts[(i + 1) % n];
      if (a == antipode(b)) throw Undefined("segment(p, q) is undefined when q = antipode(p)");
    }
  }
  Item it;
  it.kind = k;
  it.points = std::move(pts);
  it.style = std::move(s);
  items_.push_back(std::move(it));
  return *this;
}

Figure& Figure::add_circle(const Point& c0, const Point& p0, Sign o, Style s) {
  // Cartesian values may overflow for tiny w (checked below), so divide here, not in normalized().
  const Point& c = c0;
  const Point& p = p0;
  if (c.w() == 0 || p.w() == 0) {
    // Infinite radius. Centre on Ω: the line through p perpendicular to the centre's
    // direction. Proper centre, boundary on Ω: Ω. Either way the centre is on its left when
    // the circle is positive.
    Line l = c.w() == 0 ? join(p, Point(0, -c.y(), c.x())) : Line(c.w() > 0 ? 1 : -1, 0, 0);
    if (side(l, c) != o) l = opposite(l);
    if (!s.fill().empty()) s.shade();
    return add(l, std::move(s));
  }
  // Finite or beyond infinity: the Euclidean circle of radius |P − C| around the spot of the
  // centre, on the side of the boundary point.
  const double sigma = p.w() > 0 ? 1 : -1;
  const double cx = c.x() / c.w(), cy = c.y() / c.w(), px = p.x() / p.w(), py = p.y() / p.w();
  const double r = std::hypot(px - cx, py - cy);
  if (!std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(px) || !std::isfinite(py) || !std::isfinite(r))
    throw BadInput("a circle whose centre or radius is beyond the range of double (about 1.8e308) cannot be drawn");
  if (r == 0) return add(p, std::move(s));  // radius zero: the single point (c, or ¬c)
  // On the back side the planar picture is mirrored: T²-counter-clockwise runs clockwise there.
  const double turn = sigma * (o == POSITIVE ? 1 : -1);
  const double a0 = std::atan2(py - cy, px - cx);
  constexpr int n = 240;
  std::vector<Point> loop;
  loop.reserve(n);
  for (int k = 0; k < n; ++k) {
    const double a = a0 + turn * 2 * std::numbers::pi * k / n;
    loop.emplace_back(sigma, sigma * (cx + r * std::cos(a)), sigma * (cy + r * std::sin(a)));
  }
  return push(ItemKind::circle, std::move(loop), std::move(s));
}

}  // namespace t2::draw
