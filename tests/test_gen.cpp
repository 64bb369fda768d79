// The input generators (t2/gen): reproducible bytes, and the property each kind claims, checked
// exactly (GMP integers and rationals, the exact predicates).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <set>
#include <tuple>

#include "t2/gen/generate.hpp"
#include "t2/gen/random.hpp"
#include "t2/intersect/intersections.hpp"
#include "t2/kernel/orient.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using gen::Kind;
using testing::q;

gen::Options opts(std::size_t n, std::uint64_t seed = 7) {
  gen::Options o;
  o.n = n;
  o.seed = seed;
  return o;
}

TEST(Gen, NamesRoundTrip) {
  EXPECT_EQ(gen::all_kinds().size(), 24u);
  for (Kind k : gen::all_kinds()) EXPECT_EQ(gen::kind_from_name(gen::name(k)), k);
  EXPECT_THROW(gen::kind_from_name("gaussian"), BadInput);
}

// simple-polygon --untangle: its own reproducible bytes, said in the file's command line, and
// another polygon than space partitioning's on the same points' stream.
TEST(Gen, UntangleIsReproducibleAndNamed) {
  gen::Options o = opts(30);
  o.untangle = true;
  const std::string text = gen::to_text(Kind::simple_polygon, o);
  EXPECT_EQ(text, gen::to_text(Kind::simple_polygon, o));
  EXPECT_EQ(text.rfind("# t2 gen simple-polygon --n 30 --seed 7 --untangle\n", 0), 0u) << text;
  EXPECT_NE(text.substr(text.find('\n')), gen::to_text(Kind::simple_polygon, opts(30)).substr(text.find('\n')));
  gen::Options p = o;
  p.seed = 8;
  EXPECT_NE(text, gen::to_text(Kind::simple_polygon, p));
}

TEST(Gen, SameOptionsSameBytesOtherSeedOtherBytes) {
  for (Kind k : gen::all_kinds()) {
    gen::Options o = opts(50);
    if (k == Kind::segments) o.crossings = 30;
    EXPECT_EQ(gen::to_text(k, o), gen::to_text(k, o)) << gen::name(k);
    gen::Options p = o;
    p.seed = 8;
    EXPECT_NE(gen::to_text(k, o), gen::to_text(k, p)) << gen::name(k);
  }
}

// The bytes themselves: a different standard library or machine must print exactly these.
// (They follow from std::mt19937_64, whose output the C++ standard fixes, and the transforms of
// random.hpp; a change here is a change of every generated file.)
TEST(Gen, KnownBytesOnEveryMachine) {
  EXPECT_EQ(gen::to_text(Kind::uniform, opts(2, 1)),
            "# t2 gen uniform --n 2 --seed 1\n# uniform in the square [-1,1)^2\n"
            "-0.7322467119749347 -0.7271859272676056\n-0.09757019231092379 -0.957951543166546\n");
  gen::Random r(5489);  // the standard's check value: the 10000th output of a default mt19937_64
  std::uint64_t v = 0;
  for (int i = 0; i < 10000; ++i) v = r.bits();
  EXPECT_EQ(v, 9981545732273789042ULL);
}

TEST(Gen, UniformDiskAndPolygonInterior) {
  for (const auto& p : gen::points(Kind::uniform, opts(2000))) {
    EXPECT_TRUE(p.x() >= -1 && p.x() < 1 && p.y() >= -1 && p.y() < 1);
  }
  for (const auto& p : gen::points(Kind::disk, opts(2000))) EXPECT_LT(q(p.x()) * q(p.x()) + q(p.y()) * q(p.y()), 1);
  for (const auto& p : gen::points(Kind::polygon_interior, opts(2000))) EXPECT_FALSE(p.x() >= 0 && p.y() >= 0);
}

TEST(Gen, CircleIsExactlyOnTheUnitCircle) {
  const auto pts = gen::points(Kind::circle, opts(3000));
  int quadrant[4] = {0, 0, 0, 0};
  for (const auto& p : pts) {
    const Integer w(p.w()), x(p.x()), y(p.y());
    EXPECT_EQ(x * x + y * y, w * w) << to_string(p);
    EXPECT_GT(p.w(), 0);
    ++quadrant[(p.x() >= 0 ? 0 : 1) + (p.y() >= 0 ? 0 : 2)];
  }
  for (int c : quadrant) EXPECT_GT(c, 500);  // all around the circle
  gen::Options o = opts(100);
  o.cartesian = true;
  for (const auto& p : gen::points(Kind::circle, o)) {
    EXPECT_EQ(p.w(), 1);
    EXPECT_NEAR(p.x() * p.x() + p.y() * p.y(), 1.0, 1e-15);  // rounded on purpose
  }
}

