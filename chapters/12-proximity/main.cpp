// Chapter 12: proximity. The minimum spanning tree, all nearest neighbours and the closest pair
// of sites of T², with T²'s distances (finite, +∞, beyond infinity), checked against each other;
// the figures in both models (figures.cpp).
#include <t2/draw.hpp>
#include <t2/gen/generate.hpp>
#include <t2/proximity/closest_pair.hpp>
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

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = t2::draw::figures_dir(argc, argv, T2_FIGURES_DIR);
  spanning_tree();
  nearest();
  closest();
  chapter12::figures(dir);
}
