// The points of chapter 15 and its figures, in the planar and the spherical model.
#include "figures.hpp"

#include <t2/draw.hpp>
#include <t2/range/locus.hpp>

#include <iostream>
#include <string>

namespace chapter15 {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::IsoRect;
using t2::Point;
using t2::T1;

std::vector<Point> five_points() {
  return {Point::cartesian(-2, 1), Point::cartesian(-1, -2), Point::cartesian(0, 2), Point::cartesian(1, -1),
          Point::cartesian(2, 0)};
}

std::vector<Point> mixed_points() {
  return {Point::cartesian(0.5, 0.5), Point::cartesian(1.5, 0.5), Point::cartesian(-0.5, 0.5),
          Point::cartesian(2.5, 1.5), Point(-1, -0.5, -0.5),      Point(-1, -1.5, -1),
          Point(0, 1, 0),             Point(0, 1, 1),              Point(0, -1, 1)};
}

namespace {

void points(dr::Figure& f, const std::vector<Point>& P) {
  for (std::size_t i = 0; i < P.size(); ++i) f.add(P[i], dr::Style().size(3.5).label("p" + std::to_string(i)));
}

// A quadrant towards −∞ from the corner (x, y): the points it dominates.
IsoRect below_left(double x, double y) { return IsoRect(Point::cartesian(x, y), T1(0, -1), T1(0, -1)); }

}  // namespace

void figures(const std::filesystem::path& dir) {
  dr::FigurePairs out(dir);
  const dr::Style shade = dr::Style().color(pal::blue).width(1.2).fill(pal::blue).fill_opacity(0.15);
  dr::PlaneView pv;
  pv.half_width = 3.5;
  dr::SphereView above;
  above.lat = 75;
  above.lon = -90;
  const auto P = five_points();
  {  // Figure 5.38: the points dominated by a corner.
    dr::Figure f;
    f.add(below_left(1.5, 0.5), shade);
    points(f, P);
    f.add(Point::cartesian(1.5, 0.5), dr::Style().color(pal::red).size(4.5).label("q: Q(q) = 2").label_angle(30));
    out.save(f, "dominance", pv, above);
  }
  {  // Figure 5.39: a rectangle by inclusion and exclusion of four quadrants.
    dr::Figure f;
    f.add(IsoRect(Point::cartesian(-1.5, -1.5), T1(1, 3), T1(1, 3)), shade);
    points(f, P);
    const char* names[] = {"q3", "q4", "q1", "q2"};  // lower left, lower right, upper right, upper left
    const double xy[][2] = {{-1.5, -1.5}, {1.5, -1.5}, {1.5, 1.5}, {-1.5, 1.5}};
    for (int k = 0; k < 4; ++k)
      f.add(Point::cartesian(xy[k][0], xy[k][1]), dr::Style().color(pal::red).size(4).label(names[k]).label_angle(-45));
    out.save(f, "inclusion-exclusion", pv, above);
  }
  {  // Figures 5.40-5.42: the grid of the lines through the points, and Q at its corners.
    const t2::LocusCounter L(P);
    dr::Figure f;
    for (const Point& p : P) {
      f.add(t2::join(p, Point(0, 0, 1)), dr::Style().color(pal::grey).width(0.8));
      f.add(t2::join(p, Point(0, 1, 0)), dr::Style().color(pal::grey).width(0.8));
    }
    points(f, P);
    for (double x : {-1.5, -0.5, 0.5, 1.5, 2.5})
      for (double y : {-1.5, -0.5, 0.5, 1.5, 2.5})
        f.add(Point::cartesian(x, y), dr::Style().color(pal::red).size(1.5).label(std::to_string(L.count(below_left(x, y)))));
    out.save(f, "grid", pv, above);
  }
  {  // Rectangles of T²: a box, a quadrant reaching Ω, one on the back side.
    const auto M = mixed_points();
    dr::Figure f;
    f.add(IsoRect(Point::cartesian(-1, -1), T1(1, 3), T1(1, 2)), shade);
    f.add(IsoRect(Point::cartesian(0, 0), T1(0, 1), T1(0, 1)),
          dr::Style().color(pal::green).width(1.2).fill(pal::green).fill_opacity(0.15));
    f.add(IsoRect(Point(-1, 0, 0), T1(1, 2), T1(1, 2)),
          dr::Style().color(pal::orange).width(1.2).fill(pal::orange).fill_opacity(0.15));
    points(f, M);
    dr::PlaneView wide;
    wide.half_width = 4;
    dr::SphereView aside;
    aside.lat = 35;
    aside.lon = -60;
    out.save(f, "rectangles-t2", wide, aside);
  }
  std::cerr << out.summary() << "\n";
}

}  // namespace chapter15