TEST(Gen, SegmentAndBoundaryAreExactlyCollinear) {
  const auto pts = gen::points(Kind::segment, opts(300));
  const Point a = Point::cartesian(-1, -0.25), b = Point::cartesian(1, 0.75);
  for (const auto& p : pts) {
    EXPECT_EQ(orient(a, b, p), ZERO) << to_string(p);
    EXPECT_TRUE(p.x() >= -1 && p.x() <= 1);
  }
  for (const auto& p : gen::points(Kind::boundary, opts(300))) {
    EXPECT_TRUE(std::abs(p.x()) == 1 || std::abs(p.y()) == 1);
    EXPECT_TRUE(std::abs(p.x()) <= 1 && std::abs(p.y()) <= 1);
  }
}

TEST(Gen, GridAndDuplicates) {
  const auto g = gen::points(Kind::grid, opts(100));
  for (const auto& p : g) {
    EXPECT_EQ(p.x(), std::floor(p.x()));
    EXPECT_TRUE(p.x() >= 0 && p.x() < 10 && p.y() >= 0 && p.y() < 10);
  }
  const auto d = gen::points(Kind::duplicates, opts(400));
  std::vector<Point> distinct;
  bool scaled = false;
  for (const auto& p : d) {
    scaled = scaled || p.w() != 1;
    if (std::none_of(distinct.begin(), distinct.end(), [&](const Point& u) { return u == p; })) distinct.push_back(p);
  }
  EXPECT_LE(distinct.size(), 50u);
  EXPECT_TRUE(scaled);
}

TEST(Gen, BothSidesHasTheShareBehindAndAnOpenHemisphere) {
  for (double back : {0.0, 0.3, 0.5, 1.0}) {
    gen::Options o = opts(1000);
    o.back = back;
    const auto pts = gen::points(Kind::both_sides, o);
    const double c = 1 - 2 * back;
    std::size_t behind = 0;
    for (const auto& p : pts) {
      behind += p.w() < 0;
      EXPECT_GT(q(c) * q(p.w()) - q(p.x()), 0) << to_string(p);  // the hemisphere c·w − x > 0
    }
    EXPECT_EQ(behind, static_cast<std::size_t>(std::llround(back * 1000)));
  }
}

// The circle around the Ω point [0, 1, 0]: w² + y² = x² exactly, x > 0 (one circle of the sphere,
// in the open hemisphere x > 0, so its hull exists), and both sides well represented.
TEST(Gen, CircleBothSidesIsExactlyOnACircleAroundAnOmegaPoint) {
  const auto pts = gen::points(Kind::circle_both_sides, opts(3000));
  ASSERT_EQ(pts.size(), 3000u);
  std::size_t front = 0, back = 0;
  for (const auto& p : pts) {
    EXPECT_EQ(q(p.w()) * q(p.w()) + q(p.y()) * q(p.y()), q(p.x()) * q(p.x())) << to_string(p);
    EXPECT_GT(p.x(), 0) << to_string(p);
    front += p.w() > 0;
    back += p.w() < 0;
  }
  EXPECT_GT(front, 1000u);
  EXPECT_GT(back, 1000u);
}

TEST(Gen, AntipodalPairsAndPointsAtInfinity) {
  // A tenth of the points are antipodes of distinct front points: exactly n/10 antipodal pairs
  // and no two points equal (drawing the antipodes with replacement gave about 28 equal points
  // at n = 5000).
  for (std::size_t n : {200u, 5000u}) {
    auto pts = gen::points(Kind::antipodal, opts(n));
    ASSERT_EQ(pts.size(), n);
    std::size_t pairs = 0, back = 0;
    for (const auto& p : pts) back += p.w() < 0;
    std::vector<Point> front;
    for (const auto& p : pts) if (p.w() > 0) front.push_back(p);
    const auto by_xy = [](const Point& a, const Point& b) { return std::tie(a.x(), a.y()) < std::tie(b.x(), b.y()); };
    std::sort(front.begin(), front.end(), by_xy);
    for (const auto& p : pts)
      if (p.w() < 0) pairs += std::binary_search(front.begin(), front.end(), antipode(p), by_xy);
    std::sort(pts.begin(), pts.end(), [&](const Point& a, const Point& b) {
      return std::tie(a.w(), a.x(), a.y()) < std::tie(b.w(), b.x(), b.y());
    });
    EXPECT_EQ(std::adjacent_find(pts.begin(), pts.end()), pts.end()) << "equal points, n = " << n;
    EXPECT_EQ(back, n / 10) << n;
    EXPECT_EQ(pairs, n / 10) << n;
  }
  const auto inf = gen::points(Kind::infinity, opts(200));
  EXPECT_EQ(std::count_if(inf.begin(), inf.end(), [](const Point& p) { return p.w() == 0; }), 100);
  for (const auto& p : inf) EXPECT_GT(2 * q(p.w()) + q(p.x()), 0);  // the hemisphere 2w + x > 0
}

