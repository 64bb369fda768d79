// Chapter 15: range search. Counting the points in iso-rectangles of T² by the locus method
// (seed 000, Algorithms 17-18), reporting them with a kd-tree and a range tree, all checked
// against testing every point; the figures in both models (figures.cpp).
#include <t2/draw.hpp>
#include <t2/gen/generate.hpp>
#include <t2/kernel/bbox.hpp>
#include <t2/range/kdtree.hpp>
#include <t2/range/locus.hpp>
#include <t2/range/range_tree.hpp>
#include <t2/t2.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "figures.hpp"

namespace {

using t2::IsoRect;
using t2::Point;
using t2::T1;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 15: check failed: ") + what);
}

std::size_t brute(const std::vector<Point>& P, const IsoRect& r) {
  std::size_t n = 0;
  for (const Point& p : P) n += t2::contains(r, p);
  return n;
}

void grid() {
  std::cout << "== the dominance counts of five points\n";
  //> grid-demo
  const std::vector<Point> P = chapter15::five_points();
  const t2::LocusCounter L(P);
  // Q at the corner (x, y): the points with x' < x and y' < y, a quadrant's count.
  for (double y : {2.5, 1.5, 0.5, -0.5, -1.5}) {
    for (double x : {-1.5, -0.5, 0.5, 1.5, 2.5})
      std::cout << " " << L.count(IsoRect(Point::cartesian(x, y), T1(0, -1), T1(0, -1)));
    std::cout << "\n";
  }
  //< grid-demo
  std::cout << "\n";
}

void queries() {
  std::cout << "== rectangles of T2\n";
  //> query-demo
  const std::vector<Point> P = chapter15::mixed_points();
  const t2::LocusCounter L(P);
  const IsoRect box(Point::cartesian(-1, -1), T1(1, 3), T1(1, 2));  // [-1, 2] x [-1, 1]
  const IsoRect quadrant(Point::cartesian(0, 0), T1(0, 1), T1(0, 1));  // x, y >= 0
  const IsoRect back(Point(-1, 0, 0), T1(1, 2), T1(1, 2));  // on the back side
  for (const IsoRect& r : {box, quadrant, back})
    std::cout << L.count(r) << " points in " << t2::to_string(r) << "\n";
  //< query-demo
  for (const IsoRect& r : {box, quadrant, back}) require(L.count(r) == brute(P, r), "the three rectangles");
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> c(-1, 1);
  int agree = 0;
  t2::gen::Options o;
  o.n = 400;
  o.seed = 15;
  const auto R = t2::gen::points(t2::gen::Kind::both_sides, o);
  const t2::LocusCounter M(R);
  for (int q = 0; q < 1000; ++q) {
    const double x = c(rng), y = c(rng), a = c(rng), b = c(rng);  // drawn in this order
    const IsoRect r(Point(q % 2 ? 1 : -1, x, y), T1(1, a), T1(q % 7 ? 1 : 0, b));
    agree += M.count(r) == brute(R, r);
  }
  std::cout << "1000 random rectangles over 400 points on both sides: the counts agree on " << agree
            << ", with " << M.cells() << " stored counts\n";
  require(agree == 1000, "random rectangles");
  std::cout << "\n";
}

// The indices of the points in r, by testing every point.
std::vector<std::size_t> inside(const std::vector<Point>& P, const t2::ExactIsoRect& r) {
  std::vector<std::size_t> in;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (t2::contains(r, t2::to_exact(P[i]))) in.push_back(i);
  return in;
}

void trees() {
  std::cout << "== the kd-tree and the range tree\n";
  //> kdtree-demo
  // A thin window, the segment x = 1/2, 0 <= y <= 1, over n uniform points of the unit
  // square: the nodes of the kd-tree it enters grow like the square root of n.
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> u(0, 1);
  const t2::ExactIsoRect line(t2::to_exact(Point::cartesian(0.5, 0)), t2::ExactT1(1, 0),
                              t2::ExactT1(1, 1));
  std::vector<Point> P;
  for (std::size_t n = 1024; n <= 262144; n *= 4) {
    while (P.size() < n) {
      const double x = u(rng), y = u(rng);
      P.push_back(Point::cartesian(x, y));
    }
    const t2::KdTree T(P);
    std::cout << "n = " << n << ": " << T.visits(line) << " nodes entered, sqrt(n) = "
              << std::sqrt(double(n)) << "\n";
  }
  //< kdtree-demo
  t2::gen::Options o;
  o.n = 400;
  o.seed = 15;
  const auto R = t2::gen::points(t2::gen::Kind::both_sides, o);
  const t2::KdTree K(R);
  const t2::RangeTree G(R);
  std::uniform_real_distribution<double> c(-1, 1);
  int agree = 0;
  for (int q = 0; q < 1000; ++q) {
    const double x = c(rng), y = c(rng), a = c(rng), b = c(rng);  // drawn in this order
    const t2::ExactIsoRect r(t2::to_exact(Point(q % 2 ? 1 : -1, x, y)), t2::to_exact(T1(1, a)),
                             t2::to_exact(T1(q % 7 ? 1 : 0, b)));
    const auto want = inside(R, r);
    agree += K.report(r) == want && G.report(r) == want;
  }
  std::cout << "1000 random rectangles over 400 points on both sides: kd-tree and range tree "
               "report what contains says on "
            << agree << ", the range tree with " << G.entries() << " list entries\n";
  require(agree == 1000, "the trees' reports");
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = t2::draw::figures_dir(argc, argv, T2_FIGURES_DIR);
  grid();
  queries();
  trees();
  chapter15::figures(dir);
}
