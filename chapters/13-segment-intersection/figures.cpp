// The segment sets of chapter 13 and its figures, in the planar and the spherical model.
#include "figures.hpp"

#include <t2/draw.hpp>
#include <t2/intersect/intersections.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

namespace chapter13 {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Point;
using t2::Segment;

namespace {

Segment seg(double x0, double y0, double x1, double y1) {
  return Segment(Point::cartesian(x0, y0), Point::cartesian(x1, y1));
}

// The same with the coordinates in quarters: [4, x, y] is the point (x/4, y/4).
Segment quarters(double x0, double y0, double x1, double y1) {
  return Segment(Point(4, x0, y0), Point(4, x1, y1));
}

// The sphere seen from the direction of p (its point on the sphere faces the viewer).
dr::SphereView towards(const Point& p, double lat_offset = 0) {
  const dr::Vec3 s = dr::on_sphere(p);
  dr::SphereView v;
  v.lat = std::asin(std::clamp(s.z, -1.0, 1.0)) * 180 / std::numbers::pi + lat_offset;
  v.lon = std::atan2(s.y, s.x) * 180 / std::numbers::pi;
  return v;
}

// Where a segment's name goes: a quarter of the way along as drawn when both ends are on one side,
// else at its source.
Point label_point(const Point& p, const Point& q) {
  if (p.w() * q.w() <= 0) return p;
  const double px = p.x() / p.w(), py = p.y() / p.w(), qx = q.x() / q.w(), qy = q.y() / q.w();
  const double side = p.w() > 0 ? 1 : -1;
  return Point(side, side * (px + (qx - px) / 4), side * (py + (qy - py) / 4));
}

// The segments, numbered at their midpoints, and the reported points with their segment lists.
dr::Figure picture(const std::vector<Segment>& S, const std::vector<t2::IntersectionPoint>& X) {
  dr::Figure f;
  for (std::size_t i = 0; i < S.size(); ++i) {
    const Point& p = S[i].source();
    const Point& q = S[i].target();
    f.add(p, dr::Style().size(2.5));
    f.add(q, dr::Style().size(2.5));
    if (p == q) {
      f.add(p, dr::Style().size(4).color(pal::blue).label("s" + std::to_string(i)).label_angle(-60));
      continue;
    }
    f.segment(p, q, dr::Style().color(pal::blue).width(1.6));
    f.add(label_point(p, q), dr::Style().marker(dr::Marker::none).label("s" + std::to_string(i)).label_angle(-60));
  }
  for (const auto& x : X) {
    std::string l;
    for (std::size_t i : x.segments) l += (l.empty() ? "" : ",") + std::to_string(i);
    f.add(t2::to_double(x.point), dr::Style().color(pal::red).size(4.5).label("{" + l + "}").label_angle(x.point.w() < 0 ? -120 : 60));
  }
  return f;
}

}  // namespace

std::vector<Segment> degenerate_cases() {
  return {quarters(-6, -1, -2, 3), quarters(-6, 3, -2, -1),   // a crossing
          quarters(-1, -1, 3, -1), quarters(1, -1, 1, 2),     // an endpoint inside a segment
          quarters(-1, 3, 2, 3),   quarters(0, 3, 4, 3),      // collinear, overlapping
          quarters(-3, -3, -3, -3), quarters(-5, -3, 0, -3),  // a one-point segment on a segment
          quarters(5, -1, 7, 1),   quarters(5, 1, 7, -1), quarters(6, -2, 6, 2)};  // three through a point
}

std::vector<Segment> two_sided() {
  return {seg(-3, -1, 3, 1),                               // s0: front
          Segment(Point(-1, -3, 1), Point(-1, 3, -1)),     // s1: back, drawn across s0
          Segment(Point(1, 0, -2), Point(-1, 0, 4)),       // s2: front to back through Ω
          Segment(Point(0, 1, 0), Point(0, 0, 1)),         // s3: on Ω
          Segment(Point(-1, 0, -1), Point(-1, 0, 1))};     // s4: back, across s1
}

std::vector<Segment> beside_triple_point() {
  return {seg(2, 3, 5, 0), seg(5, 2, 0, 3), seg(3, 4, 2, 1), seg(1, 3, 3, 2)};
}

std::vector<Segment> sweep_example() {
  return {seg(-5, -2, 4, 3), seg(-4, 3, 5, -3), seg(-3, -4, 2, 4),
          seg(-1, 1, 6, 1),  seg(-6, 0, -2, -3), seg(1, -4, 3, 4)};
}

std::vector<Segment> circular_example() {
  return {seg(2, -1, 3, 2),                              // s0: crosses l(0), cut at w
          seg(3.5, -0.5, 1.5, 1),                        // s1: crosses s0 just after l(0)
          seg(-1.5, 0.5, 0.5, 1.5),                      // s2: front, across l(135°) near o
          seg(-4, 0.5, -1, 4),                           // s3: front, across l(135°) further out
          Segment(Point(1, -2, 4), Point(-1, -1, -3)),   // s4: front to back through Ω
          Segment(Point(-1, -1, 2), Point(-1, -2, 1)),   // s5: back, across l(135°)'s back part
          Segment(Point(-1, 3, 1), Point(-1, 1, 3))};    // s6: back, already swept
}

void figures(const std::filesystem::path& dir) {
  dr::FigurePairs out(dir);
  // A set of segments with what the brute force reports, in a plane of the given half width.
  const auto answer = [&](const std::vector<Segment>& S, const std::string& name, double half_width,
                          const dr::SphereView& sv) {
    dr::PlaneView pv;
    pv.half_width = half_width;
    out.save(picture(S, t2::intersections(S, t2::IntersectAlgorithm::brute)), name, pv, sv);
  };
  dr::SphereView from_above;  // the front pole in the middle
  from_above.lat = 90;
  from_above.lon = -90;
  dr::SphereView aside;  // both poles and Ω in sight
  aside.lat = 20;
  aside.lon = -60;
  answer(degenerate_cases(), "reported", 2.1, from_above);
  answer(two_sided(), "two-sided", 6, aside);  // two points drawn at the origin, one on Ω
  answer(beside_triple_point(), "triple", 6, towards(Point::cartesian(2.5, 2.5), 20));
  {  // The sweep at x = 3/2: the status (bottom to top), the points found so far (left).
    const auto S = sweep_example();
    const auto X = t2::intersections(S, t2::IntersectAlgorithm::sweep);
    const t2::Line sweep_line(-1.5, 1, 0);  // x = 3/2: -3w/2 + x = 0
    std::vector<std::pair<double, std::size_t>> status;
    dr::Figure f;
    for (std::size_t i = 0; i < S.size(); ++i) {
      const double x0 = S[i].source().x(), x1 = S[i].target().x();
      const bool active = std::min(x0, x1) <= 1.5 && 1.5 <= std::max(x0, x1);
      f.segment(S[i].source(), S[i].target(),
                dr::Style().color(active ? pal::blue : pal::grey).width(active ? 1.8 : 1.2));
      if (active) {
        const Point m = t2::normalized(t2::meet(t2::join(S[i].source(), S[i].target()), sweep_line));
        status.push_back({m.y() / m.w(), i});
      }
    }
    std::sort(status.begin(), status.end());
    f.add(sweep_line, dr::Style().color(pal::orange).width(1.4).dash({6, 3}));
    for (std::size_t k = 0; k < status.size(); ++k)
      f.add(Point::cartesian(1.5, status[k].first),
            dr::Style().color(pal::blue).size(3).label(std::to_string(k + 1) + ": s" + std::to_string(status[k].second)).label_angle(180));
    for (const auto& x : X) {
      const Point p = t2::to_double(x.point);
      const bool found = p.x() / p.w() < 1.5;
      f.add(p, dr::Style().color(found ? pal::red : pal::grey).size(found ? 4.5 : 3.5));
    }
    dr::PlaneView pv;
    pv.half_width = 7;
    dr::SphereView sv;
    sv.lat = 65;
    sv.lon = -90;
    out.save(f, "sweep", pv, sv);
  }
  {  // Algorithm 16: the half-line from o to ¬o through [0, 1, 0], and a segment across it.
    const Point o(1, 0, 0), d(0, 1, 0), anti_o(-1, 0, 0);
    dr::Figure f;
    f.segment(o, d, dr::Style().color(pal::orange).width(2));
    f.segment(d, anti_o, dr::Style().color(pal::orange).width(2).dash({6, 3}));
    f.add(o, dr::Style().label("o").color(pal::orange));
    f.add(anti_o, dr::Style().label("¬o").label_angle(-120).color(pal::orange));
    const Segment s0 = seg(2, -1, 3, 2), s1 = seg(3.5, -0.5, 1.5, 1);
    f.segment(s0.source(), s0.target(), dr::Style().color(pal::blue).width(1.8));
    f.segment(s1.source(), s1.target(), dr::Style().color(pal::green).width(1.8));
    f.add(s0.source(), dr::Style().label("s0").size(2.5));
    f.add(s1.source(), dr::Style().label("s1").size(2.5));
    Point cut = t2::normalized(t2::meet(t2::join(s0.source(), s0.target()), t2::Line(0, 0, 1)));
    if (cut.w() < 0) cut = t2::antipode(cut);  // of the line's two points on y = 0, the one on s0
    f.add(cut, dr::Style().color(pal::orange).size(4.5).label("w").label_angle(-30));
    for (const auto& x : t2::intersections({s0, s1}, t2::IntersectAlgorithm::brute))
      f.add(t2::to_double(x.point), dr::Style().color(pal::red).size(4.5));
    dr::PlaneView pv;
    pv.half_width = 4;
    out.save(f, "circular", pv, towards(Point::cartesian(1.5, 0.2)));
  }
  {  // The circular sweep at θ = 135°: l(θ), the status from o outwards, the cut at l(0).
    const auto S = circular_example();
    const auto X = t2::intersections(S, t2::IntersectAlgorithm::circular);
    const Point o(1, 0, 0), d(0, -1, 1), anti_o(-1, 0, 0), r(0, 1, 0);
    const t2::ExactPoint eo = t2::to_exact(o), ed = t2::to_exact(d);
    const auto angle = [](const Point& p) {  // the direction of (x, y), in [0, 2π)
      const double a = std::atan2(p.y(), p.x());
      return a < 0 ? a + 2 * std::numbers::pi : a;
    };
    dr::Figure f;
    f.segment(o, r, dr::Style().color(pal::grey).width(1));
    f.segment(r, anti_o, dr::Style().color(pal::grey).width(1).dash({4, 3}));
    f.segment(o, d, dr::Style().color(pal::orange).width(2));
    f.segment(d, anti_o, dr::Style().color(pal::orange).width(2).dash({6, 3}));
    f.add(o, dr::Style().label("o").color(pal::orange).label_angle(-60));
    std::vector<std::pair<double, std::size_t>> status;  // (distance from o on the sphere, index)
    for (std::size_t i = 0; i < S.size(); ++i) {
      const t2::ExactSegment e(t2::to_exact(S[i].source()), t2::to_exact(S[i].target()));
      t2::ExactPoint m = t2::meet(t2::join(e.source(), e.target()), t2::join(eo, ed));
      if (m.x() * ed.x() + m.y() * ed.y() < 0) m = t2::antipode(m);  // the one on l(θ)
      const bool met = t2::contains(e, m);
      f.segment(S[i].source(), S[i].target(), dr::Style().color(met ? pal::blue : pal::grey).width(met ? 1.8 : 1.2));
      f.add(label_point(S[i].source(), S[i].target()), dr::Style().marker(dr::Marker::none).label("s" + std::to_string(i)));
      if (!met) continue;
      const Point p = t2::to_double(m);
      status.push_back({std::atan2(std::hypot(p.x(), p.y()), p.w()), i});
    }
    std::sort(status.begin(), status.end());
    for (std::size_t k = 0; k < status.size(); ++k) {
      const std::size_t i = status[k].second;
      t2::ExactPoint m = t2::meet(t2::join(t2::to_exact(S[i].source()), t2::to_exact(S[i].target())), t2::join(eo, ed));
      if (m.x() * ed.x() + m.y() * ed.y() < 0) m = t2::antipode(m);
      f.add(t2::to_double(m), dr::Style().color(pal::blue).size(3.5).label(std::to_string(k + 1) + ": s" + std::to_string(i)).label_angle(m.w() < 0 ? std::numeric_limits<double>::quiet_NaN() : -135));
    }
    for (const auto& x : X) {
      const Point p = t2::to_double(x.point);
      const bool found = angle(p) < 0.75 * std::numbers::pi;
      f.add(p, dr::Style().color(found ? pal::red : pal::grey).size(found ? 4.5 : 3.5));
    }
    dr::PlaneView pv;
    pv.half_width = 5;
    out.save(f, "circular-status", pv, towards(Point::cartesian(-0.6, 0.6)));
  }
  std::cerr << out.summary() << "\n";
}

}  // namespace chapter13
