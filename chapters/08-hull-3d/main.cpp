// Chapter 08: hulls in R³. The Platonic solids with exact coordinates and Euler's formula, the
// winged-edge structure of the seed's cube, gift wrapping against the incremental hull, the
// rule for degenerate input, and the lifting map that turns a lower hull into a Delaunay
// triangulation; the figures of the chapter.
#include "figures.hpp"

#include <t2/draw/polyhedron.hpp>
#include <t2/gen/generate.hpp>
#include <t2/hull3d.hpp>
#include <t2/t2.hpp>
#include <t2/triangulation/delaunay.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace dr = t2::draw;
namespace pal = t2::draw::palette;
using t2::Hull3dAlgorithm;
using t2::Point3;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 08: check failed: ") + what);
}

void platonic_solids(const std::filesystem::path& dir) {
  std::cout << "== the Platonic solids\n";
  //> platonic-table
  for (t2::Platonic s : t2::all_platonic()) {
    const t2::Polyhedron P = t2::platonic(s);
    const std::size_t V = P.vertices.size(), E = t2::edges(P).size(), F = P.faces.size();
    std::cout << t2::name(s) << ": V=" << V << " E=" << E << " F=" << F
              << "  V-E+F=" << t2::euler_characteristic(P)
              << "  convex: " << (t2::validate_convex(P).empty() ? "yes" : "no") << "\n";
  }
  //< platonic-table
  for (t2::Platonic s : t2::all_platonic()) {
    dr::View3 v;
    v.size = 240;
    dr::save_polyhedron(t2::platonic(s), v, dir / (std::string(t2::name(s)) + ".svg"));
  }
  const t2::Polyhedron D = t2::platonic(t2::Platonic::dodecahedron);
  std::cout << "a dodecahedron vertex: " << D.vertices[0].x << " " << D.vertices[0].y << " " << D.vertices[0].z << "\n";
}

void winged_edge() {
  std::cout << "== the winged-edge structure of the cube\n";
  //> winged-cube
  const t2::WingedEdge W = t2::WingedEdge::from(t2::platonic(t2::Platonic::cube));
  std::cout << "edges: " << W.edges.size()
            << ", pointers checked: " << (W.validate().empty() ? "ok" : "BROKEN") << "\n";
  for (std::uint32_t v : {0u, 7u}) {
    std::cout << "faces around vertex " << v << ":";
    for (std::uint32_t f : W.vertex_faces(v)) std::cout << " f" << f;
    std::cout << "\n";
  }
  //< winged-cube
}

std::vector<Point3> generated(t2::gen::Kind k, std::size_t n, std::uint64_t seed) {
  t2::gen::Options o;
  o.n = n;
  o.seed = seed;
  std::vector<Point3> P;
  for (const auto& [x, y, z] : t2::gen::points3(k, o)) P.push_back({x, y, z});
  return P;
}

void three_algorithms(const std::filesystem::path& dir) {
  std::cout << "== three algorithms, one answer\n";
  //> three-algorithms
  const std::vector<Point3> P = generated(t2::gen::Kind::cube, 2000, 8);
  const t2::Facets ref = t2::hull_facets_3d(P, Hull3dAlgorithm::gift_wrap);
  for (Hull3dAlgorithm a : {Hull3dAlgorithm::gift_wrap, Hull3dAlgorithm::incremental,
                            Hull3dAlgorithm::quickhull}) {
    const t2::Facets f = t2::hull_facets_3d(P, a);
    std::cout << t2::name(a) << ": " << f.size() << " facets"
              << (f == ref ? "" : "   DIFFERS") << "\n";
  }
  const t2::Polyhedron H = t2::polyhedron_of(P, ref);
  std::cout << "vertices " << H.vertices.size()
            << ", V-E+F = " << t2::euler_characteristic(H)
            << ", every point inside: " << (t2::contains_all(H, P) ? "true" : "false")
            << "\n";
  //< three-algorithms
  require(t2::hull_facets_3d(P, Hull3dAlgorithm::incremental) == ref, "incremental == gift wrapping");
  const std::vector<Point3> S = generated(t2::gen::Kind::cube, 150, 3);
  dr::View3 v;
  dr::save_polyhedron(t2::hull_polyhedron(S), v, dir / "random-hull.svg", S);
}

void degenerate(const std::filesystem::path& dir) {
  std::cout << "== degenerate input\n";
  //> grid
  std::vector<Point3> G;  // the 4 x 4 x 4 grid: 64 points, 56 of them on the boundary
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
      for (int z = 0; z < 4; ++z) G.push_back({double(x), double(y), double(z)});
  for (const auto& f : t2::hull_facets_3d(G)) {
    for (std::uint32_t i : f) std::cout << " " << i;
    std::cout << " |";
  }
  std::cout << "\n";
  //< grid
  dr::View3 v;
  dr::save_polyhedron(t2::hull_polyhedron(G), v, dir / "grid-hull.svg", G);
  //> undefined
  // z = 1 + x + 2y
  const std::vector<Point3> flat = {{0, 0, 1}, {1, 0, 2}, {0, 1, 3}, {1, 1, 4}, {2, 5, 13}};
  try {
    t2::hull_facets_3d(flat);
    std::cout << "a hull?\n";
  } catch (const t2::Undefined& e) {
    std::cout << e.what() << "\n";
  }
  //< undefined
}

void lifting(const std::filesystem::path& dir) {
  std::cout << "== the lifting map\n";
  //> lifting
  const std::vector<t2::Point> A = {
      t2::Point::cartesian(0, 0),   t2::Point::cartesian(4, 1),
      t2::Point::cartesian(1, 5),   t2::Point::cartesian(-3, 2),
      t2::Point::cartesian(-2, -4), t2::Point::cartesian(3, -3),
      t2::Point::cartesian(6, 4),   t2::Point::cartesian(-5, -1)};
  const std::vector<t2::Triangle3> lower = t2::delaunay_by_lifting(A);
  for (const auto& t : lower) std::cout << t[0] << t[1] << t[2] << " ";
  auto flips = t2::delaunay(A).finite_triangles();  // by flips (chapter 10)
  std::sort(flips.begin(), flips.end());
  std::cout << "\nthe same as t2::delaunay: "
            << (lower.size() == flips.size() &&
                        std::equal(lower.begin(), lower.end(), flips.begin(),
                                   [](auto& a, auto& b) {
                                     return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
                                   })
                    ? "true"
                    : "false")
            << "\n";
  //< lifting
  require(lower.size() == flips.size(), "lifting == delaunay");
  chapter08::lifted_figure(A, dir);  // z scaled by 1/8 for the picture (an affine map: the same hull)
  dr::Figure f;  // the triangulation in the plane
  for (const auto& t : lower)
    f.add(std::vector<t2::Point>{A[t[0]], A[t[1]], A[t[2]]}, dr::Style().color(pal::blue).fill(pal::pale_blue));
  for (std::size_t i = 0; i < A.size(); ++i) {
    dr::Style st = dr::Style().label("p" + std::to_string(i));
    if (i == 1) st.label_angle(-60);
    if (i == 6) st.label_angle(30);
    f.add(A[i], st);
  }
  dr::PlaneView plane;
  plane.half_width = 8;
  dr::save(f, plane, dir / "lifted-delaunay-plane.svg");
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);
  platonic_solids(dir);
  winged_edge();
  three_algorithms(dir);
  degenerate(dir);
  lifting(dir);
  chapter08::gift_wrap_figure(dir);
  chapter08::horizon_figure(dir);
  return 0;
}
