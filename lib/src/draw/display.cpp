// Display lists: the rules of the planar, spherical and T¹ models (see t2/draw/render.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "t2/draw/render.hpp"
#include "t2/error.hpp"

namespace t2::draw {

namespace {

constexpr double kPi = std::numbers::pi;
const char* const kGrey = "#8c8c8c";
const char* const kLightGrey = "#c8c8c8";
const char* const kShade = "#9ecae1";

// ---------------------------------------------------------------- vectors
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 scaled(const Vec3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
Vec3 plus(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 unit(const Vec3& a) {
  const double n = std::sqrt(dot(a, a));
  return {a.x / n, a.y / n, a.z / n};
}
/// Points of the shorter great arc from a to b (unit vectors, not antipodal), every ~1.5°.
std::vector<Vec3> slerp_samples(const Vec3& a, const Vec3& b) {
  const double ang = std::atan2(std::sqrt(dot(cross(a, b), cross(a, b))), dot(a, b));
  const int n = std::max(1, static_cast<int>(std::ceil(ang / (1.5 * kPi / 180))));
  std::vector<Vec3> out{a};
  if (ang == 0) {
    out.push_back(b);
    return out;
  }
  // Orthonormal frame of the arc's plane: a and the unit vector towards b perpendicular to a.
  const Vec3 perp = unit(plus(b, scaled(a, -dot(a, b))));
  for (int i = 1; i < n; ++i) {
    const double t = ang * i / n;
    out.push_back(plus(scaled(a, std::cos(t)), scaled(perp, std::sin(t))));
  }
  out.push_back(b);
  return out;
}

/// The dense closed loop of unit vectors along a closed chain of T² segments.
std::vector<Vec3> dense_loop(const std::vector<Point>& pts) {
  std::vector<Vec3> dense;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i) {
    auto s = slerp_samples(on_sphere(pts[i]), on_sphere(pts[(i + 1) % n]));
    dense.insert(dense.end(), s.begin(), s.end() - 1);
  }
  return dense;
}

/// The point where the short arc from a to b crosses the great circle ⟂ axis, for a and b on
/// different sides of it (interpolated: a and b are samples a degree or two apart).
Vec3 crossing(const Vec3& a, const Vec3& b, const Vec3& axis) {
  const double da = std::fabs(dot(a, axis)), db = std::fabs(dot(b, axis));
  return unit(plus(scaled(a, db), scaled(b, da)));
}

/// The part of the region bounded by `loop` that lies on the side s · axis ≥ 0, as a closed
/// loop: the loop where it is on that side, and between the point E where it leaves and the
/// point F where it comes back, the shorter arc from E to F of the great circle ⟂ axis. That
/// is exact for the regions drawn here (convex, less than a hemisphere: such a region meets a
/// great circle in one arc shorter than a half circle). Empty when no point of the loop is
/// strictly on that side (a region of less than a hemisphere bounded there has no part on it).
/// Projected by a map that is one-to-one on that hemisphere (orthographic from `axis`, or
/// central for the planar model), the result bounds the visible part.
std::vector<Vec3> clip_to_hemisphere(const std::vector<Vec3>& loop, const Vec3& axis) {
  std::vector<Vec3> out;
  const std::size_t n = loop.size();
  std::size_t start = n;
  for (std::size_t i = 0; i < n && start == n; ++i)
    if (dot(loop[i], axis) > 0) start = i;
  if (start == n) return out;
  std::optional<Vec3> exit;  // set while the loop is on the other side
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 &a = loop[(start + k) % n], &b = loop[(start + k + 1) % n];
    const bool in_a = dot(a, axis) >= 0, in_b = dot(b, axis) >= 0;
    if (in_a) out.push_back(a);
    if (in_a && !in_b) exit = crossing(a, b, axis);
    if (!in_a && in_b) {
      const Vec3 entry = crossing(a, b, axis);
      const auto arc = slerp_samples(*exit, entry);  // along the great circle ⟂ axis
      out.insert(out.end(), arc.begin(), arc.end());
      exit.reset();
    }
  }
  return out;
}

// ---------------------------------------------------------------- 2-D helpers
struct V2 {
  double x, y;
};
V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
V2 operator*(double s, V2 a) { return {s * a.x, s * a.y}; }
double dot2(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
double norm2(V2 a) { return std::hypot(a.x, a.y); }
V2 unit2(V2 a) { return (1 / norm2(a)) * a; }

/// Clips the parametric line P + tD, t in [t0, t1] (possibly infinite), to the unit disk.
bool clip_disk(V2 P, V2 D, double t0, double t1, V2& a, V2& b) {
  const double A = dot2(D, D), B = 2 * dot2(P, D), C = dot2(P, P) - 1;
  if (A == 0) return false;
  const double disc = B * B - 4 * A * C;
  if (disc <= 0) return false;
  const double s = std::sqrt(disc);
  const double lo = std::max(t0, (-B - s) / (2 * A)), hi = std::min(t1, (-B + s) / (2 * A));
  if (!(lo < hi)) return false;
  a = P + lo * D;
  b = P + hi * D;
  return true;
}

/// The unit disk as a polygon.
std::vector<V2> disk_polygon(double r = 1, int n = 180) {
  std::vector<V2> v;
  for (int i = 0; i < n; ++i) v.push_back({r * std::cos(2 * kPi * i / n), r * std::sin(2 * kPi * i / n)});
  return v;
}

/// Sutherland–Hodgman: the part of polygon `poly` where k + n·x >= 0.
std::vector<V2> clip_half(const std::vector<V2>& poly, double k, V2 n) {
  std::vector<V2> out;
  const std::size_t m = poly.size();
  for (std::size_t i = 0; i < m; ++i) {
    const V2 a = poly[i], b = poly[(i + 1) % m];
    const double fa = k + dot2(n, a), fb = k + dot2(n, b);
    if (fa >= 0) out.push_back(a);
    if ((fa >= 0) != (fb >= 0)) out.push_back(a + (fa / (fa - fb)) * (b - a));
  }
  return out;
}

/// Clips a polygon to the unit disk (the disk is convex: clip by each edge of its polygon).
std::vector<V2> clip_poly_disk(std::vector<V2> poly) {
  const int n = 180;
  for (int i = 0; i < n && !poly.empty(); ++i) {
    const double a = 2 * kPi * (i + 0.5) / n;
    const V2 nn{-std::cos(a), -std::sin(a)};
    poly = clip_half(poly, std::cos(kPi / n), nn);
  }
  return poly;
}

// ---------------------------------------------------------------- the canvas
/// Maps model units to pixels and collects shapes.
struct Pending {
  Pixel at;
  std::string text;
  double angle;  // NaN: automatic
  double gap;
  std::string colour;
};

struct Canvas {
  double ox = 0, oy = 0, scale = 1;  // pixel of the model origin, pixels per model unit
  std::vector<Shape> shapes;
  double width = 0, height = 0;
  std::vector<Pending> pending;

  void label(Pixel at, const std::string& t, double angle, double gap, const std::string& colour) {
    if (!t.empty()) pending.push_back({at, t, angle, gap, colour});
  }

  Pixel px(V2 a) const { return {ox + scale * a.x, oy - scale * a.y}; }

  Shape& path(const std::vector<V2>& pts, Part part, const Style& st, bool closed = false) {
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
  Shape& fill(const std::vector<V2>& pts, Part part, const std::string& colour, double opacity, bool hatch) {
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
  Shape& marker(V2 at, Part part, const Style& st, bool hollow) {
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
  /// Text next to the pixel `at`, `gap` pixels away in direction `deg`.
  Shape& text(Pixel at, const std::string& t, double deg, double gap, const std::string& colour,
              double size = 14) {
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
  /// A filled arrowhead at `tip` pointing along `dir` (model units).
  void arrowhead(V2 tip, V2 dir, const Style& st, Part part, bool hollow) {
    const Pixel t = px(tip);
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
    s.fill = hollow ? "#ffffff" : st.color();
    shapes.push_back(std::move(s));
  }
};

Canvas make_canvas(double ox, double oy, double scale) {
  Canvas c;
  c.ox = ox;
  c.oy = oy;
  c.scale = scale;
  return c;
}

/// Opacity of a hatched (back side) fill: hatching lines cover less than a flat fill, so they
/// are drawn stronger.
double back_opacity(const Style& st) { return std::min(1.0, st.fill_opacity() * 2.5); }

/// The point normalized to |w| = 1 (or to max(|x|, |y|) = 1 on Ω). A proper point so far
/// away that x/w overflows a double is drawn as the point at infinity in its direction: at
/// more than 10^308 from the origin, no picture can tell them apart.
Point drawable(const Point& p) {
  if (p.w() != 0 && (!std::isfinite(p.x() / p.w()) || !std::isfinite(p.y() / p.w())))
    return normalized(Point(0, p.x(), p.y()));
  return normalized(p);
}

Part part_of(double w) { return w > 0 ? Part::front : (w < 0 ? Part::back : Part::infinity); }

std::vector<const Item*> by_layer(const Figure& f) {
  std::vector<const Item*> v;
  for (const auto& it : f.items()) v.push_back(&it);
  std::stable_sort(v.begin(), v.end(), [](const Item* a, const Item* b) { return a->style.layer() < b->style.layer(); });
  return v;
}

// ---------------------------------------------------------------- planar model
struct PlanePainter {
  const PlaneView& v;
  Canvas& c;
  std::vector<std::pair<Pixel, const Style*>> labels;  // drawn after all geometry

  V2 at(const Point& p) const {
    const Vec2 q = v.place(p);
    return {q.u, q.v};
  }
  static V2 dir(const Point& p) { return unit2({p.x(), p.y()}); }

  /// One piece of a T² segment inside one side: from P along D for t in [0, t1].
  /// Returns the clipped end (for arrowheads) through `end`.
  bool piece(V2 P, V2 D, double t1, Part part, const Style& st, V2* end, V2* dirout) {
    V2 a, b;
    if (!clip_disk(P, D, 0, t1, a, b)) return false;
    c.path({a, b}, part, st);
    if (end) *end = b;
    if (dirout) *dirout = D;
    return true;
  }

  /// The segment of T² from p to q (not antipodal), split where it crosses Ω.
  void arc(const Point& p0, const Point& q0, const Style& st, bool arrow) {
    const Point p = drawable(p0), q = drawable(q0);
    const double wp = p.w(), wq = q.w();
    const double inf = std::numeric_limits<double>::infinity();
    V2 end{}, d{};
    bool have_end = false;
    Part end_part = Part::front;
    if (wp != 0 && wq != 0 && (wp > 0) == (wq > 0)) {
      const V2 P = at(p), Q = at(q);
      have_end = piece(P, Q - P, 1, part_of(wp), st, &end, &d);
      end_part = part_of(wp);
    } else if (wp != 0 && wq == 0) {
      have_end = piece(at(p), (wp > 0 ? 1.0 : -1.0) * dir(q), inf, part_of(wp), st, &end, &d);
      end_part = part_of(wp);
    } else if (wp == 0 && wq != 0) {
      V2 e2, d2;
      const V2 D = (wq > 0 ? 1.0 : -1.0) * dir(p);
      if (piece(at(q), D, inf, part_of(wq), st, &e2, &d2)) {
        V2 a, b;
        clip_disk(at(q), D, 0, inf, a, b);
        end = a;  // the arrow points at q, coming from Ω
        d = -1.0 * D;
        have_end = norm2(at(q)) <= 1;
        end_part = part_of(wq);
      }
    } else if (wp != 0 && wq != 0) {
      // Crosses Ω at c = p + q (both normalized to |w| = 1, opposite signs: w = 0 exactly).
      const V2 cxy{p.x() + q.x(), p.y() + q.y()};
      if (norm2(cxy) == 0) return;
      const V2 cd = unit2(cxy);
      piece(at(p), (wp > 0 ? 1.0 : -1.0) * cd, inf, part_of(wp), st, nullptr, nullptr);
      const V2 D = (wq > 0 ? 1.0 : -1.0) * cd;
      V2 a, b;
      if (clip_disk(at(q), D, 0, inf, a, b)) {
        c.path({a, b}, part_of(wq), st);
        end = a;
        d = -1.0 * D;
        have_end = norm2(at(q)) <= 1;
        end_part = part_of(wq);
      }
    } else {
      // Both on Ω: the shorter arc of the ring.
      const double a0 = std::atan2(p.y(), p.x());
      double a1 = std::atan2(q.y(), q.x());
      if (a1 - a0 > kPi) a1 -= 2 * kPi;
      if (a0 - a1 > kPi) a1 += 2 * kPi;
      std::vector<V2> pts;
      const int n = std::max(2, static_cast<int>(std::fabs(a1 - a0) / 0.02));
      for (int i = 0; i <= n; ++i) {
        const double a = a0 + (a1 - a0) * i / n;
        pts.push_back({PlaneView::ring * std::cos(a), PlaneView::ring * std::sin(a)});
      }
      Style thick = st;
      thick.width(st.width() + 1.2);
      c.path(pts, Part::infinity, thick);
      if (arrow) c.arrowhead(pts.back(), pts.back() - pts[pts.size() - 2], st, Part::infinity, false);
      return;
    }
    if (arrow && have_end) c.arrowhead(end, d, st, end_part, end_part == Part::back);
  }

  void point(const Point& p, const Style& st) {
    const V2 q = at(p);
    if (norm2(q) > (p.w() == 0 ? 2.0 : 1.0)) return;  // outside the shown disk
    c.marker(q, part_of(p.w()), st, p.w() < 0);
    if (!st.label().empty()) labels.push_back({c.px(q), &st});
  }

  void line(const Line& l, const Style& st) {
    const double W = l.W(), X = l.X(), Y = l.Y();
    const double k = W + X * v.cx + Y * v.cy;  // the line in unit coordinates: k + hw (X u + Y v) = 0
    if (st.shade()) {
      const std::string col = st.fill().empty() ? kShade : st.fill();
      const V2 n{v.half_width * X, v.half_width * Y};
      if (X == 0 && Y == 0) {
        c.fill(disk_polygon(), W > 0 ? Part::front : Part::back, col, st.fill_opacity(), W < 0);
      } else {
        auto front = clip_half(disk_polygon(), k, n);
        if (front.size() > 2) c.fill(front, Part::front, col, st.fill_opacity(), false);
        auto back = clip_half(disk_polygon(), -k, -1.0 * n);
        if (back.size() > 2) c.fill(back, Part::back, col, back_opacity(st), true);
      }
    }
    if (X == 0 && Y == 0) {  // Ω itself
      Style thick = st;
      thick.width(st.width() + 1.2);
      c.path(disk_polygon(PlaneView::ring), Part::infinity, thick, true);
      if (!st.label().empty()) labels.push_back({c.px(PlaneView::ring * V2{std::cos(-0.3 * kPi), std::sin(-0.3 * kPi)}), &st});
      return;
    }
    const double m = std::hypot(X, Y);
    const V2 d{Y / m, -X / m};  // direction of travel of the front copy (positive side to the left)
    const V2 F = (-k / (v.half_width * m)) * V2{X / m, Y / m};  // foot of the perpendicular
    V2 a, b;
    const double inf = std::numeric_limits<double>::infinity();
    if (clip_disk(F, d, -inf, inf, a, b)) {
      c.path({b, a}, Part::back, st);   // the back copy, under the front one, travels backwards
      c.path({a, b}, Part::front, st);
      if (st.arrow()) {
        c.arrowhead(b, d, st, Part::front, false);
        c.arrowhead(a, -1.0 * d, st, Part::back, true);
      }
      if (!st.label().empty()) {
        labels.push_back({c.px(a + 0.75 * (b - a)), &st});
      }
    }
    // Its two points at infinity, on the ring.
    Style small = st;
    small.size(2.6).marker(Marker::dot);
    c.marker(PlaneView::ring * d, Part::infinity, small, false);
    c.marker(-PlaneView::ring * d, Part::infinity, small, false);
  }

  void polygon(const std::vector<Point>& pts, const Style& st, bool closed) {
    const std::size_t n = pts.size();
    if (closed && !st.fill().empty() && n >= 3) {
      const bool all_front = std::all_of(pts.begin(), pts.end(), [](const Point& p) { return p.w() > 0; });
      const bool all_back = std::all_of(pts.begin(), pts.end(), [](const Point& p) { return p.w() < 0; });
      if (all_front || all_back) {
        std::vector<V2> poly;
        for (const auto& p : pts) poly.push_back(at(p));
        fill_side(std::move(poly), all_front ? Part::front : Part::back, st);
      } else {
        region(dense_loop(pts), st);
      }
    }
    for (std::size_t i = 0; i + 1 < n; ++i) arc(pts[i], pts[i + 1], st, st.arrow() && i + 2 == n && !closed);
    if (closed && n > 2) arc(pts[n - 1], pts[0], st, false);
  }

  void label(const Point& p, const Style& st) {
    const V2 q = at(p);
    if (norm2(q) > 1.3) return;
    labels.push_back({c.px(q), &st});
  }

  /// Fills a region of T² given by its dense boundary loop: its front part solid, its back
  /// part hatched (each clipped to the shown disk; Ω is pushed far out, beyond the disk).
  void region(const std::vector<Vec3>& loop, const Style& st) {
    for (const double s : {1.0, -1.0}) {
      std::vector<V2> poly;
      for (const Vec3& p : clip_to_hemisphere(loop, {0, 0, s})) {
        const double w = s > 0 ? std::max(p.z, 1e-9) : std::min(p.z, -1e-9);
        const Vec2 q = v.to_unit(p.x / w, p.y / w);
        poly.push_back({q.u, q.v});
      }
      fill_side(std::move(poly), s > 0 ? Part::front : Part::back, st);
    }
  }

  /// Fills the part of a polygon (unit coordinates) inside the shown disk: solid on the
  /// front, hatched on the back.
  void fill_side(std::vector<V2> poly, Part part, const Style& st) {
    poly = clip_poly_disk(std::move(poly));
    if (poly.size() > 2)
      c.fill(poly, part, st.fill(), part == Part::back ? back_opacity(st) : st.fill_opacity(), part == Part::back);
  }

  /// A circle of finite or beyond-infinity radius: the dense loop `pts`, all on one side.
  void circle(const std::vector<Point>& pts, const Style& st) {
    const Part part = part_of(pts[0].w());
    std::vector<V2> q;
    for (const auto& p : pts) q.push_back(at(p));
    if (!st.fill().empty()) fill_side(q, part, st);
    // The stroke: the runs of the loop inside the shown disk, cut exactly at its edge.
    const std::size_t n = q.size();
    std::size_t start = 0;
    while (start < n && norm2(q[start]) <= 1) ++start;
    if (start == n) {
      c.path(q, part, st, true);
    } else {
      std::vector<V2> run;
      for (std::size_t k = 1; k <= n; ++k) {
        const V2 a = q[(start + k - 1) % n], b = q[(start + k) % n];
        V2 u, w;
        if (!clip_disk(a, b - a, 0, 1, u, w)) continue;
        if (!run.empty() && norm2(run.back() - u) > 1e-12) {
          c.path(run, part, st);
          run.clear();
        }
        if (run.empty()) run.push_back(u);
        run.push_back(w);
      }
      if (run.size() > 1) c.path(run, part, st);
    }
    const std::size_t k = n / 4;
    if (st.arrow() && norm2(q[k]) <= 1) c.arrowhead(q[k], q[k] - q[k - 1], st, part, part == Part::back);
    if (!st.label().empty() && norm2(q[n / 8]) <= 1) labels.push_back({c.px(q[n / 8]), &st});
  }
};

Vec3 to3(const Point& p) { return on_sphere(p); }

// ---------------------------------------------------------------- spherical model
struct SpherePainter {
  const SphereView& v;
  Canvas& c;
  std::vector<std::pair<Pixel, const Style*>> labels;

  V2 proj(const Vec3& s) const {
    const Vec2 q = v.project(s);
    return {q.u, q.v};
  }

  /// Draws a run of unit vectors that lies on one side of the limb.
  Shape& run(const std::vector<Vec3>& pts, bool visible, Part part, const Style& st) {
    std::vector<V2> q;
    for (const auto& s : pts) q.push_back(proj(s));
    Shape& sh = c.path(q, part, st);
    if (!visible) {
      sh.hidden = true;
      sh.dash = {2.5, 3};
      sh.opacity = 0.45;
    }
    return sh;
  }

  /// Part of T² a run belongs to (by its midpoint: runs are not split at Ω on the sphere).
  static Part side_part(const std::vector<Vec3>& pts) {
    const Vec3& m = pts[pts.size() / 2];
    return m.z > 0 ? Part::front : (m.z < 0 ? Part::back : Part::infinity);
  }

  void arc(const Point& p, const Point& q, const Style& st, bool arrow) {
    const auto pieces = split_at_limb(p, q, v);
    std::vector<Vec3> last;
    bool last_vis = true;
    for (const auto& pc : pieces) {
      auto pts = slerp_samples(pc.a, pc.b);
      run(pts, pc.visible, side_part(pts), st);
      last = pts;
      last_vis = pc.visible;
    }
    if (arrow && last.size() >= 2) {
      const V2 tip = proj(last.back()), prev = proj(last[last.size() - 2]);
      c.arrowhead(tip, tip - prev, st, side_part(last), !last_vis);
      if (!last_vis) c.shapes.back().opacity = 0.45;
    }
  }

  /// Splits a closed dense loop of unit vectors into runs on either side of the limb.
  void loop(const std::vector<Vec3>& pts, const Style& st, Part part) {
    const std::size_t n = pts.size();
    std::size_t start = 0;
    for (std::size_t i = 0; i < n; ++i)
      if ((v.depth(pts[i]) > 0) != (v.depth(pts[(i + n - 1) % n]) > 0)) {
        start = i;
        break;
      }
    std::vector<Vec3> cur;
    for (std::size_t k = 0; k <= n; ++k) {
      const Vec3& s = pts[(start + k) % n];
      if (!cur.empty() && (v.depth(s) > 0) != (v.depth(cur.back()) > 0)) {
        const Vec3 x = crossing(cur.back(), s, v.eye());
        cur.push_back(x);
        run(cur, v.depth(cur[cur.size() / 2]) > 0, part, st);
        cur = {x};
      }
      cur.push_back(s);
    }
    if (cur.size() > 1) run(cur, v.depth(cur[cur.size() / 2]) > 0, part, st);
  }

  /// A dense loop around the great circle of l, starting at a limb point when there is one.
  static std::vector<Vec3> circle(const Line& l) {
    const Vec3 n = unit({l.X(), l.Y(), l.W()});
    const Vec3 t = std::fabs(n.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 b1 = unit(cross(n, t)), b2 = cross(n, b1);
    std::vector<Vec3> out;
    const int N = 480;
    for (int i = 0; i < N; ++i) {
      const double a = 2 * kPi * i / N;
      out.push_back(plus(scaled(b1, std::cos(a)), scaled(b2, std::sin(a))));
    }
    return out;
  }

  /// Fills the visible part of a region given by its dense boundary loop (the hidden part
  /// of the boundary is replaced by the limb).
  void region(const std::vector<Vec3>& loop, const Style& st) {
    std::vector<V2> poly;
    for (const Vec3& s : clip_to_hemisphere(loop, v.eye())) poly.push_back(proj(s));
    if (poly.size() > 2) c.fill(poly, Part::front, st.fill(), st.fill_opacity(), false);
  }

  /// A circle of finite or beyond-infinity radius: the dense loop `pts`, all on one side.
  void circle(const std::vector<Point>& pts, const Style& st) {
    std::vector<Vec3> loop;
    for (const auto& p : pts) loop.push_back(to3(p));
    if (!st.fill().empty()) region(loop, st);
    this->loop(loop, st, part_of(pts[0].w()));
    const std::size_t k = loop.size() / 4;
    if (st.arrow()) {
      const bool vis = v.depth(loop[k]) > 0;
      c.arrowhead(proj(loop[k]), proj(loop[k]) - proj(loop[k - 1]), st, part_of(pts[0].w()), !vis);
      if (!vis) c.shapes.back().opacity = 0.45;
    }
    if (!st.label().empty()) labels.push_back({c.px(proj(loop[loop.size() / 8])), &st});
  }

  void point(const Point& p, const Style& st) {
    const Vec3 s = to3(p);
    Shape& m = c.marker(proj(s), part_of(p.w()), st, p.w() < 0);
    if (v.depth(s) < 0) {
      m.hidden = true;
      m.opacity = 0.45;
    }
    if (!st.label().empty()) labels.push_back({c.px(proj(s)), &st});
  }

  void line(const Line& l, const Style& st) {
    const Vec3 n = unit({l.X(), l.Y(), l.W()});
    if (st.shade()) {
      const std::string col = st.fill().empty() ? kShade : st.fill();
      const auto lp = limb_points(l, v);
      std::vector<V2> region;
      if (!lp) {
        if (dot(n, v.eye()) > 0) region = disk_polygon();
      } else {
        // Visible half of the great circle (through its point nearest the viewer), then the
        // half of the limb on the positive side.
        const Vec3 e = v.eye();
        Vec3 top = plus(e, scaled(n, -dot(e, n)));
        top = unit(top);
        Vec3 k = plus(n, scaled(e, -dot(n, e)));
        k = unit(k);
        auto add = [&](const Vec3& a, const Vec3& b) {
          for (const auto& s : slerp_samples(a, b)) region.push_back(proj(s));
        };
        add(lp->first, top);
        add(top, lp->second);
        add(lp->second, k);
        add(k, lp->first);
      }
      if (region.size() > 2) c.fill(region, Part::front, col, st.fill_opacity(), false);
    }
    loop(circle(l), st, Part::front);
    if (st.arrow() || !st.label().empty()) {
      // The visible point of the circle nearest the viewer, and the direction of travel there.
      const Vec3 e = v.eye();
      Vec3 top = plus(e, scaled(n, -dot(e, n)));
      if (dot(top, top) < 1e-12) return;
      top = unit(top);
      const Vec3 t = cross(n, top);  // travel direction: positive side (n) to the left
      const Vec3 ahead = unit(plus(top, scaled(t, 0.5)));
      if (st.arrow()) c.arrowhead(proj(ahead), proj(ahead) - proj(unit(plus(top, scaled(t, 0.45)))), st, part_of(ahead.z), false);
      if (!st.label().empty()) labels.push_back({c.px(proj(unit(plus(top, scaled(t, -0.35))))), &st});
    }
  }

  void polygon(const std::vector<Point>& pts, const Style& st, bool closed) {
    const std::size_t n = pts.size();
    if (closed && !st.fill().empty() && n >= 3) region(dense_loop(pts), st);
    for (std::size_t i = 0; i + 1 < n; ++i) arc(pts[i], pts[i + 1], st, st.arrow() && i + 2 == n && !closed);
    if (closed && n > 2) arc(pts[n - 1], pts[0], st, false);
  }
};

void draw_labels(Canvas& c, const std::vector<std::pair<Pixel, const Style*>>& labels) {
  for (const auto& [at, st] : labels) c.label(at, st->label(), st->label_angle(), st->size() + 4, st->color());
}

double margin_scale(int size, double extent) { return size / 2.0 / extent; }

// ---------------------------------------------------------------- label placement
struct Box {
  double x0, y0, x1, y1;
};

double dist_point_box(double x, double y, const Box& b) {
  const double dx = std::max({b.x0 - x, 0.0, x - b.x1}), dy = std::max({b.y0 - y, 0.0, y - b.y1});
  return std::hypot(dx, dy);
}
double dist_point_seg(double x, double y, Pixel a, Pixel b) {
  const double vx = b.x - a.x, vy = b.y - a.y, L = vx * vx + vy * vy;
  double t = L > 0 ? ((x - a.x) * vx + (y - a.y) * vy) / L : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x + t * vx - x, a.y + t * vy - y);
}
bool seg_hits_box(Pixel a, Pixel b, const Box& bx) {
  // Liang–Barsky clipping of the segment to the box.
  double t0 = 0, t1 = 1;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - bx.x0, bx.x1 - a.x, a.y - bx.y0, bx.y1 - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
    } else {
      const double r = q[i] / p[i];
      if (p[i] < 0) t0 = std::max(t0, r);
      else t1 = std::min(t1, r);
    }
  }
  return t0 <= t1;
}
double dist_seg_box(Pixel a, Pixel b, const Box& bx) {
  if (seg_hits_box(a, b, bx)) return 0;
  double d = std::min(dist_point_box(a.x, a.y, bx), dist_point_box(b.x, b.y, bx));
  for (auto [x, y] : {std::pair{bx.x0, bx.y0}, {bx.x1, bx.y0}, {bx.x0, bx.y1}, {bx.x1, bx.y1}})
    d = std::min(d, dist_point_seg(x, y, a, b));
  return d;
}

/// Number of characters of UTF-8 text.
int glyphs(const std::string& t) {
  int n = 0;
  for (unsigned char ch : t) n += (ch & 0xC0) != 0x80;
  return n;
}

/// Places the pending labels: each at its own angle, or at the first of eight directions where
/// its (estimated) box clears the drawn geometry and the labels placed before it.
void place_labels(Canvas& c) {
  std::vector<Box> placed;
  const double size = 14;
  for (const Pending& L : c.pending) {
    const double w = 0.62 * size * glyphs(L.text) + 2;
    auto box_for = [&](double deg, double gap) {
      Canvas tmp;
      const Shape& s = tmp.text(L.at, L.text, deg, gap, L.colour, size);
      double x = s.pts[0].x;
      if (s.halign == 0) x -= w / 2;
      if (s.halign == 1) x -= w;
      return Box{x, s.pts[0].y - 0.78 * size, x + w, s.pts[0].y + 0.22 * size};
    };
    auto clearance = [&](const Box& b) {
      double d = 1e9;
      if (c.width > 0 && (b.x0 < 0 || b.x1 > c.width || b.y0 < 0 || b.y1 > c.height)) return -1.0;
      for (const Shape& s : c.shapes) {
        if (s.opacity == 0) continue;
        if (s.kind == ShapeKind::marker) d = std::min(d, dist_point_box(s.pts[0].x, s.pts[0].y, b) - s.radius);
        if (s.kind == ShapeKind::text) {
          const double tw = 0.62 * s.font_size * glyphs(s.text) + 2;
          double x = s.pts[0].x;
          if (s.halign == 0) x -= tw / 2;
          if (s.halign == 1) x -= tw;
          const Box o{x, s.pts[0].y - 0.78 * s.font_size, x + tw, s.pts[0].y + 0.22 * s.font_size};
          const double dx = std::max({o.x0 - b.x1, 0.0, b.x0 - o.x1}), dy = std::max({o.y0 - b.y1, 0.0, b.y0 - o.y1});
          d = std::min(d, std::hypot(dx, dy));
          continue;
        }
        if (s.kind == ShapeKind::path && !s.stroke.empty()) {
          for (std::size_t i = 0; i + 1 < s.pts.size(); ++i) d = std::min(d, dist_seg_box(s.pts[i], s.pts[i + 1], b));
          if (s.closed && s.pts.size() > 2) d = std::min(d, dist_seg_box(s.pts.back(), s.pts[0], b));
        }
      }
      for (const Box& o : placed) {
        const double dx = std::max({o.x0 - b.x1, 0.0, b.x0 - o.x1}), dy = std::max({o.y0 - b.y1, 0.0, b.y0 - o.y1});
        d = std::min(d, std::hypot(dx, dy));
      }
      return d;
    };
    double angle = L.angle, gap = L.gap;
    if (std::isnan(angle)) {
      double best = -2;
      for (double g : {L.gap, L.gap + 8, L.gap + 18}) {
        for (double deg : {45.0, 135.0, -45.0, -135.0, 90.0, -90.0, 0.0, 180.0, 22.5, 157.5, -22.5, -157.5}) {
          const double d = clearance(box_for(deg, g));
          if (d > best + 0.5) best = d, angle = deg, gap = g;
        }
        if (best >= 3) break;
      }
    }
    placed.push_back(box_for(angle, gap));
    c.text(L.at, L.text, angle, gap, L.colour, size);
  }
  c.pending.clear();
}

/// Moves the picture down by `title_band` and writes the title in the band above it.
void add_title(Canvas& c, const Figure& f, double width) {
  if (f.title().empty()) return;
  for (Shape& s : c.shapes)
    for (Pixel& p : s.pts) p.y += title_band;
  c.text({width / 2.0, title_band / 2}, f.title(), 0, 0, "#000000", 14).halign = 0;
}

}  // namespace

// ---------------------------------------------------------------- public entry points

std::vector<Shape> display_list(const Figure& f, const PlaneView& v) {
  Canvas c = make_canvas(v.size / 2.0, v.size / 2.0, margin_scale(v.size, 1.2));
  c.width = c.height = v.size;
  Style faint;
  faint.color("#dddddd").width(0.8);
  c.path(disk_polygon(), Part::decoration, faint, true);
  if (v.axes) {
    V2 a, b;
    Style ax;
    ax.color(kLightGrey).width(0.8);
    const double inf = std::numeric_limits<double>::infinity();
    if (clip_disk(v.to_unit(0, 0).u == 0 ? V2{0, 0} : V2{v.to_unit(0, 0).u, v.to_unit(0, 0).v}, {1, 0}, -inf, inf, a, b))
      c.path({a, b}, Part::decoration, ax);
    if (clip_disk({v.to_unit(0, 0).u, v.to_unit(0, 0).v}, {0, 1}, -inf, inf, a, b)) c.path({a, b}, Part::decoration, ax);
  }
  if (v.omega) {
    Style ring;
    ring.color(kGrey).width(1.2);
    c.path(disk_polygon(PlaneView::ring), Part::decoration, ring, true);
    const double a = 0.3 * kPi;
    c.text(c.px({PlaneView::ring * std::cos(a), PlaneView::ring * std::sin(a)}), "Ω", 55, 5, kGrey, 15);
  }
  PlanePainter pp{v, c, {}};
  for (const Item* it : by_layer(f)) {
    const Style& st = it->style;
    switch (it->kind) {
      case ItemKind::point: pp.point(it->points[0], st); break;
      case ItemKind::line: pp.line(it->line, st); break;
      case ItemKind::segment: pp.arc(it->points[0], it->points[1], st, st.arrow());
        if (!st.label().empty()) {
          const Vec3 m = unit(plus(on_sphere(it->points[0]), on_sphere(it->points[1])));
          pp.label(Point(m.z, m.x, m.y), st);
        }
        break;
      case ItemKind::polygon: pp.polygon(it->points, st, true); break;
      case ItemKind::polyline: pp.polygon(it->points, st, false); break;
      case ItemKind::circle: pp.circle(it->points, st); break;
      case ItemKind::label: {
        const V2 q = pp.at(it->points[0]);
        if (norm2(q) <= 1.3) c.label(c.px(q), it->text, st.label_angle(), 2, st.color());
        break;
      }
      case ItemKind::t1: break;
    }
  }
  draw_labels(c, pp.labels);
  place_labels(c);
  add_title(c, f, v.size);
  return c.shapes;
}

std::vector<Shape> display_list(const Figure& f, const SphereView& v) {
  Canvas c = make_canvas(v.size / 2.0, v.size / 2.0, margin_scale(v.size, 1.15));
  c.width = c.height = v.size;
  // The sphere: a faint disk and its outline.
  c.fill(disk_polygon(1, 360), Part::decoration, "#f3f6f9", 1, false);
  SpherePainter sp{v, c, {}};
  if (v.graticule) {
    Style g;
    g.color("#d9d9d9").width(0.6);
    for (int lon = 0; lon < 180; lon += 30) {
      const double a = lon * kPi / 180;
      sp.loop(SpherePainter::circle(Line(0, -std::sin(a), std::cos(a))), g, Part::decoration);
    }
    for (int lat = -60; lat <= 60; lat += 30) {
      if (lat == 0) continue;
      std::vector<Vec3> ring;
      const double la = lat * kPi / 180;
      for (int i = 0; i < 360; ++i)
        ring.push_back({std::cos(la) * std::cos(i * kPi / 180), std::cos(la) * std::sin(i * kPi / 180), std::sin(la)});
      sp.loop(ring, g, Part::decoration);
    }
    for (auto& s : c.shapes)
      if (s.kind == ShapeKind::path && s.hidden) s.opacity = 0;  // only the visible grid
  }
  if (v.omega) {
    Style om;
    om.color(kGrey).width(1.2);
    sp.loop(SpherePainter::circle(Line(1, 0, 0)), om, Part::decoration);
    // "Ω" next to the equator point nearest the viewer, below it.
    const Vec3 e = v.eye();
    Vec3 near{e.x, e.y, 0};
    if (dot(near, near) > 1e-9) {
      near = unit(near);
      const Vec3 side = unit(cross({0, 0, 1}, near));
      const Vec3 at = unit(plus(near, scaled(side, -1.2)));
      c.text(c.px(sp.proj(at)), "Ω", -60, 4, kGrey, 15);
    }
  }
  Style outline;
  outline.color("#555555").width(1.2);
  c.path(disk_polygon(1, 360), Part::decoration, outline, true);
  for (const Item* it : by_layer(f)) {
    const Style& st = it->style;
    switch (it->kind) {
      case ItemKind::point: sp.point(it->points[0], st); break;
      case ItemKind::line: sp.line(it->line, st); break;
      case ItemKind::segment: sp.arc(it->points[0], it->points[1], st, st.arrow());
        if (!st.label().empty()) {
          const Vec3 m = unit(plus(on_sphere(it->points[0]), on_sphere(it->points[1])));
          sp.labels.push_back({c.px(sp.proj(m)), &st});
        }
        break;
      case ItemKind::polygon: sp.polygon(it->points, st, true); break;
      case ItemKind::polyline: sp.polygon(it->points, st, false); break;
      case ItemKind::circle: sp.circle(it->points, st); break;
      case ItemKind::label:
        c.label(c.px(sp.proj(on_sphere(it->points[0]))), it->text, st.label_angle(), 2, st.color());
        break;
      case ItemKind::t1: break;
    }
  }
  draw_labels(c, sp.labels);
  place_labels(c);
  add_title(c, f, v.size);
  return c.shapes;
}

std::vector<Shape> display_list(const Figure& f, const T1View& v) {
  const bool circle = v.model == T1Model::circle;
  const double h = circle ? v.size : v.size * 0.5;
  Canvas c = make_canvas(v.size / 2.0, h / 2.0, circle ? margin_scale(v.size, 1.9) : v.size / 2.0 / 1.25);
  c.width = v.size;
  c.height = h;
  Style base;
  base.color("#333333").width(1.4);
  std::vector<std::pair<Pixel, const Style*>> labels;
  if (circle) {
    // Axes w (right) and x (up); the front half w > 0 solid, the back half dashed.
    Style ax;
    ax.color(kLightGrey).width(0.8);
    c.path({{-1.3, 0}, {1.3, 0}}, Part::decoration, ax);
    c.path({{0, -1.3}, {0, 1.3}}, Part::decoration, ax);
    c.text(c.px({1.3, 0}), "w", 0, 4, kGrey, 13);
    c.text(c.px({0, 1.3}), "x", 90, 4, kGrey, 13);
    std::vector<V2> fr, bk;
    for (int i = -90; i <= 90; ++i) fr.push_back({std::cos(i * kPi / 180), std::sin(i * kPi / 180)});
    for (int i = 90; i <= 270; ++i) bk.push_back({std::cos(i * kPi / 180), std::sin(i * kPi / 180)});
    c.path(fr, Part::front, base);
    c.path(bk, Part::back, base);
    Style inf;
    inf.color("#333333").size(3);
    c.marker({0, 1}, Part::infinity, inf, false);
    c.marker({0, -1}, Part::infinity, inf, false);
    c.text(c.px({0, 1}), "+∞ = [0, 1]", 135, 8, "#333333", 12);
    c.text(c.px({0, -1}), "−∞ = [0, −1]", -135, 8, "#333333", 12);
  } else {
    // Two copies of the real line: the front above (solid), the back below (dashed). As drawn,
    // [w, x] sits at x/w, so the back copy is run through backwards: leaving the front copy
    // at +∞ one enters the back copy from its left end.
    c.path({{-1.05, 0.3}, {1.05, 0.3}}, Part::front, base);
    c.path({{-1.05, -0.3}, {1.05, -0.3}}, Part::back, base);
    c.arrowhead({1.12, 0.3}, {1, 0}, base, Part::front, false);
    c.arrowhead({-1.12, -0.3}, {-1, 0}, base, Part::back, true);
    c.text(c.px({-1.05, 0.3}), "front  w > 0", 90, 8, "#333333", 12).halign = -1;
    c.text(c.px({-1.05, -0.3}), "back  w < 0", -90, 8, "#333333", 12).halign = -1;
    c.text(c.px({1.12, 0.3}), "→ +∞", -30, 10, kGrey, 12);
    c.text(c.px({-1.12, -0.3}), "+∞ →", 150, 10, kGrey, 12);
    Style tick;
    tick.color(kGrey).width(1);
    for (int k = -static_cast<int>(v.half_width); k <= static_cast<int>(v.half_width); ++k) {
      const double u = k / v.half_width;
      c.path({{u, 0.27}, {u, 0.33}}, Part::decoration, tick);
      c.path({{u, -0.27}, {u, -0.33}}, Part::decoration, tick);
    }
  }
  for (const Item* it : by_layer(f)) {
    if (it->kind != ItemKind::t1) continue;
    const Style& st = it->style;
    const double w = it->t1w, x = it->t1x;
    V2 at{};
    if (circle) {
      const double m = std::hypot(w, x);
      at = {w / m, x / m};
    } else if (w == 0) {
      at = {x > 0 ? 1.05 : -1.05, 0.3};
    } else {
      const double u = x / w / v.half_width;
      if (std::fabs(u) > 1.05) continue;
      at = {u, w > 0 ? 0.3 : -0.3};
    }
    c.marker(at, w > 0 ? Part::front : (w < 0 ? Part::back : Part::infinity), st, w < 0);
    if (!st.label().empty()) labels.push_back({c.px(at), &st});
  }
  for (const auto& [at, st] : labels) c.label(at, st->label(), st->label_angle(), st->size() + 4, st->color());
  place_labels(c);
  return c.shapes;
}

}  // namespace t2::draw
