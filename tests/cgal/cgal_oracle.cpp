// The CGAL oracles of cgal_oracle.hpp: the only test source that includes CGAL.
#include "cgal_oracle.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Min_circle_2.h>
#include <CGAL/Min_circle_2_traits_2.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_sweep_2_algorithms.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "oracle.hpp"

namespace t2::testing::cgal {

namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

// The front point [w, x, y] as CGAL's exact point (x/w, y/w).
Epeck::Point_2 exact(const Point& p) {
  return {Epeck::FT(q(p.x())) / Epeck::FT(q(p.w())), Epeck::FT(q(p.y())) / Epeck::FT(q(p.w()))};
}

// CGAL's hull of `in`, each vertex as the index of the first point of `in` it equals.
std::vector<std::size_t> hull_indices(const std::vector<Epeck::Point_2>& in) {
  std::vector<Epeck::Point_2> out;
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out));
  std::vector<std::size_t> h;
  for (const auto& c : out) h.push_back(static_cast<std::size_t>(std::find(in.begin(), in.end(), c) - in.begin()));
  return h;
}

}  // namespace

std::vector<std::size_t> hull_2(const std::vector<Point>& P) {
  std::vector<Epeck::Point_2> in;
  for (const auto& p : P) in.push_back(exact(p));
  return hull_indices(in);
}

std::vector<std::vector<std::size_t>> layers_2(const std::vector<Point>& P) {
  std::vector<Epeck::Point_2> left;
  std::vector<std::size_t> of(P.size());
  std::iota(of.begin(), of.end(), std::size_t{0});
  for (const auto& p : P) left.push_back(exact(p));
  std::vector<std::vector<std::size_t>> layers;
  while (!left.empty()) {
    const auto h = hull_indices(left);
    std::vector<Epeck::Point_2> hull;
    std::vector<std::size_t> layer;
    for (std::size_t i : h) hull.push_back(left[i]), layer.push_back(of[i]);
    std::vector<Epeck::Point_2> rest;
    std::vector<std::size_t> rest_of;
    for (std::size_t i = 0; i < left.size(); ++i)
      if (std::find(hull.begin(), hull.end(), left[i]) == hull.end()) rest.push_back(left[i]), rest_of.push_back(of[i]);
    layers.push_back(std::move(layer));
    left = std::move(rest);
    of = std::move(rest_of);
  }
  return layers;
}

std::vector<std::array<Triangulation::Index, 3>> delaunay_triangles(
    const std::vector<Point>& pts, const std::vector<std::pair<Triangulation::Index, Triangulation::Index>>& duplicates) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Triangulation::Index, Epick>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  std::vector<std::pair<Epick::Point_2, Triangulation::Index>> in;
  for (Triangulation::Index k = 0; k < pts.size(); ++k) in.emplace_back(Epick::Point_2(pts[k].x(), pts[k].y()), k);
  CGAL::Delaunay_triangulation_2<Epick, Tds> dt(in.begin(), in.end());
  std::vector<Triangulation::Index> canonical(pts.size());
  std::iota(canonical.begin(), canonical.end(), Triangulation::Index{0});
  for (auto [dropped, kept] : duplicates) canonical[dropped] = kept;
  std::vector<std::array<Triangulation::Index, 3>> out;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    std::array<Triangulation::Index, 3> t{canonical[f->vertex(0)->info()], canonical[f->vertex(1)->info()],
                                         canonical[f->vertex(2)->info()]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<DelaunayLocation> delaunay_locate(const std::vector<Point>& pts, const std::vector<Point>& queries) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Triangulation::Index, Epick>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Dt = CGAL::Delaunay_triangulation_2<Epick, Tds>;
  std::vector<std::pair<Epick::Point_2, Triangulation::Index>> in;
  for (Triangulation::Index k = 0; k < pts.size(); ++k) in.emplace_back(Epick::Point_2(pts[k].x(), pts[k].y()), k);
  Dt dt(in.begin(), in.end());
  std::vector<DelaunayLocation> out;
  for (const Point& q : queries) {
    Dt::Locate_type lt;
    int li = 0;
    const auto f = dt.locate(Epick::Point_2(q.x() / q.w(), q.y() / q.w()), lt, li);
    DelaunayLocation l;
    if (lt == Dt::FACE) {
      l.kind = 0;
      for (int i = 0; i < 3; ++i) l.vertices.push_back(f->vertex(i)->info());
    } else if (lt == Dt::EDGE) {
      l.kind = 1;
      l.vertices = {f->vertex(Dt::ccw(li))->info(), f->vertex(Dt::cw(li))->info()};
    } else if (lt == Dt::VERTEX) {
      l.kind = 2;
      l.vertices = {f->vertex(li)->info()};
    }
    std::sort(l.vertices.begin(), l.vertices.end());
    out.push_back(l);
  }
  return out;
}

std::vector<Triangle3> hull_3(const std::vector<Point3>& P) {
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  std::vector<Epick::Point_3> in;
  std::map<std::array<double, 3>, std::uint32_t> index;
  for (std::uint32_t i = 0; i < P.size(); ++i) {
    in.emplace_back(P[i].x, P[i].y, P[i].z);
    index.emplace(std::array<double, 3>{P[i].x, P[i].y, P[i].z}, i);
  }
  Mesh m;
  CGAL::convex_hull_3(in.begin(), in.end(), m);
  std::vector<Triangle3> out;
  for (auto f : m.faces()) {
    std::vector<std::uint32_t> v;
    for (auto u : CGAL::vertices_around_face(m.halfedge(f), m)) {
      const auto& p = m.point(u);
      v.push_back(index.at({p.x(), p.y(), p.z()}));
    }
    if (v.size() != 3) throw std::runtime_error("CGAL's hull has a face that is not a triangle");
    Triangle3 t{v[0], v[1], v[2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

// CGAL's exact number as a canonical rational.
Rational rational(const Epeck::FT& v) {
  std::ostringstream os;
  os << CGAL::exact(v);  // "n" or "n/d", whichever exact number type CGAL was built with
  Rational r(os.str());
  r.canonicalize();
  return r;
}

}  // namespace

std::vector<std::array<Rational, 2>> intersection_points_2(const std::vector<Segment>& segments) {
  std::vector<Epeck::Segment_2> in;
  in.reserve(segments.size());
  for (const Segment& s : segments) in.emplace_back(exact(s.source()), exact(s.target()));
  std::vector<Epeck::Point_2> out;
  CGAL::compute_intersection_points(in.begin(), in.end(), std::back_inserter(out), false);
  std::vector<std::array<Rational, 2>> pts;
  for (const auto& p : out) pts.push_back({rational(p.x()), rational(p.y())});
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  return pts;
}

MinCircle min_circle_2(const std::vector<Point>& P) {
  std::vector<Epeck::Point_2> in;
  for (const auto& p : P) in.push_back(exact(p));
  CGAL::Min_circle_2<CGAL::Min_circle_2_traits_2<Epeck>> mc(in.begin(), in.end(), true);
  const auto& c = mc.circle();
  return {{rational(c.center().x()), rational(c.center().y())}, rational(c.squared_radius())};
}

}  // namespace t2::testing::cgal
