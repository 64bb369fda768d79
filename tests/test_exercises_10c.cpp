// Exercise 10c (the band across Ω) against the library. The reference solution's band (its own
// hulls and merge, exercises/10c-band/solution/band.cpp) is the set of faces of the library's
// Delaunay complex (t2::delaunay_complex: the whole sphere, clockwise band faces kept) with
// vertices on both sides; the faces of t2::delaunay across Ω are those of them that do not turn
// clockwise (the others became v∞); and the reference throws t2::Undefined exactly when both
// library functions do. Inputs: random sites with mixed weights, in general position and on a
// small grid (collinear hull sites, parallel hull edges facing each other, back sites on the
// lines of front hull edges), with antipodal pairs, a few back sites near Ω (a hull), and tiny
// sets. And the grader refuses a submission that calls one of the names its manifest forbids.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "../exercises/harness/grader_testing.hpp"
#include "solution/band.cpp"  // the reference solution of exercises/10c-band
#include "t2/kernel/error.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/voronoi/complex.hpp"

namespace {

using t2::Point;
using Tri = std::array<long, 3>;

Tri rotated(Tri t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

bool both_sides(const std::vector<Point>& P, const Tri& t) {
  const bool f = P[t[0]].w() > 0 || P[t[1]].w() > 0 || P[t[2]].w() > 0;
  const bool b = P[t[0]].w() < 0 || P[t[1]].w() < 0 || P[t[2]].w() < 0;
  return f && b;
}

// What the comparison found: 1 for a band with a clockwise face, 2 with a flat (antipodal) face,
// -1 for Undefined, 0 otherwise (bits or'ed).
int expect_same(const std::vector<Point>& P, const std::string& what) {
  std::vector<long> mine;
  try {
    mine = ex10c::band(P);
  } catch (const t2::Undefined&) {
    EXPECT_THROW(t2::delaunay_complex(P), t2::Undefined) << what;
    EXPECT_THROW(t2::delaunay(P), t2::Undefined) << what;
    return -1;
  }
  std::multiset<Tri> band, ccw, complex, lib;
  int found = 0;
  for (std::size_t k = 0; k < mine.size(); k += 3) {
    const Tri t = rotated({mine[k], mine[k + 1], mine[k + 2]});
    band.insert(t);
    const t2::Sign o = t2::orient(P[t[0]], P[t[1]], P[t[2]]);
    if (o != t2::NEGATIVE) ccw.insert(t);
    found |= o == t2::NEGATIVE ? 1 : o == t2::ZERO ? 2 : 0;
  }
  for (const auto& f : t2::delaunay_complex(P).faces) {
    const Tri t = rotated({long(f[0]), long(f[1]), long(f[2])});
    if (both_sides(P, t)) complex.insert(t);
  }
  for (const auto& f : t2::delaunay(P).finite_triangles()) {
    const Tri t = rotated({long(f[0]), long(f[1]), long(f[2])});
    if (both_sides(P, t)) lib.insert(t);
  }
  EXPECT_EQ(band, complex) << what;
  EXPECT_EQ(ccw, lib) << what;
  return found;
}

// n distinct sites (T² equality), both sides non-empty, none on Ω, not all on one line.
std::vector<Point> sites(std::mt19937_64& g, int n, int range, int near_omega) {
  auto c = [&](int m) { return double(long(g() % (2 * m + 1)) - m); };
  std::vector<Point> P;
  while (int(P.size()) < n) {
    const bool back = P.size() == 1 || (P.size() > 1 && g() % 2);
    double w = double(1 + g() % 3);
    if (back && near_omega > 0 && int(g() % 4) < near_omega) w = 1, P.push_back(Point(-w, 40 + c(5), c(30)));
    else P.push_back(Point(back ? -w : w, w * c(range), w * c(range)));
    if (std::count(P.begin(), P.end(), P.back()) > 1) P.pop_back();
  }
  return P;
}

bool on_one_line(const std::vector<Point>& P) {
  for (const Point& q : P)
    if (!(q == P[0] || q == t2::antipode(P[0]))) {
      for (const Point& r : P)
        if (t2::orient(P[0], q, r) != t2::ZERO) return false;
      return true;
    }
  return true;
}

TEST(Exercise10c, TheReferenceBandIsTheLibrarys) {
  std::mt19937_64 g(1028);
  int clockwise = 0, flat = 0, undefined = 0, rounds = 0;
  for (int round = 0; round < 1500; ++round) {
    const int n = 3 + int(g() % 12), range = round % 3 == 0 ? 2 : round % 3 == 1 ? 4 : 1000;
    std::vector<Point> P = sites(g, n, range, round % 5 == 0 ? 3 : 0);
    if (round % 4 == 1) {  // the antipode of a site as a further site
      const Point a = t2::antipode(P[g() % P.size()]);
      if (std::count(P.begin(), P.end(), a) == 0) P.push_back(Point(2 * a.w(), 2 * a.x(), 2 * a.y()));
    }
    if (on_one_line(P)) continue;
    ++rounds;
    const int r = expect_same(P, "round " + std::to_string(round));
    if (r < 0) ++undefined;
    else clockwise += (r & 1) != 0, flat += (r & 2) != 0;
  }
  EXPECT_GT(rounds, 1400);
  EXPECT_GT(clockwise, 100);
  EXPECT_GT(flat, 30);
  EXPECT_GT(undefined, 30);
}

TEST(Exercise10c, TinySetsAreTheLibrarys) {
  const std::vector<std::vector<Point>> cases = {
      {Point(1, 0, 0), Point(-1, -1, -2), Point(-1, -3, -1)},                   // 1 + 2
      {Point(1, 0, 0), Point(2, 2, 0), Point(-1, -1, -2)},                      // 2 + 1
      {Point(1, 0, 0), Point(1, 1, 0), Point(1, 2, 0), Point(-1, 0, -1)},       // 3 collinear + 1
      {Point(1, 0, 0), Point(1, 2, 0), Point(-2, 0, -2), Point(-1, -2, -1)},    // 2 + 2, parallel
      {Point(1, 0, 0), Point(-1, 0, -1), Point(-1, -1, 0), Point(-3, 3, 3)},    // 1 + 3
      {Point(1, 0, 0), Point(1, 1, 0), Point(-1, 0, 0), Point(-1, 0, -1)},      // an antipodal pair
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    ASSERT_FALSE(on_one_line(cases[k])) << k;
    EXPECT_GE(expect_same(cases[k], "case " + std::to_string(k)), 0) << k;
  }
}

// The grader reads the compiled object's symbols: a solution of 10c that takes the library's
// t2::delaunay (declared by hand, since no allowed header declares it) scores 0, named.
TEST(Exercise10c, TheGraderRefusesTheLibrarysDelaunay) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "grading compiles and runs programs: skipped under sanitizers";
  t2::grader_testing::TempDir t;
  std::ofstream(t.path / "band.cpp") << R"(#include "band.hpp"
#include <span>
#include <stdexcept>
namespace t2 {
class Triangulation;
Triangulation delaunay(std::span<const Point> points);
}  // namespace t2
namespace ex10c {
std::vector<long> owners(const std::vector<t2::Point>&, const t2::Point&) {
  throw std::logic_error("owners() is not implemented yet");
}
std::vector<long> band(const std::vector<t2::Point>&) {
  using Delaunay = t2::Triangulation (*)(std::span<const t2::Point>);
  volatile Delaunay d = &t2::delaunay;
  (void)d;
  throw std::logic_error("band() is not implemented yet");
}
}  // namespace ex10c
)";
  const auto r = t2::grader_testing::grade(T2_TOOL, "10c", t.path);
  EXPECT_EQ(r.score, 0);
  EXPECT_NE(r.output.find("your code calls t2::delaunay"), std::string::npos) << r.output;
}

}  // namespace
