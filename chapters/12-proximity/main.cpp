// Chapter 12: proximity. The minimum spanning tree, all nearest neighbours, the closest pair
// and the smallest enclosing circle of sites of T², with T²'s distances (finite, +∞, beyond
// infinity), checked against each other; the figures in both models (figures.cpp).
#include <t2/draw.hpp>
#include <t2/gen/generate.hpp>
#include <t2/proximity/closest_pair.hpp>
#include <t2/proximity/enclosing_circle.hpp>
#include <t2/proximity/nearest_neighbors.hpp>
#include <t2/proximity/spanning_tree.hpp>
#include <t2/t2.hpp>

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "figures.hpp"

namespace {

using t2::Point;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 12: check failed: ") + what);
}

// "finite", "infinite" or "beyond": the class of the distance of a pair (pair_distance.hpp).
const char* kind(const Point& a, const Point& b) {
  if (a.w() == 0 || b.w() == 0) return "infinite";
  return (a.w() > 0) == (b.w() > 0) ? "finite" : "beyond infinity";
}

void spanning_tree() {
  std::cout << "== the minimum spanning tree\n";
  //> emst-demo
  const std::vector<Point> P = chapter12::small_sites();
  for (const auto& [i, j] : t2::minimum_spanning_tree(P))
    std::cout << "p" << i << " p" << j << "  " << kind(P[i], P[j]) << "\n";
  //< emst-demo
  std::cout << "\n";
}

void nearest() {
  std::cout << "== all nearest neighbours\n";
  //> ann-demo
  const std::vector<Point> P = chapter12::small_sites();
  const auto nearest = t2::all_nearest_neighbors(P);
  for (std::size_t i = 0; i < P.size(); ++i)
    std::cout << "p" << i << " -> p" << nearest[i] << "  " << kind(P[i], P[nearest[i]])
              << "\n";
  const std::vector<Point> Q(P.begin(), P.end() - 1);  // without p7
  try {
    t2::all_nearest_neighbors(Q);
  } catch (const t2::UndefinedNearest& e) {
    std::cout << "without p7: p" << e.site << " has no nearest\n";
  }
  //< ann-demo
  std::cout << "\n";
}

void closest() {
  std::cout << "== the closest pair\n";
  //> closest-demo
  const std::vector<Point> P = chapter12::small_sites();
  const auto [i, j] = t2::closest_pair(P);
  std::cout << "p" << i << " p" << j << "  " << kind(P[i], P[j]) << "\n";
  const std::vector<Point> Q = {P[2], P[5]};  // one front site, one back site
  std::cout << "of p2 and p5 alone: " << kind(Q[0], Q[1]) << "\n";
  //< closest-demo
  int agree = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    t2::gen::Options o;
    o.n = 300;
    o.seed = seed;
    const auto R = t2::gen::points(seed % 2 ? t2::gen::Kind::both_sides : t2::gen::Kind::uniform, o);
    agree += t2::closest_pair(R) == t2::closest_pair_brute(R);
    require(t2::minimum_spanning_tree(R).size() == R.size() - 1, "a tree has n - 1 edges");
  }
  std::cout << "30 random sets of 300 sites: the Delaunay closest pair is the brute force's on " << agree << "\n";
  require(agree == 30, "closest pairs");
}

// "centre [w, x, y]  r^2 = ...  on it: p0 p1 p2"
void print_circle(const char* what, const t2::EnclosingCircle& c) {
  std::cout << what << ": centre [" << c.center.w() << ", " << c.center.x() << ", "
            << c.center.y() << "]  r^2 = " << c.radius2 << "  on it:";
  for (auto i : c.on_circle) std::cout << " p" << i;
  std::cout << "\n";
}

void enclosing() {
  std::cout << "\n== the smallest enclosing circle\n";
  //> sec-demo
  std::vector<Point> F = {Point::cartesian(0, 0), Point::cartesian(4, 0),
                          Point::cartesian(1, 3), Point::cartesian(2, 1)};
  print_circle("front", t2::smallest_enclosing_circle(F));
  F.push_back(Point::cartesian(5, 2));  // outside: the circle with diameter p0 p4
  print_circle("and p4", t2::smallest_enclosing_circle(F));
  std::vector<Point> B;
  for (const Point& p : F) B.push_back(t2::antipode(p));
  print_circle("back", t2::smallest_enclosing_circle(B));
  for (const Point& q : {Point(-1, 0, 0), Point(0, 1, 0)}) {
    F.push_back(q);
    try {
      t2::smallest_enclosing_circle(F);
    } catch (const t2::UndefinedEnclosing& e) {
      std::cout << "with p" << F.size() - 1 << " = " << t2::to_string(q) << ": undefined\n";
    }
    F.pop_back();
  }
  //< sec-demo
  int inside = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    t2::gen::Options o;
    o.n = 1000;
    o.seed = seed;
    const auto R = t2::gen::points(t2::gen::Kind::normal, o);
    const auto c = t2::smallest_enclosing_circle(R);
    bool all = true;
    for (const Point& p : R) {  // every site in the closed disk, exactly
      const t2::Rational dx = t2::to_rational(p.x()) / t2::to_rational(p.w()) -
                              t2::Rational(c.center.x(), c.center.w());
      const t2::Rational dy = t2::to_rational(p.y()) / t2::to_rational(p.w()) -
                              t2::Rational(c.center.y(), c.center.w());
      all = all && dx * dx + dy * dy <= c.radius2;
    }
    inside += all && c.on_circle.size() >= 2;
  }
  std::cout << "30 random sets of 1000 sites: every site in the closed disk, two or more on "
               "its circle, in "
            << inside << "\n";
  require(inside == 30, "enclosing circles");
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = t2::draw::figures_dir(argc, argv, T2_FIGURES_DIR);
  spanning_tree();
  nearest();
  closest();
  enclosing();
  chapter12::figures(dir);
}
