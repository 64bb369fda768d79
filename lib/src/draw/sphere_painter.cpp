// The spherical model (seed 000, fig. 3.4): T² on the unit sphere, front = upper hemisphere,
// seen orthographically; the far hemisphere dashed and faded (see t2/draw/view.hpp).
#include <cmath>

#include "canvas.hpp"
#include "clip.hpp"
#include "painter.hpp"
#include "sphere_math.hpp"
#include "t2/draw/palette.hpp"

namespace t2::draw {

namespace {

/// Opacity of what lies on the far hemisphere.
constexpr double kHiddenOpacity = 0.45;

class SpherePainter final : public Painter {
 public:
  SpherePainter(const SphereView& v, Canvas& c) : v_(v), c_(c) {}

  void point(const Point& p, const Style& st) override {
    const Vec3 s = on_sphere(p);
    Shape& m = c_.marker(v_.project(s), part_of(p.w()), st, p.w() < 0);
    if (v_.depth(s) < 0) {
      m.hidden = true;
      m.opacity = kHiddenOpacity;
    }
    if (!st.label().empty()) c_.label_of(v_.project(s), st);
  }

  void line(const Line& l, const Style& st) override {
    const Vec3 n = unit({l.X(), l.Y(), l.W()});
    const Vec3 e = v_.eye();
    if (st.shade()) {
      const std::string col = st.fill().empty() ? palette::shade : st.fill();
      const auto lp = limb_points(l, v_);
      std::vector<Vec2> region;
      if (!lp) {
        if (dot(n, e) > 0) region = disk_polygon();
      } else {
        // Visible half of the great circle (through its point nearest the viewer), then the
        // half of the limb on the positive side.
        const Vec3 top = unit(e + -dot(e, n) * n);
        const Vec3 k = unit(n + -dot(n, e) * e);
        auto add = [&](const Vec3& a, const Vec3& b) {
          for (const auto& s : slerp_samples(a, b)) region.push_back(v_.project(s));
        };
        add(lp->first, top);
        add(top, lp->second);
        add(lp->second, k);
        add(k, lp->first);
      }
      if (region.size() > 2) c_.fill(region, Part::front, col, st.fill_opacity(), false);
    }
    loop(great_circle(l), st, Part::front);
    if (st.arrow() || !st.label().empty()) {
      // The visible point of the circle nearest the viewer, and the direction of travel there.
      Vec3 top = e + -dot(e, n) * n;
      if (dot(top, top) < 1e-12) return;
      top = unit(top);
      const Vec3 t = cross(n, top);  // travel direction: positive side (n) to the left
      const Vec3 ahead = unit(top + 0.5 * t);
      if (st.arrow())
        c_.arrowhead(v_.project(ahead), v_.project(ahead) - v_.project(unit(top + 0.45 * t)), st, part_of(ahead.z),
                     false);
      if (!st.label().empty()) c_.label_of(v_.project(unit(top + -0.35 * t)), st);
    }
  }

  void segment(const Point& p, const Point& q, const Style& st) override {
    arc(p, q, st, st.arrow());
    if (!st.label().empty()) c_.label_of(v_.project(arc_middle(p, q)), st);
  }

  void chain(const std::vector<Point>& pts, const Style& st, bool closed) override {
    const std::size_t n = pts.size();
    if (closed && !st.fill().empty() && n >= 3) region(dense_loop(pts), st);
    for (std::size_t i = 0; i + 1 < n; ++i) arc(pts[i], pts[i + 1], st, st.arrow() && i + 2 == n && !closed);
    if (closed && n > 2) arc(pts[n - 1], pts[0], st, false);
    if (!st.label().empty() && n >= 2 && !(pts[0] == antipode(pts[1])))  // at the middle of the first edge
      c_.label_of(v_.project(arc_middle(pts[0], pts[1])), st);
  }

  void circle(const std::vector<Point>& pts, const Style& st) override {
    std::vector<Vec3> ring;
    for (const auto& p : pts) ring.push_back(on_sphere(p));
    if (!st.fill().empty()) region(ring, st);
    loop(ring, st, part_of(pts[0].w()));
    const std::size_t k = ring.size() / 4;
    if (st.arrow()) {
      const bool vis = v_.depth(ring[k]) > 0;
      c_.arrowhead(v_.project(ring[k]), v_.project(ring[k]) - v_.project(ring[k - 1]), st, part_of(pts[0].w()), !vis);
      if (!vis) c_.shapes.back().opacity = kHiddenOpacity;
    }
    if (!st.label().empty()) c_.label_of(v_.project(ring[ring.size() / 8]), st);
  }

  void label(const Point& p, const std::string& text, const Style& st) override {
    c_.label(c_.px(v_.project(on_sphere(p))), text, st.label_angle(), 2, st.color(), st.halo());
  }

  void t1(double, double, const Style&) override {}  // T¹ is drawn by T1View only

