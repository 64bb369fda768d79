// The planar model (seed 000, fig. 3.3): both sides of T² drawn over one disk of the plane,
// Ω as a ring around it (see t2/draw/view.hpp and t2/draw/render.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "canvas.hpp"
#include "clip.hpp"
#include "painter.hpp"
#include "sphere_math.hpp"
#include "t2/draw/palette.hpp"
#include "t2/kernel/segment.hpp"

namespace t2::draw {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

class PlanePainter final : public Painter {
 public:
  PlanePainter(const PlaneView& v, Canvas& c) : v_(v), c_(c) {}

  void point(const Point& p, const Style& st) override {
    const Vec2 q = v_.place(p);
    if (norm(q) > (p.w() == 0 ? 2.0 : 1.0)) return;  // outside the shown disk
    c_.marker(q, part_of(p.w()), st, p.w() < 0);
    if (!st.label().empty()) c_.label_of(q, st);
  }

  void line(const Line& l, const Style& st) override {
    const double W = l.W(), X = l.X(), Y = l.Y();
    const double k = W + X * v_.cx + Y * v_.cy;  // the line in unit coordinates: k + hw (X u + Y v) = 0
    if (st.shade()) {
      const std::string col = st.fill().empty() ? palette::shade : st.fill();
      const Vec2 n{v_.half_width * X, v_.half_width * Y};
      if (X == 0 && Y == 0) {
        c_.fill(disk_polygon(), W > 0 ? Part::front : Part::back, col, st.fill_opacity(), W < 0);
      } else {
        auto front = clip_half(disk_polygon(), k, n);
        if (front.size() > 2) c_.fill(front, Part::front, col, st.fill_opacity(), false);
        auto back = clip_half(disk_polygon(), -k, -n);
        if (back.size() > 2) c_.fill(back, Part::back, col, back_opacity(st), true);
      }
    }
    if (X == 0 && Y == 0) {  // Ω itself
      Style thick = st;
      thick.width(st.width() + 1.2);
      c_.path(disk_polygon(PlaneView::ring), Part::infinity, thick, true);
      if (!st.label().empty()) c_.label_of(PlaneView::ring * Vec2{std::cos(-0.3 * kPi), std::sin(-0.3 * kPi)}, st);
      return;
    }
    const double m = std::hypot(X, Y);
    const Vec2 d{Y / m, -X / m};  // direction of travel of the front copy (positive side to the left)
    const Vec2 F = (-k / (v_.half_width * m)) * Vec2{X / m, Y / m};  // foot of the perpendicular
    Vec2 a, b;
    if (clip_disk(F, d, -kInf, kInf, a, b)) {
      c_.path({b, a}, Part::back, st);  // the back copy, under the front one, travels backwards
      c_.path({a, b}, Part::front, st);
      if (st.arrow()) {
        c_.arrowhead(b, d, st, Part::front, false);
        c_.arrowhead(a, -d, st, Part::back, true);
      }
      if (!st.label().empty()) c_.label_of(a + 0.75 * (b - a), st);
    }
    // Its two points at infinity, on the ring.
    Style small = st;
    small.size(2.6).marker(Marker::dot);
    c_.marker(PlaneView::ring * d, Part::infinity, small, false);
    c_.marker(-PlaneView::ring * d, Part::infinity, small, false);
  }

  void segment(const Point& p, const Point& q, const Style& st) override {
    arc(p, q, st, st.arrow());
    if (!st.label().empty()) label_arc(p, q, st);
  }

  /// Queues the label of `st` at the middle of the arc from p to q, when it is shown.
  void label_arc(const Point& p, const Point& q, const Style& st) {
    if (p == antipode(q)) return;
    const Vec3 m = arc_middle(p, q);
    const Vec2 at = v_.place(Point(m.z, m.x, m.y));
    if (norm(at) <= 1.3) c_.label_of(at, st);
  }

