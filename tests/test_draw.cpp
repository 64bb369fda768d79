// The projection mathematics of the drawing library (t2/draw/view.hpp) and the rules of the
// display list (t2/draw/render.hpp), checked against independent formulas: the viewing
// direction from its latitude and longitude, the orthographic identity |P|² + depth² = 1, the
// implicit equation of the ellipse, and the conventions of the models (back hollow and dashed,
// points at infinity on the Ω ring). Tolerances here are for floating-point *drawing*, never for
// a predicate.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "t2/draw.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

namespace dr = t2::draw;

constexpr double kDeg = std::numbers::pi / 180;

struct V3 {
  double x, y, z;
};
double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 unit(const V3& a) {
  const double n = std::sqrt(dot(a, a));
  return {a.x / n, a.y / n, a.z / n};
}
V3 cross(const V3& a, const V3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 of(const dr::Vec3& v) { return {v.x, v.y, v.z}; }

// The viewing direction, written independently of the library.
V3 eye_of(double lat, double lon) {
  return {std::cos(lat * kDeg) * std::cos(lon * kDeg), std::cos(lat * kDeg) * std::sin(lon * kDeg), std::sin(lat * kDeg)};
}

dr::SphereView random_view(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> lat(-89, 89), lon(-180, 180);
  dr::SphereView v;
  v.lat = lat(rng);
  v.lon = lon(rng);
  return v;
}

Point random_point(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> c(-10, 10);
  for (;;) {
    const Point p(c(rng), c(rng), c(rng));
    if (std::fabs(p.w()) + std::fabs(p.x()) + std::fabs(p.y()) > 1e-3) return p;
  }
}

TEST(DrawView, AntipodesProjectToOppositePointsOfTheSphere) {
  std::mt19937_64 rng(1);
  const int n = 2000 * testing::scale();
  for (int i = 0; i < n; ++i) {
    const dr::SphereView v = random_view(rng);
    const Point p = random_point(rng);
    const dr::Vec2 a = v.project(p), b = v.project(antipode(p));
    // Negation commutes with every rounding step, so the images are exactly opposite.
    EXPECT_EQ(a.x, -b.x) << to_string(p);
    EXPECT_EQ(a.y, -b.y) << to_string(p);
    const dr::Vec3 s = dr::on_sphere(p), t = dr::on_sphere(antipode(p));
    EXPECT_EQ(v.depth(s), -v.depth(t));
    // On the sphere, and in the direction of (x, y, w).
    EXPECT_NEAR(dot(of(s), of(s)), 1, 1e-14);
    const V3 d = unit({p.x(), p.y(), p.w()});
    EXPECT_NEAR(dot(of(s), d), 1, 1e-14);
    // Orthographic projection: what is not depth is on the picture.
    const V3 e = eye_of(v.lat, v.lon);
    EXPECT_NEAR(a.x * a.x + a.y * a.y + dot(of(s), e) * dot(of(s), e), 1, 1e-12);
    EXPECT_NEAR(v.depth(s), dot(of(s), e), 1e-14);
  }
}

TEST(DrawView, TheFrontSideIsTheUpperHemisphere) {
  dr::SphereView top;
  top.lat = 90;  // seen from above: the front side faces the viewer, Ω is the outline
  EXPECT_GT(top.depth(dr::on_sphere(Point(1, 3, -2))), 0);
  EXPECT_LT(top.depth(dr::on_sphere(Point(-1, 3, -2))), 0);
  EXPECT_NEAR(top.depth(dr::on_sphere(Point(0, 3, -2))), 0, 1e-15);
  const dr::Vec2 q = top.project(Point(0, 3, -2));
  EXPECT_NEAR(std::hypot(q.x, q.y), 1, 1e-14);
}

// facing() looks straight at the data: a cap of points around a direction is seen around the
// middle of the picture (the cap's axis at depth 1, the picture's centre), whatever the side.
TEST(DrawView, FacingLooksStraightAtTheMeanOfThePoints) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int i = 0; i < 200; ++i) {
    const Point c = random_point(rng);
    const V3 axis = unit({c.x(), c.y(), c.w()});
    if (std::fabs(axis.z) > 0.95) continue;  // near a pole: the rule of the next test
    std::vector<Point> cap;  // c and its mirror images about it: their mean is c's direction
    for (int k = 0; k < 4; ++k) {
      const double dw = u(rng), dx = u(rng), dy = u(rng);
      const double n = std::sqrt(c.w() * c.w() + c.x() * c.x() + c.y() * c.y());
      cap.push_back(Point(c.w() / n + dw, c.x() / n + dx, c.y() / n + dy));
      cap.push_back(Point(c.w() / n - dw, c.x() / n - dx, c.y() / n - dy));
    }
    V3 m{0, 0, 0};
    for (const Point& p : cap) {
      const V3 s = unit({p.x(), p.y(), p.w()});
      m = {m.x + s.x, m.y + s.y, m.z + s.z};
    }
    const dr::SphereView v = dr::facing(cap);
    EXPECT_NEAR(dot(eye_of(v.lat, v.lon), unit(m)), 1, 1e-12) << to_string(c);
  }
}

