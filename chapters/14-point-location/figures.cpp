// The map of chapter 14 and its figures, in the planar and the spherical model.
#include "figures.hpp"

#include <t2/draw.hpp>
#include <t2/location/walk.hpp>

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
  std::cerr << out.summary() << "\n";
}

}  // namespace chapter14