TEST(Gen, ThreeDimensions) {
  for (const auto& p : gen::points3(Kind::cube, opts(500)))
    for (double c : p) EXPECT_TRUE(c >= -1 && c < 1);
  for (const auto& p : gen::points3(Kind::sphere, opts(500)))
    EXPECT_NEAR(p[0] * p[0] + p[1] * p[1] + p[2] * p[2], 1.0, 1e-15);  // rounded on purpose
}

// Proper crossing of two segments (interiors cross at one point), exactly.
bool crosses(const Segment& s, const Segment& t) {
  const Sign a = orient(s.source(), s.target(), t.source()), b = orient(s.source(), s.target(), t.target());
  const Sign c = orient(t.source(), t.target(), s.source()), d = orient(t.source(), t.target(), s.target());
  return a * b < 0 && c * d < 0;
}

TEST(Gen, PolygonsHaveTheirShape) {
  const Point o = Point::cartesian(0, 0);
  for (Kind k : {Kind::convex_polygon, Kind::star_polygon, Kind::monotone_polygon, Kind::simple_polygon}) {
    const Polygon P = gen::polygon(k, opts(60));
    const std::size_t n = P.size();
    ASSERT_GE(n, 50u) << gen::name(k);
    EXPECT_GT(signed_area(P), 0) << gen::name(k);
    for (std::size_t i = 0; i < n; ++i) {
      const Point &a = P[i], &b = P[(i + 1) % n], &c = P[(i + 2) % n];
      if (k == Kind::convex_polygon) {
        EXPECT_EQ(orient(a, b, c), POSITIVE);
      }
      if (k == Kind::star_polygon) {
        EXPECT_EQ(orient(o, a, b), POSITIVE);
      }
    }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;
        const Segment s(P[i], P[(i + 1) % n]), t(P[j], P[(j + 1) % n]);
        EXPECT_FALSE(intersects(s, t)) << gen::name(k) << " edges " << i << " and " << j;
      }
  }
}

