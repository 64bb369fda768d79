// The smallest enclosing circle (t2/proximity/enclosing_circle.hpp) against two independent
// oracles: brute force over every circle through two or three sites on exact rationals (small
// n, front and back sites, many duplicates, collinear and cocircular sites), and CGAL's
// Min_circle_2 on the exact kernel (front sites, large n). Then adversarial orders (sorted
// input, all sites on one circle), duplicates at other scales, the undefined cases, and `t2 sec`.
#include <fmt/format.h>

#include <optional>
#include <random>

#include "cgal/cgal_oracle.hpp"
#include "cli_testing.hpp"
#include "oracle.hpp"
#include "sec_oracle.hpp"
#include "t2/gen/generate.hpp"
#include "t2/proximity/enclosing_circle.hpp"

namespace t2::testing {
namespace {

using Index = EnclosingCircle::Index;

// Small sets with many duplicates, collinear and cocircular sites, on the front and on the
// back (the back ones with other weights), against brute force.
TEST(EnclosingCircle, BruteForce) {
  std::mt19937 rng(25);
  std::uniform_int_distribution<int> c(-4, 4), size(1, 11), scale(1, 3);
  for (int round = 0; round < 400; ++round) {
    const int n = size(rng), w = round % 3 == 2 ? -1 : 1;
    std::vector<Point> P;
    for (int k = 0; k < n; ++k) {
      const int s = w * scale(rng);  // [s, s x, s y]: the drawn position (x, y) on w's side
      const int x = c(rng), y = c(rng);
      P.emplace_back(s, s * x, s * y);
    }
    SCOPED_TRACE(round);
    expect_circle(P, smallest_enclosing_circle(P), brute(P));
  }
}

// Coordinates far outside the filters' range (2^±600 apart), against brute force.
TEST(EnclosingCircle, ExtremeCoordinates) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> c(-6, 6), size(2, 9), e(0, 2);
  const int exps[3] = {-500, 0, 500};
  for (int round = 0; round < 150; ++round) {
    const int n = size(rng), sign = round % 2 ? -1 : 1, ex = exps[e(rng)], wx = exps[e(rng)];
    std::vector<Point> P;
    for (int k = 0; k < n; ++k) {  // drawn at 2^(ex - wx)·(x, y), with weights of other scales
      const double w = sign * std::ldexp(1.0 + (k % 3), wx);
      P.emplace_back(w, std::ldexp(c(rng), ex) * (1 + k % 3), std::ldexp(c(rng), ex) * (1 + k % 3));
    }
    SCOPED_TRACE(round);
    expect_circle(P, smallest_enclosing_circle(P), brute(P));
  }
}

// Larger front sets against CGAL's Min_circle_2 on the exact kernel.
TEST(EnclosingCircle, Cgal) {
  for (gen::Kind k : {gen::Kind::uniform, gen::Kind::disk, gen::Kind::normal, gen::Kind::kuzmin, gen::Kind::circle,
                      gen::Kind::grid, gen::Kind::duplicates, gen::Kind::segment, gen::Kind::boundary})
    for (std::uint64_t seed : {1, 2, 3}) {
      gen::Options o;
      o.n = 3000;
      o.seed = seed;
      const std::vector<Point> P = gen::points(k, o);
      SCOPED_TRACE(fmt::format("{} seed {}", gen::name(k), seed));
      const auto want = cgal::min_circle_2(P);
      expect_circle(P, smallest_enclosing_circle(P), {want.center, want.radius2});
    }
}

// The orders that defeat the unshuffled algorithm: sorted along x, and sites all on one circle
// in angular order (every site is then on the final circle), exactly.
TEST(EnclosingCircle, AdversarialOrders) {
  gen::Options o;
  o.n = 20000;
  std::vector<Point> P = gen::points(gen::Kind::uniform, o);
  std::sort(P.begin(), P.end(), [](const Point& a, const Point& b) { return a.x() < b.x(); });
  auto want = cgal::min_circle_2(P);
  expect_circle(P, smallest_enclosing_circle(P), {want.center, want.radius2});
  // The lattice points of x² + y² = R², R = 5·13·17·29: 4·81 of them, sorted by angle.
  const long R = 5 * 13 * 17 * 29;
  std::vector<std::pair<double, Point>> ring;
  for (long x = -R; x <= R; ++x) {
    const long y2 = R * R - x * x;
    const long y = std::lround(std::sqrt(double(y2)));
    if (y * y != y2) continue;
    ring.push_back({std::atan2(double(y), double(x)), Point::cartesian(double(x), double(y))});
    if (y != 0) ring.push_back({std::atan2(double(-y), double(x)), Point::cartesian(double(x), double(-y))});
  }
  std::sort(ring.begin(), ring.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  P.clear();
  for (const auto& [a, p] : ring) P.push_back(p);
  ASSERT_EQ(P.size(), 324u);
  const EnclosingCircle c = smallest_enclosing_circle(P);
  expect_circle(P, c, {{Rational(0), Rational(0)}, Rational(R * R)});
  EXPECT_EQ(c.on_circle.size(), P.size());
  EXPECT_EQ(c.center, ExactPoint(1, 0, 0));
  // Reversed, and the same circle's sites with interior sites interleaved.
  std::reverse(P.begin(), P.end());
  for (long k = 0; k < 300; ++k) P.push_back(Point::cartesian(double(k - 150), double(2 * k - 300)));
  expect_circle(P, smallest_enclosing_circle(P), {{Rational(0), Rational(0)}, Rational(R * R)});
}

// One site, two, equal sites at other scales, collinear sites.
TEST(EnclosingCircle, Degenerate) {
  EnclosingCircle c = smallest_enclosing_circle(std::vector<Point>{Point(2, 6, -4)});
  EXPECT_EQ(c.center, ExactPoint(1, 3, -2));
  EXPECT_EQ(c.radius2, 0);
  EXPECT_EQ(c.on_circle, std::vector<Index>{0});
  c = smallest_enclosing_circle(std::vector<Point>{Point(-2, 6, -4)});  // a back site
  EXPECT_EQ(c.center, ExactPoint(-1, 3, -2));
}

TEST(EnclosingCircle, EqualAndCollinearSites) {
  const std::vector<Point> two{Point(1, 0, 0), Point(2, 6, 8)};
  EnclosingCircle c = smallest_enclosing_circle(two);
  EXPECT_EQ(c.center, ExactPoint(2, 3, 4));
  EXPECT_EQ(c.radius2, Rational(25, 4));
  EXPECT_EQ(c.support, (std::vector<Index>{0, 1}));
  const std::vector<Point> same{Point(4, 4, 8), Point(1, 1, 2), Point(2, 2, 4)};
  c = smallest_enclosing_circle(same);
  EXPECT_EQ(c.center, ExactPoint(1, 1, 2));
  EXPECT_EQ(c.radius2, 0);
  EXPECT_EQ(c.on_circle, (std::vector<Index>{0, 1, 2}));
  std::vector<Point> line;
  for (int k = 0; k < 50; ++k) line.emplace_back(1, (k * 37) % 50, 2 * ((k * 37) % 50) + 1);
  line.emplace_back(4, 0, 4);  // a copy of (0, 1) at scale 4
  c = smallest_enclosing_circle(line);
  EXPECT_EQ(c.center, ExactPoint(2, 49, 100));
  std::vector<Index> ends;
  for (Index i = 0; i < line.size(); ++i)
    if (line[i].x() == 0 || line[i].x() == 49) ends.push_back(i);
  EXPECT_EQ(c.on_circle, ends);
  EXPECT_EQ(c.on_circle.size(), 3u);
}

// The back side: the antipode of the front answer of the antipodes.
TEST(EnclosingCircle, BackSites) {
  gen::Options o;
  o.n = 500;
  const std::vector<Point> F = gen::points(gen::Kind::disk, o);
  std::vector<Point> B;
  for (const auto& p : F) B.push_back(antipode(p));
  const EnclosingCircle f = smallest_enclosing_circle(F), b = smallest_enclosing_circle(B);
  EXPECT_EQ(b.center, antipode(f.center));
  EXPECT_LT(b.center.w(), 0);
  EXPECT_EQ(b.radius2, f.radius2);
  EXPECT_EQ(b.on_circle, f.on_circle);
}

// The input order changes nothing but, among cocircular sites, which are the support.
TEST(EnclosingCircle, OrderAndRepeats) {
  gen::Options o;
  o.n = 2000;
  std::vector<Point> P = gen::points(gen::Kind::normal, o);
  const EnclosingCircle a = smallest_enclosing_circle(P), again = smallest_enclosing_circle(P);
  EXPECT_EQ(a.support, again.support) << "deterministic";
  std::mt19937 rng(3);
  std::shuffle(P.begin(), P.end(), rng);
  const EnclosingCircle b = smallest_enclosing_circle(P);
  EXPECT_EQ(a.center, b.center);
  EXPECT_EQ(a.radius2, b.radius2);
}

// The traced run (t2 animate sec) gives the same circle; its last disk is the support, and a
// new disk follows exactly the tests that found a site outside.
TEST(EnclosingCircle, Trace) {
  gen::Options o;
  o.n = 300;
  const std::vector<Point> P = gen::points(gen::Kind::disk, o);
  std::vector<std::size_t> last;
  int disks = 0, outside = 0, tests = 0;
  const EnclosingCircle c = smallest_enclosing_circle(P, [&](const trace::Report& r) {
    if (r.event == trace::Event::enclose) {
      last.assign(r.points().begin(), r.points().end());
      ++disks;
    } else {
      ASSERT_EQ(r.event, trace::Event::in_disk);
      ++tests;
      outside += r.sign == NEGATIVE;
    }
  });
  const EnclosingCircle plain = smallest_enclosing_circle(P);
  EXPECT_EQ(c.support, plain.support);
  EXPECT_EQ(c.center, plain.center);
  std::sort(last.begin(), last.end());
  EXPECT_EQ(last, std::vector<std::size_t>(c.support.begin(), c.support.end()));
  EXPECT_EQ(disks, outside + 1);
  EXPECT_GE(tests, 298);
}

// Ω and both sides: UndefinedEnclosing naming the sites; no sites: BadInput.
TEST(EnclosingCircle, Undefined) {
  try {
    smallest_enclosing_circle(std::vector<Point>{Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 1)});
    FAIL();
  } catch (const UndefinedEnclosing& e) {
    EXPECT_EQ(e.site, 2u);
    EXPECT_EQ(e.other, 2u);
  }
  try {
    smallest_enclosing_circle(std::vector<Point>{Point(-1, 0, 0), Point(-1, 1, 0), Point(2, 1, 1)});
    FAIL();
  } catch (const UndefinedEnclosing& e) {
    EXPECT_EQ(e.site, 2u) << "the front site";
    EXPECT_EQ(e.other, 0u) << "the back site";
  }
  try {  // both sides first, whatever is on Ω
    smallest_enclosing_circle(std::vector<Point>{Point(0, 1, 0), Point(-1, 0, 0), Point(3, 1, 1), Point(1, 0, 0)});
    FAIL();
  } catch (const UndefinedEnclosing& e) {
    EXPECT_EQ(e.site, 2u);
    EXPECT_EQ(e.other, 1u);
  }
  try {  // only Ω
    smallest_enclosing_circle(std::vector<Point>{Point(0, 1, 0), Point(0, 0, 1)});
    FAIL();
  } catch (const UndefinedEnclosing& e) {
    EXPECT_EQ(e.site, 0u);
  }
  // p and its antipode: one drawn position, but no circle of T² holds both.
  EXPECT_THROW(smallest_enclosing_circle(std::vector<Point>{Point(1, 3, 4), Point(-1, -3, -4)}), UndefinedEnclosing);
  EXPECT_THROW(smallest_enclosing_circle(std::vector<Point>{}), BadInput);
}

class EnclosingCircleCli : public CliTest {};

TEST_F(EnclosingCircleCli, PrintsTheCentreAndTheSitesOnTheCircle) {
  write("p.t2", "0 0\n4 0\n# a comment\n0 3\n1 1\n2 8 0\n");
  Result r = t2("sec p.t2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "2 4 3\n0 1 2 4\n");  // centre (2, 3/2): [2, 4, 3]
  write("b.t2", "-1 0 0\n-1 4 0\n-1 0 3\n");
  r = t2("sec b.t2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "-2 4 3\n0 1 2\n");  // drawn centre (-2, -3/2), on the back
  write("o.t2", "0 0\n1 0\n0 1 1\n");
  r = t2("sec o.t2");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("o.t2:3"), std::string::npos) << r.err;
  write("m.t2", "0 0\n-1 1 0\n");
  r = t2("sec m.t2");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("m.t2:1 and line 2"), std::string::npos) << r.err;
  write("e.t2", "# nothing\n");
  EXPECT_EQ(t2("sec e.t2").status, 2);
  r = t2("sec p.t2 --scene s.t2 --svg s.svg");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(dir_ / "s.t2").find("circle"), std::string::npos);
}

}  // namespace
}  // namespace t2::testing