TEST(DrawView, FacingNearAPoleIsTurnedAsThePlanarModel) {
  const std::vector<Point> front{Point::cartesian(0.1, 0.05), Point::cartesian(-0.2, 0.1), Point::cartesian(0.05, -0.1)};
  const dr::SphereView v = dr::facing(front);
  EXPECT_EQ(v.lat, 90);
  EXPECT_EQ(v.lon, -90);
  const dr::Vec2 x = v.project(Point::cartesian(1, 0)), y = v.project(Point::cartesian(0, 1));
  EXPECT_GT(x.x, 0);  // x to the right
  EXPECT_NEAR(x.y, 0, 1e-12);
  EXPECT_GT(y.y, 0);  // y up
  EXPECT_NEAR(y.x, 0, 1e-12);
  dr::SphereView base;
  base.lat = 12;
  base.size = 200;
  const dr::SphereView same = dr::facing({Point::cartesian(1, 1), antipode(Point::cartesian(1, 1))}, base);
  EXPECT_EQ(same.lat, 12);  // balanced points: the base view, unchanged
  EXPECT_EQ(same.lon, base.lon);
  EXPECT_EQ(dr::facing({Point::cartesian(1, 1)}, base).size, 200);
}

TEST(DrawView, AGreatCircleProjectsToAnEllipseTangentToTheOutline) {
  std::mt19937_64 rng(2);
  const int n = 300 * testing::scale();
  int checked = 0;
  for (int i = 0; i < n; ++i) {
    const dr::SphereView v = random_view(rng);
    const Point a = random_point(rng), b = random_point(rng);
    const Line l = join(a, b);
    const V3 nrm = unit({l.X(), l.Y(), l.W()});
    const V3 e = eye_of(v.lat, v.lon);
    if (std::fabs(dot(nrm, e)) < 0.05 || std::fabs(dot(nrm, e)) > 0.999) continue;  // nearly edge-on or face-on
    ++checked;
    const dr::Ellipse el = dr::great_circle_ellipse(l, v);
    EXPECT_NEAR(std::hypot(el.major.x, el.major.y), 1, 1e-12);
    EXPECT_NEAR(el.minor, std::fabs(dot(nrm, e)), 1e-12);
    EXPECT_LE(el.minor, 1 + 1e-12);
    const dr::Vec2 minor_dir{-el.major.y, el.major.x};
    // Sample the great circle: the points s with s · n = 0 (an orthonormal basis of its plane).
    const V3 u1 = unit(cross(nrm, std::fabs(nrm.x) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0}));
    const V3 u2 = cross(nrm, u1);
    double most = 0;
    for (int k = 0; k < 64; ++k) {
      const double t = 2 * std::numbers::pi * k / 64;
      const V3 s{std::cos(t) * u1.x + std::sin(t) * u2.x, std::cos(t) * u1.y + std::sin(t) * u2.y,
                 std::cos(t) * u1.z + std::sin(t) * u2.z};
      const dr::Vec2 P = v.project(dr::Vec3{s.x, s.y, s.z});
      const double pu = P.x * el.major.x + P.y * el.major.y, pv = P.x * minor_dir.x + P.y * minor_dir.y;
      EXPECT_NEAR(pu * pu + pv * pv / (el.minor * el.minor), 1, 1e-9) << "line " << to_string(a) << " v " << to_string(b);
      most = std::max(most, std::hypot(P.x, P.y));
    }
    EXPECT_LE(most, 1 + 1e-12);  // inside the outline ...
    // ... and touching it at the limb points, which project to ±major and lie on the circle.
    const auto lp = dr::limb_points(l, v);
    ASSERT_TRUE(lp.has_value());
    for (const dr::Vec3& s : {lp->first, lp->second}) {
      EXPECT_NEAR(dot(of(s), nrm), 0, 1e-12);
      EXPECT_NEAR(dot(of(s), e), 0, 1e-12);
      const dr::Vec2 P = v.project(s);
      EXPECT_NEAR(std::hypot(P.x, P.y), 1, 1e-12);
      EXPECT_NEAR(std::fabs(P.x * el.major.x + P.y * el.major.y), 1, 1e-12);
    }
  }
  EXPECT_GT(checked, n / 2);
}

