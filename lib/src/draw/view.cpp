// Projection mathematics of the planar and spherical models (see t2/draw/view.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "t2/draw/view.hpp"
#include "t2/kernel/error.hpp"

namespace t2::draw {

namespace {
constexpr double kDeg = std::numbers::pi / 180;
}  // namespace

Vec3 on_sphere(const Point& p) { return unit_scaled({p.x(), p.y(), p.w()}); }

Vec2 PlaneView::to_unit(double x, double y) const { return {(x - cx) / half_width, (y - cy) / half_width}; }

Vec2 PlaneView::place(const Point& p) const {
  if (p.w() != 0) {
    // x/w and y/w may overflow for tiny w: such a point is far outside the disk anyway.
    const double x = p.x() / p.w(), y = p.y() / p.w();
    if (std::isfinite(x) && std::isfinite(y)) return to_unit(x, y);
  }
  const double m = std::hypot(p.x(), p.y());
  if (p.w() == 0) return {ring * p.x() / m, ring * p.y() / m};
  return {1e6 * p.x() / m * (p.w() > 0 ? 1 : -1), 1e6 * p.y() / m * (p.w() > 0 ? 1 : -1)};
}

Vec3 SphereView::eye() const {
  return {std::cos(lat * kDeg) * std::cos(lon * kDeg), std::cos(lat * kDeg) * std::sin(lon * kDeg),
          std::sin(lat * kDeg)};
}

SphereView facing(const std::vector<Point>& pts, SphereView base) {
  Vec3 m{0, 0, 0};
  for (const Point& p : pts) {
    const Vec3 s = on_sphere(p);
    m = {m.x + s.x, m.y + s.y, m.z + s.z};
  }
  const double r = std::sqrt(m.x * m.x + m.y * m.y + m.z * m.z);
  if (!(r > 1e-9 * static_cast<double>(pts.size()))) return base;
  base.lat = std::asin(std::clamp(m.z / r, -1.0, 1.0)) / kDeg;
  base.lon = std::atan2(m.y, m.x) / kDeg;
  if (std::abs(base.lat) > 80) {  // near a pole: the planar model's turn, not the mean's whim
    base.lat = base.lat > 0 ? 90 : -90;
    base.lon = -90;
  }
  return base;
}

std::pair<Vec3, Vec3> SphereView::screen_axes() const {
  const Vec3 right{-std::sin(lon * kDeg), std::cos(lon * kDeg), 0};
  const Vec3 up{-std::sin(lat * kDeg) * std::cos(lon * kDeg), -std::sin(lat * kDeg) * std::sin(lon * kDeg),
                std::cos(lat * kDeg)};
  return {right, up};
}

Vec2 SphereView::project(const Vec3& s) const {
  const auto [r, u] = screen_axes();
  return {dot(s, r), dot(s, u)};
}

double SphereView::depth(const Vec3& s) const { return dot(s, eye()); }

std::optional<std::pair<Vec3, Vec3>> limb_points(const Line& l, const SphereView& v) {
  const Vec3 n = unit_scaled({l.X(), l.Y(), l.W()});
  const Vec3 m = cross(n, v.eye());
  if (dot(m, m) == 0) return std::nullopt;
  const Vec3 a = unit_scaled(m);
  return std::pair{a, -a};
}

Ellipse great_circle_ellipse(const Line& l, const SphereView& v) {
  const Vec3 n = unit_scaled({l.X(), l.Y(), l.W()});
  const auto lp = limb_points(l, v);
  if (!lp) return {{1, 0}, 1};  // the circle is the limb: the outline itself
  const Vec2 a = v.project(lp->first);
  const double m = norm(a);
  return {{a.x / m, a.y / m}, std::fabs(dot(n, v.eye()))};
}

std::vector<ArcPiece> split_at_limb(const Point& p, const Point& q, const SphereView& v) {
  if (p == antipode(q)) throw Undefined("segment(p, q) is undefined when q = antipode(p)");
  const Vec3 a = on_sphere(p), b = on_sphere(q);
  const double da = v.depth(a), db = v.depth(b);
  if ((da > 0 && db < 0) || (da < 0 && db > 0)) {
    // The point |db|·a + |da|·b lies on the arc (positive combination) and has depth 0.
    const Vec3 c = unit_scaled(std::fabs(db) * a + std::fabs(da) * b);
    return {{a, c, da > 0}, {c, b, db > 0}};
  }
  return {{a, b, da > 0 || db > 0 || (da == 0 && db == 0)}};
}

}  // namespace t2::draw
