// Circles, filled regions and the primitive overloads of the drawing library, checked against
// independent oracles: every drawn point of a circle is un-projected (the planar model by its
// Cartesian position, the sphere by the orthographic identity) and must be at the circle's
// distance from the centre on the right side of T²; a filled region must agree, pixel by pixel,
// with the exact containment predicates of T² except within a pixel or two of its drawn
// boundary. Tolerances are for floating-point *drawing*, never for a predicate.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "t2/draw.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

namespace dr = t2::draw;

const char* const kInk = "#123456";  // the colour of the item under test

// Pixel <-> model maps, written from the documented layout: the picture is `size` pixels
// square; the plane shows the disk of radius half_width at 1/1.2 of the half-size, the sphere
// outline is at 1/1.15 of the half-size; pixel y grows downwards.
struct PlaneMap {
  dr::PlaneView v;
  double scale() const { return v.size / 2.0 / 1.2 / v.half_width; }  // pixels per model unit
  dr::Vec2 px(double x, double y) const {
    return {v.size / 2.0 + scale() * (x - v.cx), v.size / 2.0 - scale() * (y - v.cy)};
  }
  std::pair<double, double> xy(const dr::Vec2& p) const {
    return {v.cx + (p.x - v.size / 2.0) / scale(), v.cy - (p.y - v.size / 2.0) / scale()};
  }
};
struct SphereMap {
  dr::SphereView v;
  double scale() const { return v.size / 2.0 / 1.15; }
  // The point of the unit sphere drawn at pixel p, on the visible (front = true) or the hidden
  // hemisphere; nullopt outside the outline.
  std::optional<dr::Vec3> unproject(const dr::Vec2& p, bool visible) const {
    const double u = (p.x - v.size / 2.0) / scale(), w = -(p.y - v.size / 2.0) / scale();
    const double d2 = 1 - u * u - w * w;
    if (d2 < -1e-9) return std::nullopt;
    const double d = (visible ? 1 : -1) * std::sqrt(std::max(0.0, d2));
    const auto [r, up] = v.screen_axes();
    const dr::Vec3 e = v.eye();
    return dr::Vec3{u * r.x + w * up.x + d * e.x, u * r.y + w * up.y + d * e.y, u * r.z + w * up.z + d * e.z};
  }
};

std::vector<dr::Shape> strokes(const std::vector<dr::Shape>& list, const std::string& colour) {
  std::vector<dr::Shape> out;
  for (const auto& s : list)
    if (s.kind == dr::ShapeKind::path && s.stroke == colour) out.push_back(s);
  return out;
}
std::vector<dr::Shape> fills(const std::vector<dr::Shape>& list, const std::string& colour) {
  std::vector<dr::Shape> out;
  for (const auto& s : list)
    if (s.kind == dr::ShapeKind::path && s.fill == colour && s.stroke.empty()) out.push_back(s);
  return out;
}

