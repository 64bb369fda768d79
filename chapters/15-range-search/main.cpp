// Chapter 15: range search. Counting the points in iso-rectangles of T² by the locus method
// (seed 000, Algorithms 17-18), checked against testing every point; the figures in both models
// (figures.cpp).
#include <t2/draw.hpp>
#include <t2/gen/generate.hpp>
#include <t2/kernel/bbox.hpp>
#include <t2/range/locus.hpp>
#include <t2/t2.hpp>

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
    const IsoRect r(Point(q % 2 ? 1 : -1, c(rng), c(rng)), T1(1, c(rng)), T1(q % 7 ? 1 : 0, c(rng)));
    agree += M.count(r) == brute(R, r);
  }
  std::cout << "1000 random rectangles over 400 points on both sides: the counts agree on " << agree
            << ", with " << M.cells() << " stored counts\n";
  require(agree == 1000, "random rectangles");
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = t2::draw::figures_dir(argc, argv, T2_FIGURES_DIR);
  grid();
  queries();
  chapter15::figures(dir);
}
