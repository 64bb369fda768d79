// The three smallest-enclosing-circle algorithms — Welzl's (enclosing_circle.hpp), Shamos's and
// Bhattacharya–Toussaint's (enclosing_circle_voronoi.hpp) — give the same answer exactly: the same
// centre W X Y, squared radius, sites on the circle and support, and the same exceptions. Each is
// checked against brute force on exact rationals (small n: front, back, duplicates, collinear,
// cocircular) and CGAL's Min_circle_2 (front, large n, sites all on one circle), and the support
// against brute force on the support alone (it defines the circle). Then seed 003's figure 4.31
// (the diameter is no farthest-point Delaunay edge) and `t2 sec --algorithm`.
#include <fmt/format.h>

#include <random>
#include <set>

#include "cgal/cgal_oracle.hpp"
#include "cli_testing.hpp"
#include "oracle.hpp"
#include "sec_oracle.hpp"
#include "t2/gen/generate.hpp"
#include "t2/proximity/enclosing_circle.hpp"
#include "t2/proximity/enclosing_circle_voronoi.hpp"
#include "t2/voronoi/complex.hpp"

namespace t2::testing {
namespace {

using Index = EnclosingCircle::Index;

/// Runs the three algorithms on P, checks that they agree exactly and that Welzl's answer is
/// `want` (expect_circle), and that the support alone has the same circle.
void expect_three(const std::vector<Point>& P, const Circ& want) {
  const EnclosingCircle w = smallest_enclosing_circle(P), s = smallest_enclosing_circle_shamos(P),
                        b = smallest_enclosing_circle_bt(P);
  expect_circle(P, w, want);
  for (const auto& [name, c] : {std::pair{"shamos", &s}, std::pair{"bt", &b}}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(c->center, w.center);
    EXPECT_EQ(c->radius2, w.radius2);
    EXPECT_EQ(c->on_circle, w.on_circle);
    EXPECT_EQ(c->support, w.support);
  }
  std::vector<Point> S;
  for (Index i : w.support) S.push_back(P[i]);
  const Circ own = brute(S);
  EXPECT_EQ(own.c, want.c) << "the support defines the circle";
  EXPECT_EQ(own.r2, want.r2);
}

/// The twelve lattice points of x² + y² = 25 (cocircular, with antipodal pairs).
std::vector<std::array<int, 2>> ring25() {
  return {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
}

// Small sets against brute force: a grid with many duplicates and collinear triples, points
// of one circle (cocircular, with and without diametral pairs), on the front and on the back
// with other weights.
TEST(EnclosingCircleAlgorithms, BruteForce) {
  std::mt19937 rng(1225);
  std::uniform_int_distribution<int> c(-4, 4), size(1, 10), scale(1, 3), pick(0, 11), kind(0, 2);
  const auto ring = ring25();
  for (int round = 0; round < 600; ++round) {
    const int n = size(rng), w = round % 3 == 2 ? -1 : 1, k = kind(rng);
    std::vector<Point> P;
    for (int m = 0; m < n; ++m) {
      const int s = w * scale(rng);  // [s, s x, s y]: drawn at (x, y) on w's side
      std::array<int, 2> xy{c(rng), c(rng)};
      if (k == 1 || (k == 2 && m % 2)) xy = ring[pick(rng)];  // on the circle (k = 2: and inside)
      if (k == 2 && m % 2 == 0) xy = {xy[0] / 2, xy[1] / 2};
      P.emplace_back(s, s * xy[0], s * xy[1]);
    }
    SCOPED_TRACE(round);
    expect_three(P, brute(P));
  }
}

// Drawn positions 2^±500 apart from their weights, far outside the filters' range, where the
// complex, the hull and the diameter test all reach their exact stages.
TEST(EnclosingCircleAlgorithms, ExtremeScales) {
  std::mt19937 rng(31);
  std::uniform_int_distribution<int> c(-5, 5), size(2, 8), e(0, 2);
  const int exps[3] = {-500, 0, 500};
  for (int round = 0; round < 120; ++round) {
    const int n = size(rng), side = round % 2 ? -1 : 1, ex = exps[e(rng)], wx = exps[e(rng)];
    std::vector<Point> P;
    for (int m = 0; m < n; ++m) {
      const double w = side * std::ldexp(1.0 + (m % 2), wx), s = std::ldexp(1.0 + (m % 2), ex);
      P.emplace_back(w, s * c(rng), s * c(rng));
    }
    SCOPED_TRACE(round);
    expect_three(P, brute(P));
  }
}

// One, two, three sites; equal sites; collinear sites with duplicates; a right triangle (the
// diameter is a side and the third site on the circle).
TEST(EnclosingCircleAlgorithms, FewAndDegenerate) {
  const std::vector<std::vector<Point>> cases{
      {Point(2, 6, -4)},
      {Point(-2, 6, -4)},
      {Point(1, 0, 0), Point(2, 6, 8)},
      {Point(4, 4, 8), Point(1, 1, 2), Point(2, 2, 4)},
      {Point(1, 0, 0), Point(1, 4, 0), Point(1, 0, 3)},
      {Point(1, 0, 0), Point(1, 4, 0), Point(1, 1, 1)},
      {Point(1, 0, 0), Point(1, 2, 1), Point(3, 12, 6), Point(1, 2, 1), Point(1, -2, -1), Point(1, 0, 0)},
      {Point(-1, 0, 0), Point(-1, 1, 1), Point(-1, 2, 2)},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE(k);
    expect_three(cases[k], brute(cases[k]));
  }
  std::vector<Point> line;  // 50 collinear sites in scrambled order, an end repeated at scale 4
  for (int k = 0; k < 50; ++k) line.emplace_back(1, (k * 37) % 50, 2 * ((k * 37) % 50) + 1);
  line.emplace_back(4, 0, 4);
  expect_three(line, {{Rational(49, 2), Rational(50)}, Rational(49 * 49 * 5, 4)});
}

// Larger front sets against CGAL's Min_circle_2 on the exact kernel, and their antipodes.
TEST(EnclosingCircleAlgorithms, Cgal) {
  for (gen::Kind k : {gen::Kind::uniform, gen::Kind::disk, gen::Kind::normal, gen::Kind::circle, gen::Kind::grid,
                      gen::Kind::duplicates, gen::Kind::segment, gen::Kind::boundary})
    for (std::uint64_t seed : {1, 2}) {
      gen::Options o;
      o.n = 2000;
      o.seed = seed;
      std::vector<Point> P = gen::points(k, o);
      SCOPED_TRACE(fmt::format("{} seed {}", gen::name(k), seed));
      const auto want = cgal::min_circle_2(P);
      const EnclosingCircle w = smallest_enclosing_circle(P);
      expect_circle(P, w, {want.center, want.radius2});
      EXPECT_EQ(smallest_enclosing_circle_shamos(P).support, w.support);
      const EnclosingCircle b = smallest_enclosing_circle_bt(P);
      EXPECT_EQ(b.center, w.center);
      EXPECT_EQ(b.on_circle, w.on_circle);
      EXPECT_EQ(b.support, w.support);
      for (Point& p : P) p = antipode(p);
      const EnclosingCircle back = smallest_enclosing_circle_shamos(P);
      EXPECT_EQ(back.center, antipode(w.center));
      EXPECT_EQ(back.support, w.support);
      EXPECT_EQ(smallest_enclosing_circle_bt(P).on_circle, w.on_circle);
    }
}

// All sites on one circle (the 324 lattice points of x² + y² = R², R = 5·13·17·29): with their
// diametral pairs, then one site of each antipodal pair kept at random (no diametral pair left,
// the centre inside a fan of many cocircular faces), with interior sites; against CGAL.
TEST(EnclosingCircleAlgorithms, Cocircular) {
  const long R = 5 * 13 * 17 * 29;
  std::vector<Point> ring;
  for (long x = -R; x <= R; ++x) {
    const long y2 = R * R - x * x, y = std::lround(std::sqrt(double(y2)));
    if (y * y != y2) continue;
    ring.push_back(Point::cartesian(double(x), double(y)));
    if (y != 0) ring.push_back(Point::cartesian(double(x), double(-y)));
  }
  ASSERT_EQ(ring.size(), 324u);
  expect_three(ring, {{Rational(0), Rational(0)}, Rational(R * R)});
  std::mt19937 rng(4);
  for (int round = 0; round < 6; ++round) {
    std::vector<Point> P;
    std::set<std::pair<double, double>> kept;
    std::shuffle(ring.begin(), ring.end(), rng);
    for (const Point& p : ring)
      if (!kept.count({-p.x(), -p.y()}) && rng() % 2) {
        kept.insert({p.x(), p.y()});
        P.push_back(p);
      }
    for (int k = 0; k < 40 * round; ++k) P.push_back(Point::cartesian(double(k % 97) - 48, double(k % 89) - 44));
    SCOPED_TRACE(round);
    const auto want = cgal::min_circle_2(P);
    const EnclosingCircle w = smallest_enclosing_circle(P), s = smallest_enclosing_circle_shamos(P),
                          b = smallest_enclosing_circle_bt(P);
    expect_circle(P, w, {want.center, want.radius2});
    EXPECT_EQ(s.center, w.center);
    EXPECT_EQ(b.center, w.center);
    EXPECT_EQ(s.on_circle, w.on_circle);
    EXPECT_EQ(b.on_circle, w.on_circle);
    EXPECT_EQ(s.support, w.support);
    EXPECT_EQ(b.support, w.support);
  }
}

// Seed 003's figure 4.31: the diameter ab of {a, b, c, d} is no edge of the farthest-point
// Delaunay triangulation (c and d lie outside its circle, on either side), yet the longest
// edge's test fails and the acute face acd gives the circle, centre (17/32, 0).
TEST(EnclosingCircleAlgorithms, DiameterIsNoFarthestEdge) {
  const std::vector<Point> P{Point(1, -10, 0), Point(1, 6, -9), Point(1, 10, 0), Point(1, 6, 9)};  // a d b c
  for (const auto& t : farthest_delaunay(P))
    for (int m = 0; m < 3; ++m) {
      const std::set<Index> e{t[m], t[(m + 1) % 3]};
      EXPECT_NE(e, (std::set<Index>{0, 2})) << "ab is a farthest-point Delaunay edge";
    }
  expect_three(P, brute(P));
  EXPECT_EQ(smallest_enclosing_circle_shamos(P).center, ExactPoint(32, 17, 0));
  EXPECT_EQ(smallest_enclosing_circle_bt(P).support, (std::vector<Index>{0, 1, 3}));
}

// Ω and both sides: the three throw the same UndefinedEnclosing, naming the same sites.
TEST(EnclosingCircleAlgorithms, Undefined) {
  const std::vector<std::vector<Point>> cases{
      {Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 1)},
      {Point(-1, 0, 0), Point(-1, 1, 0), Point(2, 1, 1)},
      {Point(0, 1, 0), Point(-1, 0, 0), Point(3, 1, 1), Point(1, 0, 0)},
      {Point(0, 1, 0), Point(0, 0, 1)},
      {Point(1, 3, 4), Point(-1, -3, -4)},
  };
  using F = EnclosingCircle (*)(std::span<const Point>);
  const F algorithms[] = {smallest_enclosing_circle, smallest_enclosing_circle_shamos, smallest_enclosing_circle_bt};
  for (std::size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE(k);
    std::vector<std::string> got;
    for (F f : algorithms) {
      try {
        f(cases[k]);
        ADD_FAILURE() << "no exception";
      } catch (const UndefinedEnclosing& e) {
        got.push_back(fmt::format("{} {} {}", e.site, e.other, e.what()));
      }
    }
    ASSERT_EQ(got.size(), 3u);
    EXPECT_EQ(got[1], got[0]);
    EXPECT_EQ(got[2], got[0]);
  }
  for (F f : algorithms) EXPECT_THROW(f(std::vector<Point>{}), BadInput);
}

class EnclosingCircleAlgorithmsCli : public CliTest {};

TEST_F(EnclosingCircleAlgorithmsCli, TheThreeAlgorithmsPrintTheSame) {
  write("p.t2", "0 0\n4 0\n# a comment\n0 3\n1 1\n2 8 0\n-10 0\n6 -9\n10 0\n6 9\n");
  const Result w = t2("sec p.t2");
  ASSERT_EQ(w.status, 0) << w.err;
  EXPECT_EQ(w.out, "32 17 0\n5 6 8\n");
  for (const char* a : {"welzl", "shamos", "bt"}) {
    const Result r = t2(fmt::format("sec p.t2 --algorithm {}", a));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, w.out) << a;
  }
  write("o.t2", "0 0\n1 0\n0 1 1\n");
  const Result o = t2("sec o.t2 --algorithm bt");
  EXPECT_EQ(o.status, 3);
  EXPECT_NE(o.err.find("o.t2:3"), std::string::npos) << o.err;
  EXPECT_EQ(t2("sec o.t2 --algorithm shamos").status, 3);
  EXPECT_EQ(t2("sec p.t2 --algorithm megiddo").status, 2);
}

}  // namespace
}  // namespace t2::testing