// Even-odd point in polygon (the polygons here are simple).
bool inside(const std::vector<dr::Vec2>& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto &a = poly[i], &b = poly[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}
double dist_to_strokes(const std::vector<dr::Shape>& paths, double x, double y) {
  double best = 1e9;
  for (const auto& s : paths)
    for (std::size_t i = 0; i + 1 < s.pts.size() + (s.closed ? 1 : 0); ++i) {
      const auto& a = s.pts[i];
      const auto& b = s.pts[(i + 1) % s.pts.size()];
      const double vx = b.x - a.x, vy = b.y - a.y, L = vx * vx + vy * vy;
      const double t = L > 0 ? std::clamp(((x - a.x) * vx + (y - a.y) * vy) / L, 0.0, 1.0) : 0;
      best = std::min(best, std::hypot(a.x + t * vx - x, a.y + t * vy - y));
    }
  return best;
}

dr::Style ink() { return dr::Style().color(kInk); }

TEST(DrawCircle, AFiniteCircleIsTheEuclideanCircleOnItsSide) {
  // Centre (1, 0.5), radius 1.5 — on the front, and the same circle written on the back.
  for (const double s : {1.0, 2.0, -1.0}) {
    dr::Figure f;
    f.add(Circle(Point(s, s * 1, s * 0.5), Point(s, s * 2.5, s * 0.5)), ink());
    PlaneMap pm;
    const auto paths = strokes(dr::display_list(f, pm.v), kInk);
    ASSERT_EQ(paths.size(), 1u) << s;
    EXPECT_TRUE(paths[0].closed);
    EXPECT_EQ(paths[0].part, s > 0 ? dr::Part::front : dr::Part::back);
    EXPECT_EQ(paths[0].dash.empty(), s > 0);  // the back side is dashed
    EXPECT_GE(paths[0].pts.size(), 100u);
    for (const auto& p : paths[0].pts) {
      const auto [x, y] = pm.xy(p);
      EXPECT_NEAR(std::hypot(x - 1, y - 0.5), 1.5, 1e-9);
    }
    SphereMap sm;
    for (const auto& sh : strokes(dr::display_list(f, sm.v), kInk))
      for (const auto& p : sh.pts) {
        const auto q = sm.unproject(p, !sh.hidden);
        ASSERT_TRUE(q.has_value());
        EXPECT_EQ(q->z > 0, s > 0);
        // 1e-3: the points where a run meets the limb are interpolated between two samples
        // 1.5° apart (a sagitta below 1e-4 of the sphere), far below a pixel.
        EXPECT_NEAR(std::hypot(q->x / q->z - 1, q->y / q->z - 0.5), 1.5, 1e-3);
      }
  }
}

TEST(DrawCircle, ABeyondInfinityCircleLiesOnTheOtherSideAroundTheSameSpot) {
  dr::Figure f;
  const Point c(1, 1, 0.5), p(-1, -3.5, -0.5);  // p on the back at Cartesian distance 2.5
  ASSERT_EQ(radius_kind(Circle(c, p)), RadiusKind::beyond_infinity);
  f.add(Circle(c, p), ink());
  PlaneMap pm;
  const auto paths = strokes(dr::display_list(f, pm.v), kInk);
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(paths[0].part, dr::Part::back);
  EXPECT_FALSE(paths[0].dash.empty());
  for (const auto& q : paths[0].pts) {
    const auto [x, y] = pm.xy(q);
    EXPECT_NEAR(std::hypot(x - 1, y - 0.5), 2.5, 1e-9);
  }
  // On the sphere: around ¬c, on the lower hemisphere, split at the limb into visible and
  // hidden runs that still lie on the circle.
  SphereMap sm;
  sm.v.lat = 10;
  int hidden = 0, visible = 0;
  for (const auto& sh : strokes(dr::display_list(f, sm.v), kInk)) {
    (sh.hidden ? hidden : visible)++;
    for (const auto& q : sh.pts) {
      const auto s = sm.unproject(q, !sh.hidden);
      ASSERT_TRUE(s.has_value());
      EXPECT_LT(s->z, 0);
      EXPECT_NEAR(std::hypot(s->x / s->z - 1, s->y / s->z - 0.5), 2.5, 1e-3);  // as above
    }
  }
  EXPECT_GE(hidden, 1);
  EXPECT_GE(visible, 1);
}

TEST(DrawCircle, ItsOrientationIsTheOrientationOfT2) {
  // Three samples of the drawn loop turn as the circle is oriented, by the exact orient(),
  // on both sides (on the back, positive runs clockwise as drawn).
  for (const double s : {1.0, -1.0})
    for (const Sign o : {POSITIVE, NEGATIVE}) {
      dr::Figure f;
      f.add(Circle(Point(s, s * -2, s * 1), Point(s, s * -2, s * 4), o));
      const auto& pts = f.items().at(0).points;
      ASSERT_EQ(f.items()[0].kind, dr::ItemKind::circle);
      const std::size_t n = pts.size();
      EXPECT_EQ(orient(pts[0], pts[n / 3], pts[2 * n / 3]), o) << s;
      EXPECT_EQ(orient(pts[n / 5], pts[n / 2], pts[n - 1]), o) << s;
    }
}

TEST(DrawCircle, InfiniteRadiiAreALineOrOmega) {
  // Centre at infinity: the line through the boundary point perpendicular to the centre's
  // direction, with the centre on its left for a positive circle.
  for (const Sign o : {POSITIVE, NEGATIVE}) {
    const Point c(0, 1, 1), p(1, -2, 0);
    dr::Figure f;
    f.add(Circle(c, p, o), ink());
    ASSERT_EQ(f.items().size(), 1u);
    ASSERT_EQ(f.items()[0].kind, dr::ItemKind::line);
    const Line& l = f.items()[0].line;
    EXPECT_EQ(side(l, p), ZERO);
    EXPECT_EQ(l.X() * c.y() - l.Y() * c.x(), 0);  // normal parallel to the centre's direction
    EXPECT_EQ(side(l, c), o);
  }
  // A proper centre with its boundary on Ω: Ω itself, the centre's hemisphere on its left.
  for (const Point c : {Point(1, 3, 1), Point(-2, 1, 1)}) {
    dr::Figure f;
    f.add(Circle(c, Point(0, 1, 0)), ink().fill("#00ff00"));
    ASSERT_EQ(f.items()[0].kind, dr::ItemKind::line);
    const Line& l = f.items()[0].line;
    EXPECT_EQ(l.X(), 0);
    EXPECT_EQ(l.Y(), 0);
    EXPECT_EQ(side(l, c), POSITIVE);
    EXPECT_TRUE(f.items()[0].style.shade());  // fill: the centre's hemisphere is shaded
  }
  EXPECT_THROW(Circle(Point(0, 1, 0), Point(0, 0, 1)), Undefined);
}

TEST(DrawCircle, ExactAndDoubleCirclesGiveTheSameFigure) {
  dr::Figure a, b;
  a.add(Circle(Point(1, 1, 2), Point(1, 3, 2)), ink().fill("#ff0000").arrow().label("c"));
  b.add(ExactCircle(ExactPoint(1, 1, 2), ExactPoint(1, 3, 2)), ink().fill("#ff0000").arrow().label("c"));
  a.add(Circle(Point(0, 1, 0), Point(1, 3, 2)));
  b.add(ExactCircle(ExactPoint(0, 1, 0), ExactPoint(1, 3, 2)));
  EXPECT_TRUE(dr::render(a, dr::PlaneView()) == dr::render(b, dr::PlaneView()));
  EXPECT_TRUE(dr::render(a, dr::SphereView()) == dr::render(b, dr::SphereView()));
}

// A filled triangle agrees with bounded_side() at every pixel not within 2 pixels of its edges.
void expect_fill_matches(const Triangle& t) {
  dr::Figure f;
  f.add(t, ink().fill(kInk));
  PlaneMap pm;
  pm.v.half_width = 5;
  const auto list = dr::display_list(f, pm.v);
  const auto edges = strokes(list, kInk), areas = fills(list, kInk);
  std::vector<dr::Vec2> front, back;
  for (const auto& a : areas) (a.part == dr::Part::front ? front : back) = a.pts;
  int checked = 0;
  for (double py = 2; py < pm.v.size; py += 7)
    for (double px = 2; px < pm.v.size; px += 7) {
      const auto [x, y] = pm.xy({px, py});
      if (std::hypot(x - pm.v.cx, y - pm.v.cy) > pm.v.half_width * 0.99) continue;  // outside the shown disk
      if (dist_to_strokes(edges, px, py) < 2) continue;
      ++checked;
      const Point p(1, x, y);
      EXPECT_EQ(bounded_side(t, p) == BoundedSide::inside, !front.empty() && inside(front, px, py))
          << to_string(t) << " at " << to_string(p);
      EXPECT_EQ(bounded_side(t, antipode(p)) == BoundedSide::inside, !back.empty() && inside(back, px, py))
          << to_string(t) << " at " << to_string(antipode(p));
    }
  EXPECT_GT(checked, 500);
  // The spherical model: the fill is the visible part of the triangle.
  SphereMap sm;
  sm.v.lat = 5;
  sm.v.lon = 200;
  const auto slist = dr::display_list(f, sm.v);
  const auto sedges = strokes(slist, kInk), sareas = fills(slist, kInk);
  ASSERT_LE(sareas.size(), 1u);
  checked = 0;
  for (double py = 2; py < sm.v.size; py += 7)
    for (double px = 2; px < sm.v.size; px += 7) {
      const auto s = sm.unproject({px, py}, true);
      if (!s || std::hypot(px - sm.v.size / 2.0, py - sm.v.size / 2.0) > sm.scale() - 2) continue;
      if (dist_to_strokes(sedges, px, py) < 2) continue;
      ++checked;
      const Point p(s->z, s->x, s->y);
      EXPECT_EQ(bounded_side(t, p) == BoundedSide::inside, !sareas.empty() && inside(sareas[0].pts, px, py))
          << to_string(t) << " at " << to_string(p);
    }
  EXPECT_GT(checked, 500);
}

TEST(DrawRegion, AFilledPolygonIsItsRegionOfT2OnBothSidesAndOnTheSphere) {
  expect_fill_matches(Triangle(Point(1, -2, -2), Point(1, 2, -3), Point(1, 0, 3)));     // front only
  expect_fill_matches(Triangle(Point(1, -2, -2), Point(1, -1, -3), Point(-1, 1, -3)));  // crosses Ω
  expect_fill_matches(Triangle(Point(-1, 0, 0), Point(1, 3, 1), Point(0, -1, 2)));      // a vertex on Ω
  expect_fill_matches(Triangle(Point(-1, -1, 0), Point(-1, 1, -4), Point(-1, 2, 3)));   // back only
}

TEST(DrawPrimitives, SegmentsRaysTrianglesRectanglesAndBoxesAreTheirPolygons) {
  auto same = [](const dr::Figure& a, const dr::Figure& b) {
    // (EXPECT_TRUE: a failure should not print two SVG documents)
    EXPECT_TRUE(dr::render(a, dr::PlaneView()) == dr::render(b, dr::PlaneView()));
    EXPECT_TRUE(dr::render(a, dr::SphereView()) == dr::render(b, dr::SphereView()));
  };
  const Point p(1, 1, 2), q(-1, 2, 1), r(1, -1, 0.5);
  dr::Figure a, b;
  a.add(Segment(p, q), ink());
  b.segment(p, q, ink());
  same(a, b);
  a = b = dr::Figure();
  a.add(Ray(p, Point(0, 1, -1)), ink());
  b.segment(p, Point(0, 1, -1), ink());
  same(a, b);
  a = b = dr::Figure();
  a.add(Triangle(p, q, r), ink().fill("#00ff00"));
  b.add(std::vector<Point>{p, q, r}, ink().fill("#00ff00"));
  same(a, b);
  // An iso-rectangle unbounded in x: a, then b = c = [0, 1, 0] on Ω (drawn once), then d.
  const IsoRect rect(Point(1, 0, 0), T1(0, 1), T1(1, 2));
  ASSERT_EQ(rect.vertex(1), rect.vertex(2));
  a = b = dr::Figure();
  a.add(rect, ink());
  b.add(std::vector<Point>{rect.vertex(0), rect.vertex(1), rect.vertex(3)}, ink());
  same(a, b);
  const BBox box(Point(1, 0, 0), T1(0, 1), T1(0, 1));  // the quadrant x, y ≥ 0
  a = dr::Figure();
  a.add(box, ink());
  ASSERT_EQ(a.items().size(), 1u);
  EXPECT_EQ(a.items()[0].points.size(), 4u);
  // Exact coordinates instantiate the same overloads.
  dr::Figure e;
  e.add(ExactSegment(ExactPoint(1, 1, 2), ExactPoint(-1, 2, 1)), ink());
  e.add(ExactRay(ExactPoint(1, 1, 2), ExactPoint(0, 1, -1)), ink());
  e.add(ExactTriangle(ExactPoint(1, 1, 2), ExactPoint(-1, 2, 1), ExactPoint(1, -1, 1)), ink());
  e.add(ExactIsoRect(ExactPoint(1, 0, 0), ExactT1(0, 1), ExactT1(1, 2)), ink());
  e.add(ExactBBox(ExactPoint(1, 0, 0), ExactT1(0, 1), ExactT1(0, 1)), ink());
  EXPECT_EQ(e.items().size(), 5u);
  EXPECT_EQ(e.items()[4].points.size(), 4u);
}

TEST(DrawTitle, ATitleGetsItsOwnBandAboveThePicture) {
  dr::Figure f;
  f.add(Line(1, 0, 0), ink());  // Ω: the ring reaches the top of the planar picture
  f.add(Point(1, 0, 3.9), ink());
  f.title("a title");
  for (int model = 0; model < 2; ++model) {
    const auto list = model == 0 ? dr::display_list(f, dr::PlaneView()) : dr::display_list(f, dr::SphereView());
    int titles = 0;
    for (const auto& s : list)
      for (const auto& p : s.pts) {
        if (s.kind == dr::ShapeKind::text && s.text == "a title") {
          ++titles;
          EXPECT_LT(p.y, dr::title_band);
        } else {
          EXPECT_GE(p.y, dr::title_band - 1e-9) << "model " << model;  // below the band
        }
      }
    EXPECT_EQ(titles, 1);
  }
  const std::string svg = dr::render(f, dr::PlaneView());
  EXPECT_NE(svg.find("height=\"384px\""), std::string::npos);  // 360 + 24
  dr::Figure untitled;
  EXPECT_NE(dr::render(untitled, dr::PlaneView()).find("height=\"360px\""), std::string::npos);
}

}  // namespace
}  // namespace t2
