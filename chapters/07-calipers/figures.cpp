// The shapes of chapter 07 and its figures, in the planar and the spherical model.
#include "figures.hpp"

#include <t2/gen/generate.hpp>
#include <t2/hull.hpp>

#include <iostream>
#include <string>

namespace chapter07 {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Point;

std::vector<Point> pocket_polygon() {
  const double xy[][2] = {{0, 0},  {2, 0.5}, {4, 0},   {5, 2}, {3.5, 2.2}, {3, 3.5}, {5, 4},
                          {4, 5.5}, {1, 5},  {1.5, 3}, {0.5, 2.5}, {-1, 3},  {-0.5, 1}};
  std::vector<Point> P;
  for (const auto& p : xy) P.push_back(Point::cartesian(p[0] - 2, p[1] - 2.5));
  return P;
}

std::vector<Point> hexagon() {
  return {Point::cartesian(-2, -2), Point::cartesian(1, -2), Point::cartesian(3, 0),
          Point::cartesian(2, 2),   Point::cartesian(-1, 2), Point::cartesian(-3, 0)};
}

std::vector<Point> front_and_back() {
  return {Point::cartesian(0, 0), Point::cartesian(6, 2), Point(-1, 2, -3), Point(-1, -5, 1)};
}

std::vector<Point> hourglass() {
  return {Point::cartesian(0, 0), Point::cartesian(4, 0), Point::cartesian(3, 2),
          Point::cartesian(4, 4), Point::cartesian(0, 4), Point::cartesian(1, 2)};
}

std::vector<Point> u_shape() {
  return {Point::cartesian(0, 0), Point::cartesian(5, 0), Point::cartesian(5, 3), Point::cartesian(4, 3),
          Point::cartesian(4, 1), Point::cartesian(1, 1), Point::cartesian(1, 3), Point::cartesian(0, 3)};
}

std::vector<Point> pinwheel() {
  return {Point::cartesian(2, 0),  Point::cartesian(1, 0),  Point::cartesian(0, 2),  Point::cartesian(0, 1),
          Point::cartesian(-2, 0), Point::cartesian(-1, 0), Point::cartesian(0, -2), Point::cartesian(0, -1)};
}

std::vector<Point> corridor() { return {Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 1), Point(0, 0, 1)}; }

std::vector<Point> notched_half_plane() {
  return {Point::cartesian(-2, 0), Point::cartesian(-1, 0), Point::cartesian(0, 1), Point::cartesian(1, 0),
          Point::cartesian(2, 0),  Point(0, 1, 0),          Point(0, 0, 1),         Point(0, -1, 0)};
}

namespace {

std::vector<Point> at(const std::vector<Point>& P, const std::vector<std::size_t>& idx) {
  std::vector<Point> out;
  for (std::size_t i : idx) out.push_back(P[i]);
  return out;
}

std::vector<Point> corners(const t2::PolygonKernel& K) {
  std::vector<Point> out;
  for (const auto& v : K.vertices) out.push_back(t2::normalized(t2::to_double(v)));
  return out;
}

}  // namespace

void figures(const std::filesystem::path& dir) {
  dr::FigurePairs out(dir);
  const dr::Style green = dr::Style().fill(pal::green).fill_opacity(0.2).color(pal::green).width(1.6);
  const dr::Style red = dr::Style().color(pal::red).width(2.2);
  dr::PlaneView plane;
  plane.half_width = 4;
  dr::SphereView sphere;
  sphere.lat = 25;
  sphere.lon = -20;
  {  // Melkman: the polygon and its hull, the pockets between them.
    const auto P = pocket_polygon();
    dr::Figure f;
    f.add(at(P, t2::melkman(P)), green);
    f.add(P, dr::Style().width(1.4));
    for (std::size_t i = 0; i < P.size(); ++i) f.add(P[i], dr::Style().label("v" + std::to_string(i)));
    out.save(f, "melkman", plane, dr::facing(P, sphere));
  }
  {  // The calipers on the hexagon: every antipodal pair, the diameter, the narrowest strip.
    const auto H = hexagon();
    const std::vector<std::size_t> all{0, 1, 2, 3, 4, 5};
    dr::Figure f;
    f.add(H, green);
    for (const auto& [a, b] : t2::antipodal_pairs(H, all))
      f.segment(H[a], H[b], dr::Style().color(pal::blue).dash({4, 3}).width(1));
    const auto d = t2::diameter(H);
    f.segment(H[d->first], H[d->second], red);
    const auto w = t2::width(H);
    const auto edge = t2::join(H[w->from], H[w->to]);
    f.add(edge, dr::Style().color(pal::orange).width(1.2));
    f.add(t2::join(H[w->vertex], t2::meet(edge, t2::omega<double>())), dr::Style().color(pal::orange).width(1.2));
    for (std::size_t i = 0; i < H.size(); ++i) f.add(H[i], dr::Style().label("p" + std::to_string(i)));
    out.save(f, "calipers", plane, dr::facing(H, sphere));
  }
  {  // The diameter across Ω: the front-back pair nearest as drawn.
    const std::vector<Point> M = front_and_back();
    const auto d = t2::diameter(M);
    dr::Figure f;
    f.segment(M[d->first], M[d->second], red);
    for (std::size_t i = 0; i < M.size(); ++i) f.add(M[i], dr::Style().label("p" + std::to_string(i)));
    dr::PlaneView wide;
    wide.half_width = 8;
    out.save(f, "diameter-t2", wide, sphere);
  }
  {  // Convex layers of 200 points in a disk.
    t2::gen::Options o;
    o.n = 200;
    o.seed = 7;
    const auto P = t2::gen::points(t2::gen::Kind::disk, o);
    static const char* colours[] = {pal::blue, pal::orange, pal::green, pal::red, pal::purple, pal::brown};
    dr::Figure f;
    const auto L = t2::convex_layers(P);
    for (std::size_t j = 0; j < L.size(); ++j) {
      const auto h = at(P, L[j]);
      const dr::Style s = dr::Style().color(colours[j % 6]).width(1.4);
      if (h.size() >= 3) f.add(h, s);
      if (h.size() == 2) f.segment(h[0], h[1], s);
    }
    for (const auto& p : P) f.add(p, dr::Style().size(1.5));
    dr::PlaneView unit;
    unit.half_width = 1.15;
    out.save(f, "layers", unit, dr::facing(P));  // from above the disk: every layer in full
  }
  {  // Kernels: a star polygon (bounded) and the notched half-plane (unbounded, corners on Ω).
    t2::gen::Options o;
    o.n = 24;
    o.seed = 5;
    const t2::Polygon S = t2::gen::polygon(t2::gen::Kind::star_polygon, o);
    dr::Figure f;
    f.add(corners(t2::polygon_kernel(S)), green);
    f.add(S, dr::Style().width(1.4));
    f.add(Point(1, 0, 0), dr::Style().label("origin").color(pal::red));
    dr::PlaneView unit;
    unit.half_width = 1.2;
    out.save(f, "kernel-star", unit, sphere);
    const auto N = notched_half_plane();
    dr::Figure g;
    g.add(corners(t2::polygon_kernel(N)), green);
    g.add(N, dr::Style().width(1.4));
    for (std::size_t i = 0; i < N.size(); ++i) g.add(N[i], dr::Style().label("v" + std::to_string(i)));
    out.save(g, "kernel-unbounded", plane, sphere);
  }
  std::cerr << out.summary() << "\n";
}

}  // namespace chapter07