// The side of r from p → q, on exact rational positions (the classic plane test, independent
// of the library's predicates).
Sign turn(const testing::Pos& p, const testing::Pos& q, const testing::Pos& r) {
  return testing::sign_oracle((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
}

// r, collinear with p and q, lies on the closed segment pq.
bool within(const testing::Pos& p, const testing::Pos& q, const testing::Pos& r) {
  for (int k : {0, 1})
    if (r[k] < std::min(p[k], q[k]) || r[k] > std::max(p[k], q[k])) return false;
  return true;
}

// The closed segments ab and cd meet.
bool meet_oracle(const testing::Pos& a, const testing::Pos& b, const testing::Pos& c, const testing::Pos& d) {
  const Sign s1 = turn(a, b, c), s2 = turn(a, b, d), s3 = turn(c, d, a), s4 = turn(c, d, b);
  if (s1 * s2 < 0 && s3 * s4 < 0) return true;
  return (s1 == 0 && within(a, b, c)) || (s2 == 0 && within(a, b, d)) || (s3 == 0 && within(c, d, a)) ||
         (s4 == 0 && within(c, d, b));
}

// Every polygon kind makes simple, counter-clockwise polygons, small n included (star-polygon
// once closed non-simple polygons for n = 4, seed 9: the origin outside its vertices); so does
// simple-polygon --untangle (2-opt).
TEST(Gen, EveryPolygonIsSimple) {
  for (int kind = 0; kind < 5; ++kind)
    for (std::size_t n : {3, 4, 5, 6, 7, 8, 10, 13, 20, 40})
      for (std::uint64_t seed = 1; seed <= (n < 40 ? 30u : 5u); ++seed) {
        const Kind k = std::array{Kind::convex_polygon, Kind::star_polygon, Kind::monotone_polygon,
                                  Kind::simple_polygon, Kind::simple_polygon}[static_cast<std::size_t>(kind)];
        gen::Options o = opts(n, seed);
        o.untangle = kind == 4;
        const Polygon P = gen::polygon(k, o);
        const std::size_t m = P.size();
        const std::string what = fmt::format("{} --n {} --seed {}{}", gen::name(k), n, seed, o.untangle ? " --untangle" : "");
        ASSERT_GE(m, 3u) << what;
        if (k != Kind::simple_polygon || o.untangle) {
          EXPECT_EQ(m, n) << what;  // simple-polygon by space partitioning drops repeats
        }
        std::vector<testing::Pos> V;
        for (const Point& p : P) V.push_back(testing::pos(p));
        Rational area2 = 0;
        for (std::size_t i = 0; i < m; ++i) {
          area2 += V[i][0] * V[(i + 1) % m][1] - V[i][1] * V[(i + 1) % m][0];
          for (std::size_t j = i + 1; j < m; ++j) ASSERT_FALSE(V[i] == V[j]) << what << ": repeated vertex";
        }
        EXPECT_GT(area2, 0) << what << ": not counter-clockwise";
        for (std::size_t i = 0; i < m; ++i) {
          for (std::size_t j = i + 1; j < m; ++j) {
            const auto &a = V[i], &b = V[(i + 1) % m], &c = V[j], &d = V[(j + 1) % m];
            if (j == i + 1 || (i == 0 && j == m - 1)) {  // neighbours u → v → w: only v in common
              const auto &u = j == i + 1 ? a : c, &v = j == i + 1 ? b : a, &w = j == i + 1 ? d : b;
              const bool flat = turn(u, v, w) == ZERO;
              EXPECT_FALSE(flat && (within(u, v, w) || within(v, w, u)))
                  << what << ": edges " << i << " and " << j << " overlap";
              EXPECT_FALSE(m == 3 && flat) << what << ": a flat triangle";
            } else {
              EXPECT_FALSE(meet_oracle(a, b, c, d)) << what << ": edges " << i << " and " << j << " meet";
            }
          }
          }
        EXPECT_TRUE(is_simple(P)) << what;
      }
}

TEST(Gen, SegmentsHaveExactlyTheCrossingsAsked) {
  for (std::size_t want : {0u, 1u, 17u, 100u}) {
    gen::Options o = opts(40);
    o.crossings = want;
    const auto S = gen::segments(o);
    ASSERT_EQ(S.size(), 40u);
    std::size_t got = 0, touching = 0;
    for (std::size_t i = 0; i < S.size(); ++i)
      for (std::size_t j = i + 1; j < S.size(); ++j) {
        got += crosses(S[i], S[j]);
        touching += intersects(S[i], S[j]) && !crosses(S[i], S[j]);
      }
    EXPECT_EQ(got, want);
    EXPECT_EQ(touching, 0u);
  }
  gen::Options o = opts(4);
  o.crossings = 5;
  EXPECT_THROW(gen::segments(o), BadInput);
}

// The connected and degenerate kinds: what each promises, exactly, and the sweep equal to the
// brute force on them.
TEST(Gen, ConnectedAndDegenerateSegmentKinds) {
  const auto edges = gen::segments(Kind::polygon_edges, opts(100));
  ASSERT_EQ(edges.size(), 100u);
  for (std::size_t k = 0; k < 100; ++k) {
    const std::size_t next = k % 16 == 15 ? k - 15 : k + 1;  // round each 16-gon
    if (next < 100) EXPECT_TRUE(edges[k].target() == edges[next].source()) << k;
  }
  const auto grid = gen::segments(Kind::segment_grid, opts(100));
  ASSERT_EQ(grid.size(), 100u);
  std::set<std::array<double, 4>> distinct;
  for (const auto& s : grid) {
    const double dx = s.target().x() - s.source().x(), dy = s.target().y() - s.source().y();
    EXPECT_TRUE((dx == 1 && dy == 0) || (dx == 0 && dy == 1));
    EXPECT_EQ(s.source().x(), std::floor(s.source().x()));
    EXPECT_EQ(s.source().y(), std::floor(s.source().y()));
    distinct.insert({s.source().x(), s.source().y(), s.target().x(), s.target().y()});
  }
  EXPECT_EQ(distinct.size(), 100u);
  const auto star = gen::segments(Kind::segments_through_point, opts(60));
  ASSERT_EQ(star.size(), 60u);
  const Point origin(1, 0, 0);
  for (const auto& s : star) {
    EXPECT_EQ(orient(s.source(), s.target(), origin), ZERO);
    EXPECT_LT(q(s.source().x()) * q(s.target().x()) + q(s.source().y()) * q(s.target().y()), 0);  // between
  }
  const auto at = intersections(star, IntersectAlgorithm::sweep);
  ASSERT_EQ(at.size(), 1u);  // the origin, on all 60
  EXPECT_EQ(at[0].segments.size(), 60u);
  for (const auto* S : {&edges, &grid, &star}) {
    const auto a = intersections(*S, IntersectAlgorithm::sweep), b = intersections(*S, IntersectAlgorithm::brute);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_TRUE(a[k].point == b[k].point);
      EXPECT_EQ(a[k].segments, b[k].segments);
    }
  }
  EXPECT_THROW(gen::segments(Kind::uniform, opts(10)), BadInput);
  for (Kind k : gen::all_kinds())
    EXPECT_EQ(gen::is_segment_kind(k), k == Kind::segments || k == Kind::polygon_edges || k == Kind::segment_grid ||
                                           k == Kind::segments_through_point);
}

}  // namespace
}  // namespace t2