  void chain(const std::vector<Point>& pts, const Style& st, bool closed) override {
    const std::size_t n = pts.size();
    if (closed && !st.fill().empty() && n >= 3) {
      const bool all_front = std::all_of(pts.begin(), pts.end(), [](const Point& p) { return p.w() > 0; });
      const bool all_back = std::all_of(pts.begin(), pts.end(), [](const Point& p) { return p.w() < 0; });
      if (all_front || all_back) {
        std::vector<Vec2> poly;
        for (const auto& p : pts) poly.push_back(v_.place(p));
        fill_side(std::move(poly), all_front ? Part::front : Part::back, st);
      } else {
        region(dense_loop(pts), st);
      }
    }
    for (std::size_t i = 0; i + 1 < n; ++i) arc(pts[i], pts[i + 1], st, st.arrow() && i + 2 == n && !closed);
    if (closed && n > 2) arc(pts[n - 1], pts[0], st, false);
    if (!st.label().empty() && n >= 2) label_arc(pts[0], pts[1], st);  // at the middle of the first edge
  }

  void circle(const std::vector<Point>& pts, const Style& st) override {
    const Part part = part_of(pts[0].w());
    std::vector<Vec2> q;
    for (const auto& p : pts) q.push_back(v_.place(p));
    if (!st.fill().empty()) fill_side(q, part, st);
    // The stroke: the runs of the loop inside the shown disk, cut exactly at its edge.
    const std::size_t n = q.size();
    std::size_t start = 0;
    while (start < n && norm(q[start]) <= 1) ++start;
    if (start == n) {
      c_.path(q, part, st, true);
    } else {
      std::vector<Vec2> run;
      for (std::size_t k = 1; k <= n; ++k) {
        const Vec2 a = q[(start + k - 1) % n], b = q[(start + k) % n];
        Vec2 u, w;
        if (!clip_disk(a, b - a, 0, 1, u, w)) continue;
        if (!run.empty() && norm(run.back() - u) > 1e-12) {
          c_.path(run, part, st);
          run.clear();
        }
        if (run.empty()) run.push_back(u);
        run.push_back(w);
      }
      if (run.size() > 1) c_.path(run, part, st);
    }
    const std::size_t k = n / 4;
    if (st.arrow() && norm(q[k]) <= 1) c_.arrowhead(q[k], q[k] - q[k - 1], st, part, part == Part::back);
    if (!st.label().empty() && norm(q[n / 8]) <= 1) c_.label_of(q[n / 8], st);
  }

  void label(const Point& p, const std::string& text, const Style& st) override {
    const Vec2 q = v_.place(p);
    if (norm(q) <= 1.3) c_.label(c_.px(q), text, st.label_angle(), 2, st.color(), st.halo());
  }

  void t1(double, double, const Style&) override {}  // T¹ is drawn by T1View only

 private:
  /// The segment of T² from p to q (not antipodal): the pieces the geometry splits it into
  /// where it crosses Ω (`planar_pieces`), or the shorter arc of the ring when both are on Ω.
  void arc(const Point& p0, const Point& q0, const Style& st, bool arrow) {
    const Point p = drawable(p0), q = drawable(q0);
    if (p == antipode(q)) return;  // two points rounded onto antipodes: no segment to draw
    if (p.w() == 0 && q.w() == 0) {
      ring_arc(p, q, st, arrow);
      return;
    }
    const auto pieces = planar_pieces(Segment(p, q));
    for (std::size_t i = 0; i < pieces.size(); ++i)
      half(pieces[i].source(), pieces[i].target(), st, arrow && i + 1 == pieces.size());
  }

  /// A segment within one side, or a half-ray between one side and Ω, clipped to the disk.
  void half(const Point& p, const Point& q, const Style& st, bool arrow) {
    const double wp = p.w(), wq = q.w();
    const Part part = part_of(wp != 0 ? wp : wq);
    Vec2 a, b;
    if (wp != 0) {  // from p to q, or from p towards the point q of Ω
      const Vec2 P = v_.place(p);
      const Vec2 D = wq != 0 ? v_.place(q) - P : (wp > 0 ? 1.0 : -1.0) * unit(Vec2{q.x(), q.y()});
      if (!clip_disk(P, D, 0, wq != 0 ? 1 : kInf, a, b)) return;
      c_.path({a, b}, part, st);
      if (arrow) c_.arrowhead(b, D, st, part, part == Part::back);
    } else {  // from the point p of Ω to q: drawn from q outwards, the arrow at q when shown
      const Vec2 Q = v_.place(q), D = (wq > 0 ? 1.0 : -1.0) * unit(Vec2{p.x(), p.y()});
      if (!clip_disk(Q, D, 0, kInf, a, b)) return;
      c_.path({a, b}, part, st);
      if (arrow && norm(Q) <= 1) c_.arrowhead(a, -D, st, part, part == Part::back);
    }
  }

