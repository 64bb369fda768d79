// Label placement (see labels.hpp).
#include "labels.hpp"

#include <algorithm>
#include <cmath>

namespace t2::draw {

namespace {

/// A box of the picture, in pixels.
struct Box {
  double x0, y0, x1, y1;
};

double dist_point_box(double x, double y, const Box& b) {
  const double dx = std::max({b.x0 - x, 0.0, x - b.x1}), dy = std::max({b.y0 - y, 0.0, y - b.y1});
  return std::hypot(dx, dy);
}
double dist_box_box(const Box& o, const Box& b) {
  const double dx = std::max({o.x0 - b.x1, 0.0, b.x0 - o.x1}), dy = std::max({o.y0 - b.y1, 0.0, b.y0 - o.y1});
  return std::hypot(dx, dy);
}
double dist_point_seg(double x, double y, Vec2 a, Vec2 b) {
  const double vx = b.x - a.x, vy = b.y - a.y, L = vx * vx + vy * vy;
  double t = L > 0 ? ((x - a.x) * vx + (y - a.y) * vy) / L : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x + t * vx - x, a.y + t * vy - y);
}
bool seg_hits_box(Vec2 a, Vec2 b, const Box& bx) {
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
double dist_seg_box(Vec2 a, Vec2 b, const Box& bx) {
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

/// The (estimated) box of a text shape.
Box text_box(const Shape& s) {
  const double w = 0.62 * s.font_size * glyphs(s.text) + 2;
  double x = s.pts[0].x;
  if (s.halign == 0) x -= w / 2;
  if (s.halign == 1) x -= w;
  return Box{x, s.pts[0].y - 0.78 * s.font_size, x + w, s.pts[0].y + 0.22 * s.font_size};
}

/// Distance from box b to everything drawn on c and to the boxes placed so far; −1 when b
/// leaves the picture.
double clearance(const Canvas& c, const std::vector<Box>& placed, const Box& b) {
  double d = 1e9;
  if (c.width > 0 && (b.x0 < 0 || b.x1 > c.width || b.y0 < 0 || b.y1 > c.height)) return -1.0;
  for (const Shape& s : c.shapes) {
    if (s.opacity == 0) continue;
    if (s.kind == ShapeKind::marker) d = std::min(d, dist_point_box(s.pts[0].x, s.pts[0].y, b) - s.radius);
    if (s.kind == ShapeKind::text) {
      d = std::min(d, dist_box_box(text_box(s), b));
      continue;
    }
    if (s.kind == ShapeKind::path && !s.stroke.empty()) {
      for (std::size_t i = 0; i + 1 < s.pts.size(); ++i) d = std::min(d, dist_seg_box(s.pts[i], s.pts[i + 1], b));
      if (s.closed && s.pts.size() > 2) d = std::min(d, dist_seg_box(s.pts.back(), s.pts[0], b));
    }
  }
  for (const Box& o : placed) d = std::min(d, dist_box_box(o, b));
  return d;
}

}  // namespace

void place_labels(Canvas& c) {
  for (const auto& [at, st] : c.styled) c.label(at, st->label(), st->label_angle(), st->size() + 4, st->color(), st->halo());
  c.styled.clear();
  std::vector<Box> placed;
  const double size = 14;
  for (const Pending& L : c.pending) {
    auto box_for = [&](double deg, double gap) {
      Canvas tmp;
      return text_box(tmp.text(L.at, L.text, deg, gap, L.colour, size));
    };
    double angle = L.angle, gap = L.gap;
    if (std::isnan(angle)) {
      double best = -2;
      for (double g : {L.gap, L.gap + 8, L.gap + 18}) {
        for (double deg : {45.0, 135.0, -45.0, -135.0, 90.0, -90.0, 0.0, 180.0, 22.5, 157.5, -22.5, -157.5}) {
          const double d = clearance(c, placed, box_for(deg, g));
          if (d > best + 0.5) best = d, angle = deg, gap = g;
        }
        if (best >= 3) break;
      }
    }
    placed.push_back(box_for(angle, gap));
    c.text(L.at, L.text, angle, gap, L.colour, size).halo = L.halo;
  }
  c.pending.clear();
}

}  // namespace t2::draw
