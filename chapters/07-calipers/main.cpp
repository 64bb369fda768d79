// Chapter 07: calipers. The hull of a simple polygon in linear time (Melkman), antipodal pairs and
// the rotating calipers, the diameter (a maximum) and the width, convex layers both ways of seed
// 003, and the kernel of a polygon, unbounded ones included; figures in figures.cpp.
#include <t2/gen/generate.hpp>
#include <t2/hull.hpp>
#include <t2/t2.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "figures.hpp"

namespace {

using t2::Point;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 07: check failed: ") + what);
}

std::string indices(const std::vector<std::size_t>& h) {
  std::string s;
  for (std::size_t i : h) s += " p" + std::to_string(i);
  return s;
}

// d²(a, b) as the T¹ point [±1, d²] (or [0, 1] = +∞), from the exact value.
std::string squared(const Point& a, const Point& b) {
  const t2::ExactT1 d = t2::squared_distance(t2::to_exact(a), t2::to_exact(b));
  if (d.w() == 0) return "[0, 1]";
  const t2::Rational x = t2::Rational(d.x()) / t2::Rational(abs(d.w()));
  return std::string(d.w() > 0 ? "[1, " : "[-1, ") + t2::to_string(x.get_d()) + "]";
}

bool same_set(std::vector<std::size_t> a, std::vector<std::size_t> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

void polygon_hull() {
  std::cout << "== the hull of a simple polygon (Melkman)\n";
  //> melkman-demo
  const std::vector<Point> P = chapter07::pocket_polygon();
  const std::vector<std::size_t> h = t2::melkman(P);
  std::cout << "polygon of " << P.size() << " vertices, hull:" << indices(h) << "\n";
  std::cout << "the same as convex_hull: " << std::boolalpha
            << same_set(h, t2::convex_hull(P)) << "\n";
  //< melkman-demo
  require(t2::is_simple(P) && same_set(h, t2::convex_hull(P)), "Melkman = convex_hull");
  int agree = 0;
  for (std::uint64_t s = 1; s <= 100; ++s) {
    t2::gen::Options o;
    o.n = 500;
    o.seed = s;
    const t2::Polygon Q = t2::gen::polygon(t2::gen::Kind::simple_polygon, o);
    agree += same_set(t2::melkman(Q), t2::convex_hull(Q));
  }
  std::cout << "100 random simple polygons of 500 vertices: " << agree << " agree with convex_hull\n\n";
  require(agree == 100, "random polygons");
}

void calipers() {
  std::cout << "== antipodal pairs, diameter, width\n";
  //> calipers-demo
  const std::vector<Point> H = chapter07::hexagon();  // three pairs of parallel edges
  const std::vector<std::size_t> all{0, 1, 2, 3, 4, 5};
  std::cout << "antipodal pairs:";
  for (const auto& [a, b] : t2::antipodal_pairs(H, all))
    std::cout << " p" << a << "-p" << b;
  const auto d = t2::diameter(H);
  std::cout << "\ndiameter: p" << d->first << " p" << d->second << ", squared "
            << squared(H[d->first], H[d->second]) << "\n";
  const auto w = t2::width(H);
  std::cout << "width: edge p" << w->from << " p" << w->to << " and vertex p" << w->vertex
            << "\n";
  //< calipers-demo
  std::cout << "\n";
}

void diameter_in_t2() {
  std::cout << "== the diameter in T2\n";
  //> diameter-t2
  // front (0,0), (6,2); back at (-2,3), (5,-1)
  const std::vector<Point> mixed = chapter07::front_and_back();
  const auto d = t2::diameter(mixed);
  std::cout << "farthest p" << d->first << " p" << d->second
            << ", squared " << squared(mixed[d->first], mixed[d->second]) << "\n";
  const std::vector<Point> omega{Point::cartesian(0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  try {
    t2::diameter(omega);
  } catch (const t2::Undefined& e) {
    std::cout << "two points of Omega: " << e.what() << "\n";
  }
  //< diameter-t2
  require(d->first == 1 && d->second == 3, "front-back diameter");
  std::cout << "\n";
}

void layers() {
  std::cout << "== convex layers\n";
  t2::gen::Options o;
  o.n = 200;
  o.seed = 7;
  //> layers-demo
  const std::vector<Point> P = t2::gen::points(t2::gen::Kind::disk, o);
  const auto jarvis = t2::convex_layers(P, t2::LayersMethod::jarvis);
  const auto graham = t2::convex_layers(P, t2::LayersMethod::graham);
  std::cout << P.size() << " points in a disk: " << jarvis.size() << " layers, outermost "
            << jarvis.front().size() << " vertices, innermost " << jarvis.back().size()
            << "\n";
  std::cout << "both ways agree: " << std::boolalpha << (jarvis.size() == graham.size())
            << "\n";
  //< layers-demo
  for (std::size_t j = 0; j < jarvis.size(); ++j) require(same_set(jarvis[j], graham[j]), "layers agree");
  std::cout << "\n";
}

void kernels() {
  std::cout << "== the kernel of a polygon\n";
  //> kernel-demo
  const auto show = [](const char* name, const std::vector<Point>& P) {
    const t2::PolygonKernel K = t2::polygon_kernel(P);
    std::cout << name << ": " << K.vertices.size() << " corners"
              << (K.empty() ? " (empty)" : "")
              << (!K.empty() && !K.bounded() ? " (unbounded)" : "") << ":";
    for (const auto& v : K.vertices)
      std::cout << " " << t2::to_string(t2::normalized(t2::to_double(v)));
    std::cout << "\n";
  };
  show("hourglass", chapter07::hourglass());
  show("U", chapter07::u_shape());
  show("pinwheel", chapter07::pinwheel());
  show("quadrant [1,0,0] [0,1,0] [0,0,1]",
       {Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)});
  show("corridor [1,0,0] [0,1,0] [1,1,1] [0,0,1]", chapter07::corridor());
  //< kernel-demo
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = t2::draw::figures_dir(argc, argv, T2_FIGURES_DIR);
  polygon_hull();
  calipers();
  diameter_in_t2();
  layers();
  kernels();
  chapter07::figures(dir);
}