  /// The shorter arc of the Ω ring from p to q (both on Ω), drawn thicker.
  void ring_arc(const Point& p, const Point& q, const Style& st, bool arrow) {
    const double a0 = std::atan2(p.y(), p.x());
    double a1 = std::atan2(q.y(), q.x());
    if (a1 - a0 > kPi) a1 -= 2 * kPi;
    if (a0 - a1 > kPi) a1 += 2 * kPi;
    std::vector<Vec2> pts;
    const int n = std::max(2, static_cast<int>(std::fabs(a1 - a0) / 0.02));
    for (int i = 0; i <= n; ++i) {
      const double a = a0 + (a1 - a0) * i / n;
      pts.push_back({PlaneView::ring * std::cos(a), PlaneView::ring * std::sin(a)});
    }
    Style thick = st;
    thick.width(st.width() + 1.2);
    c_.path(pts, Part::infinity, thick);
    if (arrow) c_.arrowhead(pts.back(), pts.back() - pts[pts.size() - 2], st, Part::infinity, false);
  }

  /// Fills a region of T² given by its dense boundary loop: its front part solid, its back
  /// part hatched (each clipped to the shown disk; Ω is pushed far out, beyond the disk).
  void region(const std::vector<Vec3>& loop, const Style& st) {
    for (const double s : {1.0, -1.0}) {
      std::vector<Vec2> poly;
      for (const Vec3& p : clip_to_hemisphere(loop, {0, 0, s})) {
        const double w = s > 0 ? std::max(p.z, 1e-9) : std::min(p.z, -1e-9);
        poly.push_back(v_.to_unit(p.x / w, p.y / w));
      }
      fill_side(std::move(poly), s > 0 ? Part::front : Part::back, st);
    }
  }

  /// Fills the part of a polygon (unit coordinates) inside the shown disk: solid on the
  /// front, hatched on the back.
  void fill_side(std::vector<Vec2> poly, Part part, const Style& st) {
    poly = clip_poly_disk(std::move(poly));
    if (poly.size() > 2)
      c_.fill(poly, part, st.fill(), part == Part::back ? back_opacity(st) : st.fill_opacity(), part == Part::back);
  }

  const PlaneView& v_;
  Canvas& c_;
};

}  // namespace

std::vector<Shape> display_list(const Figure& f, const PlaneView& v) {
  Canvas c = Canvas::square(v.size, 1.2);
  Style faint;
  faint.color(palette::disk_edge).width(0.8);
  c.path(disk_polygon(), Part::decoration, faint, true);
  if (v.axes) {
    Style ax;
    ax.color(palette::axis).width(0.8);
    const Vec2 o = v.to_unit(0, 0);
    Vec2 a, b;
    if (clip_disk(o, {1, 0}, -kInf, kInf, a, b)) c.path({a, b}, Part::decoration, ax);
    if (clip_disk(o, {0, 1}, -kInf, kInf, a, b)) c.path({a, b}, Part::decoration, ax);
  }
  if (v.omega) {
    Style ring;
    ring.color(palette::omega).width(1.2);
    c.path(disk_polygon(PlaneView::ring), Part::decoration, ring, true);
    const double a = 0.3 * kPi;
    c.text(c.px({PlaneView::ring * std::cos(a), PlaneView::ring * std::sin(a)}), "Ω", 55, 5, palette::omega, 15);
  }
  PlanePainter painter(v, c);
  return display(f, painter, c);
}

}  // namespace t2::draw
