// The map of chapter 14 and its figures, in the planar and the spherical model.
#include "figures.hpp"

#include <t2/draw.hpp>
#include <t2/location/trapezoid_locate.hpp>
#include <t2/location/walk.hpp>
#include <t2/triangulation/delaunay.hpp>

#include <algorithm>
#include <iostream>
#include <string>

namespace chapter14 {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Point;
using t2::Subdivision;
using Index = Subdivision::Index;

std::vector<t2::Polygon> fan_map() {
  const Point O(1, 0, 0), a(1, 1, 0), b(1, 0, 1), c(-1, 1, 1), d(1, 0, -1), e(-1, 1, -1);
  return {{O, a, b}, {b, a, c}, {c, a, d}, {d, a, O}, {c, d, e}};
}

t2::Polygon comb(int m) {
  const auto at = [](double x, double y) { return Point(8, x, y); };  // in eighths
  t2::Polygon c{at(0, 0), at(2 * m - 1, 0)};
  for (int i = m - 1; i >= 0; --i) {
    c.push_back(at(2 * i + 1, 2));
    c.push_back(at(2 * i, 2));
    if (i > 0) c.push_back(at(2 * i, 1)), c.push_back(at(2 * i - 1, 1));
  }
  return c;
}

t2::Polygon comb_start() { return {Point(8, -3, 0), Point(8, -1, 1.5), Point(8, -3, 3)}; }

namespace {

const char* const kFill[] = {pal::blue, pal::green, pal::orange, pal::purple, pal::cyan};

// The faces of the map, each named F0 … at a point inside it, and its labelled vertices.
void map(dr::Figure& f, const std::vector<t2::Polygon>& F, double opacity, const std::vector<bool>& strong = {}) {
  for (std::size_t i = 0; i < F.size(); ++i) {
    const bool s = i < strong.size() && strong[i];
    f.add(F[i], dr::Style().color(pal::dark_grey).width(1.2).fill(kFill[i]).fill_opacity(s ? 0.45 : opacity));
  }
  const Point inside[] = {Point(3, 1, 1), Point(1, 2, 2), Point(2, 4, -1), Point(3, 1, -1), Point(4, 2, -6)};
  for (std::size_t i = 0; i < F.size(); ++i)
    f.add(inside[i], dr::Style().size(0.1).label("F" + std::to_string(i)).color(pal::dark_grey));
  const char* names[] = {"O", "a", "b", "c", "d", "e"};
  const Point V[] = {Point(1, 0, 0), Point(1, 1, 0), Point(1, 0, 1), Point(-1, 1, 1), Point(1, 0, -1), Point(-1, 1, -1)};
  for (int k = 0; k < 6; ++k) f.add(V[k], dr::Style().size(2.5).label(names[k]).label_angle(135));
}

// The walk from vertex q to p: the regions it crosses shaded strongly, the segment in red.
dr::Figure walk_picture(const Point& q, const Point& p) {
  const auto F = fan_map();
  const Subdivision S(F);
  Index v = 0;
  while (S.points()[v] != q) ++v;
  std::vector<Index> crossed;
  t2::walk(S, p, v, &crossed);
  std::vector<bool> strong(F.size(), false);
  for (const Index r : crossed)
    if (r != Subdivision::outside) strong[r] = true;
  dr::Figure f;
  map(f, F, 0.08, strong);
  f.segment(q, p, dr::Style().color(pal::red).width(2.2).arrow());
  f.add(q, dr::Style().color(pal::red).size(4).label("q").label_angle(-45));
  f.add(p, dr::Style().color(pal::red).size(4).label("p").label_angle(-45));
  return f;
}

// The trapezoidal map of the front chart of a small Delaunay map, each trapezoid filled, cut
// to the square |x|, |y| ≤ 2.5 (drawing only: the corners are computed in floating point).
dr::Figure trapezoid_picture() {
  const std::vector<Point> P{Point::cartesian(-1.9, -0.8), Point::cartesian(-0.7, -1.6),
                             Point::cartesian(0.6, -1.1),  Point::cartesian(1.7, -0.2),
                             Point::cartesian(1.1, 1.3),   Point::cartesian(-0.4, 0.9),
                             Point::cartesian(-1.3, 1.8),  Point::cartesian(0.2, -0.1)};
  std::vector<std::vector<Index>> F;
  for (const auto& t : t2::delaunay(P).finite_triangles()) F.push_back({t[0], t[1], t[2]});
  const Subdivision S(P, F);
  const t2::TrapezoidLocator L(S, 5);
  const t2::TrapezoidMap& M = *L.chart(t2::TrapezoidLocator::front);
  const auto& Q = S.points();  // the chart's points are the front vertices, in order
  const double B = 2.5;
  const auto y_at = [&](Index s, double x) {
    const auto [a, b] = M.segment(s);
    return Q[a].y() + (Q[b].y() - Q[a].y()) * (x - Q[a].x()) / (Q[b].x() - Q[a].x());
  };
  dr::Figure f;
  const char* const fill[] = {pal::blue, pal::green, pal::orange, pal::purple, pal::cyan};
  std::size_t k = 0;
  for (const auto& t : M.trapezoids()) {
    if (t.node == t2::TrapezoidMap::none) continue;
    const double x0 = t.leftp == t2::TrapezoidMap::none ? -B : Q[t.leftp].x();
    const double x1 = t.rightp == t2::TrapezoidMap::none ? B : Q[t.rightp].x();
    const auto top = [&](double x) { return t.top == t2::TrapezoidMap::none ? B : y_at(t.top, x); };
    const auto bot = [&](double x) { return t.bottom == t2::TrapezoidMap::none ? -B : y_at(t.bottom, x); };
    t2::Polygon g;
    for (const auto& [x, y] : {std::pair{x0, bot(x0)}, {x1, bot(x1)}, {x1, top(x1)}, {x0, top(x0)}})
      if (g.empty() || (g.back() != Point::cartesian(x, y) && g.front() != Point::cartesian(x, y)))
        g.push_back(Point::cartesian(x, y));
    if (g.size() >= 3)
      f.add(g, dr::Style().color(pal::grey).width(0.6).fill(fill[k++ % 5]).fill_opacity(0.25));
  }
  for (Index s = 0; s < M.segments(); ++s) {
    const auto [a, b] = M.segment(s);
    f.segment(Q[a], Q[b], dr::Style().color(pal::dark_grey).width(1.6));
  }
  for (const Point& p : P) f.add(p, dr::Style().size(2.5));
  return f;
}

}  // namespace

void figures(const std::filesystem::path& dir) {
  dr::FigurePairs out(dir);
  dr::PlaneView pv;
  pv.half_width = 3;
  dr::SphereView sv;
  sv.lat = 30;
  sv.lon = 20;
  {  // The map: five faces, two of them across Ω, and the complement (white).
    dr::Figure f;
    map(f, fan_map(), 0.3);
    out.save(f, "map", pv, sv);
  }
  // Figure 5.32 redrawn: a walk from the front to a back point of F4, through Ω.
  out.save(walk_picture(Point(1, 0, 0), Point(-2, 4, 1)), "walk", pv, sv);
  // A degenerate walk: along the edge O a, through the vertex a, into F2.
  out.save(walk_picture(Point(1, 0, 0), Point(2, 5, 0)), "walk-vertex", pv, sv);
  {  // A non-convex face entered once per tooth: the comb, and the walk across it.
    dr::Figure f;
    f.add(comb(6), dr::Style().color(pal::dark_grey).width(1.2).fill(pal::blue).fill_opacity(0.3));
    f.add(comb_start(), dr::Style().color(pal::dark_grey).width(1.2).fill(pal::green).fill_opacity(0.3));
    const Point q(8, -1, 1.5), p(8, 13, 1.5);
    f.segment(q, p, dr::Style().color(pal::red).width(2).arrow());
    f.add(q, dr::Style().color(pal::red).size(4).label("q").label_angle(-60));
    f.add(p, dr::Style().color(pal::red).size(4).label("p").label_angle(-60));
    dr::PlaneView wide;
    wide.cx = 5.0 / 8;
    wide.cy = 1.5 / 8;
    wide.half_width = 9.0 / 8;
    dr::SphereView near;
    near.lat = 75;
    near.lon = -90;
    out.save(f, "comb", wide, near);
  }
  {  // The trapezoidal map of a small Delaunay map's edges (sections 8-11).
    dr::PlaneView tight;
    tight.half_width = 2.6;
    dr::SphereView above;
    above.lat = 65;
    above.lon = 20;
    out.save(trapezoid_picture(), "trapezoids", tight, above);
  }
  std::cerr << out.summary() << "\n";
}

}  // namespace chapter14
