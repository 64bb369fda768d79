// Exercise 07c (the hull of a simple polygon in linear time) against the library. The reference
// solution (exercises/07c-melkman/solution/hull.cpp, written for the exercise on the kernel's
// orient alone) gives exactly t2::melkman's answer — the same vertices, named by the same
// indices, in the same order from the same start — on star-shaped polygons of a small grid
// (collinear neighbours, vertices inside hull edges, repeated vertices at another scale, polygons
// on one line), lifted to the front, the back and across Ω. And the grader refuses a submission
// that calls t2::melkman.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <vector>

#include "../exercises/harness/grader_testing.hpp"
#include "solution/hull.cpp"  // the reference solution of exercises/07c-melkman
#include "t2/hull/melkman.hpp"

namespace {

using t2::Point;

// m grid points of |x|, |y| ≤ r with distinct directions from the origin, sorted by angle: a
// star-shaped polygon (the origin sees it all), with collinear runs when r is small.
std::vector<std::array<double, 2>> star(std::mt19937_64& g, int m, int r) {
  std::vector<std::array<double, 2>> v;
  for (int k = 0; k < 8 * m && int(v.size()) < m; ++k) {
    const double x = double(long(g() % (2 * r + 1)) - r), y = double(long(g() % (2 * r + 1)) - r);
    const bool taken = std::any_of(v.begin(), v.end(), [&](const auto& p) { return p[0] * y == p[1] * x && p[0] * x + p[1] * y > 0; });
    if ((x != 0 || y != 0) && !taken) v.push_back({x, y});
  }
  std::sort(v.begin(), v.end(), [](const auto& p, const auto& q) { return std::atan2(p[1], p[0]) < std::atan2(q[1], q[0]); });
  return v;
}

TEST(Exercise07c, TheReferenceIsTheLibrarysMelkman) {
  std::mt19937_64 g(2807);
  int rounds = 0, collinear = 0;
  for (int round = 0; round < 3000; ++round) {
    auto v = star(g, 3 + int(g() % 14), round % 2 ? 3 : 50);
    bool around = true;  // every angular gap under a half-turn: the origin is inside, the polygon simple
    for (std::size_t k = 0; k < v.size(); ++k) {
      const auto &p = v[k], &q = v[(k + 1) % v.size()];
      around = around && p[0] * q[1] - p[1] * q[0] > 0;
    }
    if (round % 7 == 0) v.resize(std::min<std::size_t>(v.size(), 2));  // a point or a segment
    else if (!around) continue;
    if (g() % 2) std::reverse(v.begin(), v.end());
    const int side = round % 3;  // front, back, across Ω (the open hemisphere x > 0)
    std::vector<Point> P;
    for (const auto& [a, b] : v) {
      const double s = double(1 + g() % 3);
      P.push_back(side == 0 ? Point(s, s * a, s * b) : side == 1 ? Point(-s, -s * a, -s * b) : Point(s * a, s * 60, s * b));
      if (g() % 5 == 0) P.push_back(Point(2 * P.back().w(), 2 * P.back().x(), 2 * P.back().y()));
    }
    if (P.empty()) continue;
    ++rounds;
    const std::vector<long> mine = ex07c::hull(P);
    const std::vector<std::size_t> lib = t2::melkman(std::span<const Point>(P));
    collinear += lib.size() <= 2;
    EXPECT_EQ(std::vector<long>(lib.begin(), lib.end()), mine) << "round " << round;
  }
  EXPECT_GT(rounds, 1500);
  EXPECT_GT(collinear, 300);
}

// The grader reads the compiled object's symbols: a solution of 07c that takes the library's
// t2::melkman (declared by hand, since no allowed header declares it) scores 0, named.
TEST(Exercise07c, TheGraderRefusesTheLibrarysMelkman) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "grading compiles and runs programs: skipped under sanitizers";
  t2::grader_testing::TempDir t;
  std::ofstream(t.path / "hull.cpp") << R"(#include "hull.hpp"
#include <span>
#include <stdexcept>
namespace t2 {
std::vector<std::size_t> polygon_hull(std::span<const Point> P);
}  // namespace t2
namespace ex07c {
std::vector<long> hull(const std::vector<t2::Point>&) {
  using Hull = std::vector<std::size_t> (*)(std::span<const t2::Point>);
  volatile Hull h = &t2::polygon_hull;
  (void)h;
  throw std::logic_error("hull() is not implemented yet");
}
}  // namespace ex07c
)";
  const auto r = t2::grader_testing::grade(T2_TOOL, "07c", t.path);
  EXPECT_EQ(r.score, 0);
  EXPECT_NE(r.output.find("your code calls t2::polygon_hull"), std::string::npos) << r.output;
}

}  // namespace