  /// Splits a closed dense loop of unit vectors into runs on either side of the limb.
  void loop(const std::vector<Vec3>& pts, const Style& st, Part part) {
    const std::size_t n = pts.size();
    std::size_t start = 0;
    for (std::size_t i = 0; i < n; ++i)
      if ((v_.depth(pts[i]) > 0) != (v_.depth(pts[(i + n - 1) % n]) > 0)) {
        start = i;
        break;
      }
    std::vector<Vec3> cur;
    for (std::size_t k = 0; k <= n; ++k) {
      const Vec3& s = pts[(start + k) % n];
      if (!cur.empty() && (v_.depth(s) > 0) != (v_.depth(cur.back()) > 0)) {
        const Vec3 x = crossing(cur.back(), s, v_.eye());
        cur.push_back(x);
        run(cur, v_.depth(cur[cur.size() / 2]) > 0, part, st);
        cur = {x};
      }
      cur.push_back(s);
    }
    if (cur.size() > 1) run(cur, v_.depth(cur[cur.size() / 2]) > 0, part, st);
  }

 private:
  /// Draws a run of unit vectors that lies on one side of the limb.
  void run(const std::vector<Vec3>& pts, bool visible, Part part, const Style& st) {
    std::vector<Vec2> q;
    for (const auto& s : pts) q.push_back(v_.project(s));
    Shape& sh = c_.path(q, part, st);
    if (!visible) {
      sh.hidden = true;
      sh.dash = {2.5, 3};
      sh.opacity = kHiddenOpacity;
    }
  }

  /// Part of T² a run belongs to (by its midpoint: runs are not split at Ω on the sphere).
  static Part side_part(const std::vector<Vec3>& pts) { return part_of(pts[pts.size() / 2].z); }

  void arc(const Point& p, const Point& q, const Style& st, bool arrow) {
    std::vector<Vec3> last;
    bool last_vis = true;
    for (const auto& pc : split_at_limb(p, q, v_)) {
      auto pts = slerp_samples(pc.a, pc.b);
      run(pts, pc.visible, side_part(pts), st);
      last = pts;
      last_vis = pc.visible;
    }
    if (arrow && last.size() >= 2) {
      const Vec2 tip = v_.project(last.back()), prev = v_.project(last[last.size() - 2]);
      c_.arrowhead(tip, tip - prev, st, side_part(last), !last_vis);
      if (!last_vis) c_.shapes.back().opacity = kHiddenOpacity;
    }
  }

  /// Fills the visible part of a region given by its dense boundary loop (the hidden part
  /// of the boundary is replaced by the limb).
  void region(const std::vector<Vec3>& loop, const Style& st) {
    std::vector<Vec2> poly;
    for (const Vec3& s : clip_to_hemisphere(loop, v_.eye())) poly.push_back(v_.project(s));
    if (poly.size() > 2) c_.fill(poly, Part::front, st.fill(), st.fill_opacity(), false);
  }

  const SphereView& v_;
  Canvas& c_;
};

}  // namespace

std::vector<Shape> display_list(const Figure& f, const SphereView& v) {
  Canvas c = Canvas::square(v.size, 1.15);
  // The sphere: a faint disk and its outline.
  c.fill(disk_polygon(1, 360), Part::decoration, palette::sphere, 1, false);
  SpherePainter painter(v, c);
  if (v.graticule) {
    Style g;
    g.color(palette::graticule).width(0.6);
    for (int lon = 0; lon < 180; lon += 30) {
      const double a = lon * kPi / 180;
      painter.loop(great_circle(Line(0, -std::sin(a), std::cos(a))), g, Part::decoration);
    }
    for (int lat = -60; lat <= 60; lat += 30) {
      if (lat == 0) continue;
      std::vector<Vec3> ring;
      const double la = lat * kPi / 180;
      for (int i = 0; i < 360; ++i)
        ring.push_back({std::cos(la) * std::cos(i * kPi / 180), std::cos(la) * std::sin(i * kPi / 180), std::sin(la)});
      painter.loop(ring, g, Part::decoration);
    }
    for (auto& s : c.shapes)
      if (s.kind == ShapeKind::path && s.hidden) s.opacity = 0;  // only the visible grid
  }
  if (v.omega) {
    Style om;
    om.color(palette::omega).width(1.2);
    painter.loop(great_circle(Line(1, 0, 0)), om, Part::decoration);
    // "Ω" next to the equator point nearest the viewer, below it.
    const Vec3 e = v.eye();
    Vec3 near{e.x, e.y, 0};
    if (dot(near, near) > 1e-9) {
      near = unit(near);
      const Vec3 side = unit(cross({0, 0, 1}, near));
      const Vec3 at = unit(near + -1.2 * side);
      c.text(c.px(v.project(at)), "Ω", -60, 4, palette::omega, 15);
    }
  }
  Style outline;
  outline.color(palette::outline).width(1.2);
  c.path(disk_polygon(1, 360), Part::decoration, outline, true);
  return display(f, painter, c);
}

}  // namespace t2::draw
