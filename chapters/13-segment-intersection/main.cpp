// Chapter 13: segment intersection. What is reported (the degenerate cases), the brute force on
// the whole of T², Bentley–Ottmann on the front side, the circular sweep of T², checked against
// each other; the figures in both models (figures.cpp).
#include <t2/gen/generate.hpp>
#include <t2/intersect/intersections.hpp>
#include <t2/draw.hpp>
#include <t2/t2.hpp>

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "figures.hpp"

namespace {

using t2::Point;
using t2::Segment;

void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("chapter 13: check failed: ") + what);
}

bool same(const std::vector<t2::IntersectionPoint>& a, const std::vector<t2::IntersectionPoint>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (t2::to_line(a[k]) != t2::to_line(b[k])) return false;
  return true;
}

void reported() {
  std::cout << "== what is reported\n";
  //> reported-demo
  const std::vector<Segment> S = chapter13::degenerate_cases();
  const auto brute = t2::intersections(S, t2::IntersectAlgorithm::brute);
  for (const auto& p : brute) std::cout << t2::to_line(p) << "\n";
  const auto sweep = t2::intersections(S, t2::IntersectAlgorithm::sweep);
  std::cout << "the sweep gives the same lines: " << std::boolalpha << same(brute, sweep)
            << "\n";
  //< reported-demo
  require(same(brute, sweep) && brute.size() == 6, "the degenerate cases");
  std::cout << "\n";
}

void two_sides() {
  std::cout << "== segments of T²\n";
  //> two-sides-demo
  const std::vector<Segment> S = chapter13::two_sided();
  for (const auto& p : t2::intersections(S, t2::IntersectAlgorithm::brute))
    std::cout << t2::to_line(p) << "\n";
  try {
    t2::intersections(S, t2::IntersectAlgorithm::sweep);
  } catch (const t2::Undefined& e) {
    std::cout << "sweep: " << e.what() << "\n";
  }
  //< two-sides-demo
  std::cout << "\n";
}

void beside_a_triple_point() {
  std::cout << "== an endpoint beside a triple point\n";
  //> triple-demo
  const std::vector<Segment> S = chapter13::beside_triple_point();
  const auto sweep = t2::intersections(S, t2::IntersectAlgorithm::sweep);
  for (const auto& p : sweep) std::cout << t2::to_line(p) << "\n";
  //< triple-demo
  require(same(sweep, t2::intersections(S, t2::IntersectAlgorithm::brute)) && sweep.size() == 4, "triple point");
  std::cout << "\n";
}

void random_sets() {
  std::cout << "== random sets\n";
  int agree = 0, points = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    t2::gen::Options o;
    o.n = 150;
    o.seed = seed;
    o.crossings = 300;
    const auto S = t2::gen::segments(o);
    const auto sweep = t2::intersections(S, t2::IntersectAlgorithm::sweep);
    agree += same(sweep, t2::intersections(S, t2::IntersectAlgorithm::brute));
    points += static_cast<int>(sweep.size());
  }
  std::cout << "40 sets of 150 segments with 300 crossings each: the sweep equals the brute force on "
            << agree << ", " << points << " points in all\n";
  require(agree == 40, "random sets");
}

void circular_sweep() {
  std::cout << "== the circular sweep of T²\n";
  //> circular-demo
  const std::vector<Segment> S = chapter13::two_sided();
  const auto circular = t2::intersections(S, t2::IntersectAlgorithm::circular);
  for (const auto& p : circular) std::cout << t2::to_line(p) << "\n";
  std::cout << "the brute force gives the same lines: " << std::boolalpha
            << same(circular, t2::intersections(S, t2::IntersectAlgorithm::brute)) << "\n";
  //< circular-demo
  require(same(circular, t2::intersections(S, t2::IntersectAlgorithm::brute)), "circular sweep");
  // Random segments of every kind: small integer coordinates, w in {-1, 0, 1, 2}.
  std::uint64_t state = 13;
  const auto next = [&state](int n) {
    state = state * 6364136223846793005u + 1442695040888963407u;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(n));
  };
  int agree = 0, points = 0;
  for (int round = 0; round < 40; ++round) {
    std::vector<Segment> T;
    while (T.size() < 60) {
      const int a[6] = {next(4) - 1, next(9) - 4, next(9) - 4, next(4) - 1, next(9) - 4, next(9) - 4};
      if ((a[0] == 0 && a[1] == 0 && a[2] == 0) || (a[3] == 0 && a[4] == 0 && a[5] == 0)) continue;
      const Point p(a[0], a[1], a[2]), q(a[3], a[4], a[5]);
      if (!(p == t2::antipode(q))) T.emplace_back(p, q);
    }
    const auto c = t2::intersections(T, t2::IntersectAlgorithm::circular);
    agree += same(c, t2::intersections(T, t2::IntersectAlgorithm::brute));
    points += static_cast<int>(c.size());
  }
  std::cout << "40 sets of 60 segments of every kind: the circular sweep equals the brute force on "
            << agree << ", " << points << " points in all\n";
  require(agree == 40, "circular sweep on random sets");
  std::cout << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = t2::draw::figures_dir(argc, argv, T2_FIGURES_DIR);
  reported();
  two_sides();
  beside_a_triple_point();
  random_sets();
  circular_sweep();
  chapter13::figures(dir);
}