TEST(DrawView, ASegmentIsSplitWhereItCrossesTheLimb) {
  std::mt19937_64 rng(3);
  const int n = 2000 * testing::scale();
  for (int i = 0; i < n; ++i) {
    const dr::SphereView v = random_view(rng);
    const Point p = random_point(rng), q = random_point(rng);
    const auto pieces = dr::split_at_limb(p, q, v);
    const V3 e = eye_of(v.lat, v.lon);
    const double dp = dot(unit({p.x(), p.y(), p.w()}), e), dq = dot(unit({q.x(), q.y(), q.w()}), e);
    if (dp * dq < 0) {
      ASSERT_EQ(pieces.size(), 2u);
      EXPECT_NEAR(dot(of(pieces[0].b), e), 0, 1e-12);
      EXPECT_EQ(pieces[0].visible, dp > 0);
      EXPECT_EQ(pieces[1].visible, dq > 0);
    } else if (dp * dq > 0) {
      ASSERT_EQ(pieces.size(), 1u);
      EXPECT_EQ(pieces[0].visible, dp > 0);
    }
  }
  EXPECT_THROW(dr::split_at_limb(Point(1, 2, 3), Point(-1, -2, -3), dr::SphereView()), Undefined);
}

TEST(DrawView, APointAtInfinityLandsOnTheOmegaRingAtItsDirection) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> c(-5, 5), hw(0.5, 20);
  const int n = 2000 * testing::scale();
  for (int i = 0; i < n; ++i) {
    dr::PlaneView v;
    v.half_width = hw(rng);
    v.cx = c(rng);
    v.cy = c(rng);
    const double x = c(rng), y = c(rng);
    if (x == 0 && y == 0) continue;
    const dr::Vec2 at = v.place(Point(0, x, y));
    EXPECT_NEAR(std::hypot(at.x, at.y), dr::PlaneView::ring, 1e-12);
    EXPECT_NEAR(at.x * y - at.y * x, 0, 1e-12 * std::hypot(x, y));  // parallel to (x, y) ...
    EXPECT_GT(at.x * x + at.y * y, 0);                              // ... and the same way
    // A proper point and its antipode land on the same spot of the plane.
    const Point p(c(rng) == 0 ? 1 : c(rng), x, y);
    if (p.w() == 0) continue;
    const dr::Vec2 a = v.place(p), b = v.place(antipode(p));
    EXPECT_NEAR(a.x, (x / p.w() - v.cx) / v.half_width, 1e-12 * (1 + std::fabs(a.x)));
    EXPECT_NEAR(a.y, (y / p.w() - v.cy) / v.half_width, 1e-12 * (1 + std::fabs(a.y)));
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
  }
}

std::vector<dr::Shape> markers(const std::vector<dr::Shape>& list) {
  std::vector<dr::Shape> out;
  for (const auto& s : list)
    if (s.kind == dr::ShapeKind::marker) out.push_back(s);
  return out;
}

TEST(DrawDisplayList, APointAtInfinityIsDrawnOnTheRingInThePlane) {
  dr::PlaneView v;
  v.half_width = 3;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{1, 0}, {0, 1}, {-2, 1}, {3, -4}}) {
    dr::Figure f;
    f.add(Point(1, v.half_width, 0));  // a front point on the edge of the visible disk
    f.add(Point(0, x, y));
    const auto m = markers(dr::display_list(f, v));
    ASSERT_EQ(m.size(), 2u);
    EXPECT_EQ(m[0].part, dr::Part::front);
    EXPECT_EQ(m[1].part, dr::Part::infinity);
    const double c = v.size / 2.0;  // the picture is centred on the view
    const double edge = std::hypot(m[0].pts[0].x - c, m[0].pts[0].y - c);
    const double dx = m[1].pts[0].x - c, dy = -(m[1].pts[0].y - c);  // pixels: y down
    EXPECT_NEAR(std::hypot(dx, dy), dr::PlaneView::ring * edge, 1e-9);
    EXPECT_NEAR(dx * y - dy * x, 0, 1e-9 * std::hypot(x, y) * edge);
    EXPECT_GT(dx * x + dy * y, 0);
  }
}

