// The points of chapter 15 and its figures, in the planar and the spherical model.
#include "figures.hpp"

#include <t2/draw.hpp>
#include <t2/range/kdtree.hpp>
#include <t2/range/locus.hpp>

#include <random>

#include <algorithm>
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

// The cuts of the kd-tree's nodes owning [lo, hi) of T (kdtree.hpp's implicit layout), each
// drawn across its region [x0, x1] x [y0, y1].
void cuts(dr::Figure& f, const std::vector<t2::DrawnPoint>& T, std::size_t lo, std::size_t hi, int depth,
          double x0, double x1, double y0, double y1) {
  if (hi - lo <= t2::KdTree::kLeaf) return;
  const std::size_t mid = lo + (hi - lo) / 2;
  const double x = T[mid].x / T[mid].w, y = T[mid].y / T[mid].w;  // drawing only: rounded
  const dr::Style cut = dr::Style().color(pal::grey).width(depth == 0 ? 1.6 : depth == 1 ? 1.1 : 0.7);
  if (depth % 2 == 0) {
    f.add(t2::Segment(Point::cartesian(x, y0), Point::cartesian(x, y1)), cut);
    cuts(f, T, lo, mid, depth + 1, x0, x, y0, y1);
    cuts(f, T, mid + 1, hi, depth + 1, x, x1, y0, y1);
  } else {
    f.add(t2::Segment(Point::cartesian(x0, y), Point::cartesian(x1, y)), cut);
    cuts(f, T, lo, mid, depth + 1, x0, x1, y0, y);
    cuts(f, T, mid + 1, hi, depth + 1, x0, x1, y, y1);
  }
}

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
  {  // The kd-tree of 60 points: its cuts, a query and the points it reports.
    std::mt19937_64 rng(1515);
    std::uniform_int_distribution<int> c(-24, 24);
    std::vector<Point> K;
    for (int k = 0; k < 60; ++k) {
      const double x = c(rng) / 8.0, y = c(rng) / 8.0;  // in this order, on every compiler
      K.push_back(Point::cartesian(x, y));
    }
    const t2::KdTree T(K);
    const IsoRect q(Point::cartesian(-0.5, -1.25), T1(1, 2.25), T1(1, 2));
    const t2::ExactIsoRect eq(t2::to_exact(q.a()), t2::to_exact(q.dx()), t2::to_exact(q.dy()));
    const auto in = T.report(eq);
    dr::Figure f;
    f.add(q, shade);
    cuts(f, T.tree_order(0), 0, T.tree_order(0).size(), 0, -3, 3, -3, 3);
    for (std::size_t i = 0; i < K.size(); ++i)
      f.add(K[i], dr::Style().size(2.5).color(std::binary_search(in.begin(), in.end(), i) ? pal::red : pal::black));
    out.save(f, "kdtree", pv, above);
  }
  std::cerr << out.summary() << "\n";
}

}  // namespace chapter15
