// The sites of chapter 12 and its figures, in the planar and the spherical model.
#include "figures.hpp"

#include <t2/draw.hpp>
#include <t2/gen/generate.hpp>
#include <t2/proximity/enclosing_circle.hpp>
#include <t2/proximity/enclosing_circle_voronoi.hpp>
#include <t2/proximity/nearest_neighbors.hpp>
#include <t2/proximity/spanning_tree.hpp>
#include <t2/triangulation/delaunay.hpp>
#include <t2/voronoi/complex.hpp>

#include <algorithm>
#include <iostream>
#include <string>

namespace chapter12 {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Point;

std::vector<Point> small_sites() {
  return {Point::cartesian(0, 0),  Point::cartesian(2, 1), Point::cartesian(-1, 2), Point::cartesian(3, -2),
          Point(-1, -3, 1), Point(-1, 2, 3), Point(0, 1, -1), Point(0, 1, 0)};
}

namespace {

void sites(dr::Figure& f, const std::vector<Point>& P, bool labels) {
  for (std::size_t i = 0; i < P.size(); ++i) {
    dr::Style s = dr::Style().size(labels ? 3.5 : 2);
    if (labels) s.label("p" + std::to_string(i));
    f.add(P[i], s);
  }
}

}  // namespace

void figures(const std::filesystem::path& dir) {
  dr::FigurePairs out(dir);
  const dr::Style tree = dr::Style().color(pal::red).width(2.2);
  {  // The tree of front sites inside their Delaunay triangulation.
    t2::gen::Options o;
    o.n = 60;
    o.seed = 12;
    const auto P = t2::gen::points(t2::gen::Kind::disk, o);
    dr::Figure f;
    for (const auto& t : t2::delaunay(P).finite_triangles())
      for (int k = 0; k < 3; ++k) f.segment(P[t[k]], P[t[(k + 1) % 3]], dr::Style().color(pal::grey).width(0.8));
    for (const auto& [i, j] : t2::minimum_spanning_tree(P)) f.segment(P[i], P[j], tree);
    sites(f, P, false);
    dr::PlaneView pv;
    pv.half_width = 1.1;
    dr::SphereView sv;
    sv.lat = 70;
    sv.lon = -90;
    out.save(f, "emst-delaunay", pv, sv);
  }
  dr::PlaneView wide;
  wide.half_width = 4.5;
  dr::SphereView aside;
  aside.lat = 20;
  aside.lon = -60;
  const auto P = small_sites();
  {  // The tree of the eight sites: finite edges, one at +∞, one beyond infinity.
    dr::Figure f;
    for (const auto& [i, j] : t2::minimum_spanning_tree(P)) f.segment(P[i], P[j], tree);
    sites(f, P, true);
    out.save(f, "emst-t2", wide, aside);
  }
  {  // Each site's nearest, an arrow from it.
    dr::Figure f;
    const auto nearest = t2::all_nearest_neighbors(P);
    for (std::size_t i = 0; i < P.size(); ++i)
      f.segment(P[i], P[nearest[i]], dr::Style().color(pal::blue).width(1.6).arrow());
    sites(f, P, true);
    out.save(f, "ann-t2", wide, aside);
  }
  {  // The smallest enclosing circle of front sites, and that of back sites: each on its side.
    t2::gen::Options o;
    o.n = 50;
    o.seed = 25;
    const auto D = t2::gen::points(t2::gen::Kind::disk, o);
    std::vector<Point> F, B;
    for (std::size_t i = 0; i < D.size(); ++i) {
      const double x = D[i].x() / D[i].w(), y = D[i].y() / D[i].w();
      if (i % 3 != 0)
        F.push_back(Point::cartesian(1.1 * x + 1.3, 0.8 * y + 0.3));
      else  // drawn at (0.9 x - 1.6, 0.9 y - 0.4), on the back
        B.push_back(Point(-1, -(0.9 * x - 1.6), -(0.9 * y - 0.4)));
    }
    dr::Figure f;
    for (const auto* S : {&F, &B}) {
      const t2::EnclosingCircle c = t2::smallest_enclosing_circle(*S);
      const dr::Style st = dr::Style().color(S == &F ? pal::red : pal::blue).width(2);
      f.add(t2::ExactCircle(c.center, t2::to_exact((*S)[c.support[0]])), st);
      f.add(t2::to_double(c.center), dr::Style().color(S == &F ? pal::red : pal::blue).size(3));
      for (std::size_t i = 0; i < S->size(); ++i) {
        const bool on = std::binary_search(c.on_circle.begin(), c.on_circle.end(), i);
        f.add((*S)[i], dr::Style().size(on ? 3.5 : 2));
      }
    }
    dr::PlaneView pv;
    pv.half_width = 3.2;
    dr::SphereView side_on;  // both sets lie towards +x, one above Ω and one below
    side_on.lat = 5;
    side_on.lon = 10;
    out.save(f, "sec-t2", pv, side_on);
  }
  {  // Seed 003's figure 4.31: the diameter a b is no farthest-point Delaunay edge.
    const std::vector<Point> Q{Point::cartesian(-1, 0), Point::cartesian(0.6, -0.9), Point::cartesian(1, 0),
                               Point::cartesian(0.6, 0.9)};  // a d b c, a tenth of sec-diameter.t2
    dr::Figure f;
    f.add(t2::ExactCircle(t2::ExactPoint(1, 0, 0), t2::to_exact(Q[0])),
          dr::Style().color(pal::grey).width(1.2).dash({4, 3}));  // the circle on the diameter
    f.segment(Q[0], Q[2], dr::Style().color(pal::grey).width(1.2).dash({4, 3}));
    for (const auto& t : t2::farthest_delaunay(Q))
      for (int k = 0; k < 3; ++k) f.segment(Q[t[k]], Q[t[(k + 1) % 3]], dr::Style().color(pal::blue).width(1.6));
    const t2::EnclosingCircle c = t2::smallest_enclosing_circle_shamos(Q);
    f.add(t2::ExactCircle(c.center, t2::to_exact(Q[c.support[0]])), dr::Style().color(pal::red).width(2));
    f.add(t2::to_double(c.center), dr::Style().color(pal::red).size(3));
    const char* names[] = {"a", "d", "b", "c"};
    for (std::size_t i = 0; i < Q.size(); ++i) f.add(Q[i], dr::Style().size(3.5).label(names[i]));
    out.save(f, "sec-diameter", dr::PlaneView{.half_width = 1.5}, dr::SphereView{.lat = 60, .lon = -90});
  }
  std::cerr << out.summary() << "\n";
}

}  // namespace chapter12
