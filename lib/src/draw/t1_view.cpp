// The oriented projective line T¹: as a circle (fig. 3.1) or as two copies of the real line
// (fig. 3.2) (see t2/draw/view.hpp).
#include <cmath>

#include "canvas.hpp"
#include "painter.hpp"
#include "sphere_math.hpp"
#include "t2/draw/palette.hpp"

namespace t2::draw {

namespace {

/// Draws the T¹ items of a figure; the items of T² have no place on T¹.
class T1Painter final : public Painter {
 public:
  T1Painter(const T1View& v, Canvas& c) : v_(v), c_(c) {}

  void t1(double w, double x, const Style& st) override {
    Vec2 at{};
    if (v_.model == T1Model::circle) {
      const double m = std::hypot(w, x);
      at = {w / m, x / m};
    } else if (w == 0) {
      at = {x > 0 ? 1.05 : -1.05, 0.3};
    } else {
      const double u = x / w / v_.half_width;
      if (std::fabs(u) > 1.05) return;
      at = {u, w > 0 ? 0.3 : -0.3};
    }
    c_.marker(at, part_of(w), st, w < 0);
    if (!st.label().empty()) c_.label_of(at, st);
  }

  void point(const Point&, const Style&) override {}
  void line(const Line&, const Style&) override {}
  void segment(const Point&, const Point&, const Style&) override {}
  void chain(const std::vector<Point>&, const Style&, bool) override {}
  void circle(const std::vector<Point>&, const Style&) override {}
  void label(const Point&, const std::string&, const Style&) override {}

 private:
  const T1View& v_;
  Canvas& c_;
};

/// The circle model: axes w (right) and x (up); the front half w > 0 solid, the back dashed.
void circle_model(Canvas& c, const Style& base) {
  Style ax;
  ax.color(palette::axis).width(0.8);
  c.path({{-1.3, 0}, {1.3, 0}}, Part::decoration, ax);
  c.path({{0, -1.3}, {0, 1.3}}, Part::decoration, ax);
  c.text(c.px({1.3, 0}), "w", 0, 4, palette::omega, 13);
  c.text(c.px({0, 1.3}), "x", 90, 4, palette::omega, 13);
  std::vector<Vec2> fr, bk;
  for (int i = -90; i <= 90; ++i) fr.push_back({std::cos(i * kPi / 180), std::sin(i * kPi / 180)});
  for (int i = 90; i <= 270; ++i) bk.push_back({std::cos(i * kPi / 180), std::sin(i * kPi / 180)});
  c.path(fr, Part::front, base);
  c.path(bk, Part::back, base);
  Style inf;
  inf.color(palette::t1_ink).size(3);
  c.marker({0, 1}, Part::infinity, inf, false);
  c.marker({0, -1}, Part::infinity, inf, false);
  c.text(c.px({0, 1}), "+∞ = [0, 1]", 135, 8, palette::t1_ink, 12);
  c.text(c.px({0, -1}), "−∞ = [0, −1]", -135, 8, palette::t1_ink, 12);
}

/// Two copies of the real line: the front above (solid), the back below (dashed). As drawn,
/// [w, x] sits at x/w, so the back copy is run through backwards: leaving the front copy at
/// +∞ one enters the back copy from its left end.
void lines_model(Canvas& c, const Style& base, double half_width) {
  c.path({{-1.05, 0.3}, {1.05, 0.3}}, Part::front, base);
  c.path({{-1.05, -0.3}, {1.05, -0.3}}, Part::back, base);
  c.arrowhead({1.12, 0.3}, {1, 0}, base, Part::front, false);
  c.arrowhead({-1.12, -0.3}, {-1, 0}, base, Part::back, true);
  c.text(c.px({-1.05, 0.3}), "front  w > 0", 90, 8, palette::t1_ink, 12).halign = -1;
  c.text(c.px({-1.05, -0.3}), "back  w < 0", -90, 8, palette::t1_ink, 12).halign = -1;
  c.text(c.px({1.12, 0.3}), "→ +∞", -30, 10, palette::omega, 12);
  c.text(c.px({-1.12, -0.3}), "+∞ →", 150, 10, palette::omega, 12);
  Style tick;
  tick.color(palette::omega).width(1);
  for (int k = -static_cast<int>(half_width); k <= static_cast<int>(half_width); ++k) {
    const double u = k / half_width;
    c.path({{u, 0.27}, {u, 0.33}}, Part::decoration, tick);
    c.path({{u, -0.27}, {u, -0.33}}, Part::decoration, tick);
  }
}

}  // namespace

std::vector<Shape> display_list(const Figure& f, const T1View& v) {
  const bool circle = v.model == T1Model::circle;
  const double h = circle ? v.size : v.size * 0.5;
  Canvas c(v.size / 2.0, h / 2.0, circle ? v.size / 2.0 / 1.9 : v.size / 2.0 / 1.25);
  c.width = v.size;
  c.height = h;
  Style base;
  base.color(palette::t1_ink).width(1.4);
  if (circle)
    circle_model(c, base);
  else
    lines_model(c, base, v.half_width);
  T1Painter painter(v, c);
  return display(f, painter, c, false);
}

}  // namespace t2::draw