TEST(DrawDisplayList, BackPointsAreHollowAndTheBackSideIsDashed) {
  const Point front(1, 1, 0.5), back(-1, 1, -2), back2(-2, -1, -1);
  dr::Figure f;
  f.add(front);
  f.add(back);
  f.segment(back, back2);  // entirely on the back side
  f.segment(front, Point(1, -1, 1));  // entirely on the front side
  for (int model = 0; model < 2; ++model) {
    const auto list = model == 0 ? dr::display_list(f, dr::PlaneView()) : dr::display_list(f, dr::SphereView());
    const auto m = markers(list);
    ASSERT_EQ(m.size(), 2u);
    EXPECT_EQ(m[0].part, dr::Part::front);
    EXPECT_FALSE(m[0].hollow);
    EXPECT_FALSE(m[0].fill.empty());
    EXPECT_EQ(m[1].part, dr::Part::back);
    EXPECT_TRUE(m[1].hollow);
    EXPECT_TRUE(m[1].fill.empty());
    int back_paths = 0, front_paths = 0;
    for (const auto& s : list) {
      if (s.kind != dr::ShapeKind::path) continue;
      if (s.part == dr::Part::back) {
        ++back_paths;
        EXPECT_FALSE(s.dash.empty()) << "model " << model;
      } else if (s.part == dr::Part::front && !s.hidden) {
        ++front_paths;
        EXPECT_TRUE(s.dash.empty()) << "model " << model;
      }
    }
    EXPECT_GE(back_paths, 1) << "model " << model;
    EXPECT_GE(front_paths, 1) << "model " << model;
  }
}

TEST(DrawDisplayList, ExactAndDoubleCoordinatesGiveTheSameFigure) {
  // Figure's templates with Integer coordinates round to the same double points.
  dr::Figure a, b;
  a.add(Point(1, 2, 3)).segment(Point(1, 0, 0), Point(-1, 2, 1)).add(join(Point(1, 0, 0), Point(1, 1, 1)));
  a.add(std::vector<Point>{Point(1, 0, 0), Point(1, 1, 0), Point(1, 0, 1)}).polyline(std::vector<Point>{Point(1, 0, 0), Point(0, 1, 1)});
  b.add(ExactPoint(1, 2, 3)).segment(ExactPoint(1, 0, 0), ExactPoint(-1, 2, 1)).add(join(ExactPoint(1, 0, 0), ExactPoint(1, 1, 1)));
  b.add(std::vector<ExactPoint>{ExactPoint(1, 0, 0), ExactPoint(1, 1, 0), ExactPoint(1, 0, 1)})
      .polyline(std::vector<ExactPoint>{ExactPoint(1, 0, 0), ExactPoint(0, 1, 1)});
  EXPECT_EQ(dr::render(a, dr::PlaneView()), dr::render(b, dr::PlaneView()));
  EXPECT_EQ(dr::render(a, dr::SphereView()), dr::render(b, dr::SphereView()));
  EXPECT_THROW(dr::Figure().segment(Point(1, 2, 3), Point(-1, -2, -3)), Undefined);
}

TEST(DrawRender, TheSameFigureGivesTheSameBytes) {
  auto make = [] {
    dr::Figure f;
    f.add(Point(1, 1, 0.5), dr::Style().label("p"));
    f.add(Point(-1, -2, 1), dr::Style().label("q"));
    f.segment(Point(1, 1, 0.5), Point(-1, -2, 1), dr::Style().color("#1f77b4"));
    f.add(join(Point(1, 1, 0.5), Point(1, 0, 2)), dr::Style().shade());
    return f;
  };
  for (const dr::Format fmt : {dr::Format::svg, dr::Format::png, dr::Format::pdf}) {
    const std::string a = dr::render(make(), dr::PlaneView(), fmt), b = dr::render(make(), dr::PlaneView(), fmt);
    EXPECT_GT(a.size(), 100u);
    EXPECT_EQ(a, b) << static_cast<int>(fmt);
    EXPECT_EQ(dr::render_both(make(), dr::PlaneView(), dr::SphereView(), fmt),
              dr::render_both(make(), dr::PlaneView(), dr::SphereView(), fmt));
  }
  EXPECT_TRUE(dr::render(make(), dr::SphereView()).starts_with("<?xml"));
  EXPECT_TRUE(dr::render(make(), dr::SphereView(), dr::Format::png).starts_with("\x89PNG"));
  EXPECT_TRUE(dr::render(make(), dr::SphereView(), dr::Format::pdf).starts_with("%PDF"));
  EXPECT_EQ(dr::format_of("a/b.svg"), dr::Format::svg);
  EXPECT_EQ(dr::format_of("b.png"), dr::Format::png);
  EXPECT_EQ(dr::format_of("b.pdf"), dr::Format::pdf);
  EXPECT_THROW(dr::format_of("b.jpg"), BadInput);
}

}  // namespace
}  // namespace t2
