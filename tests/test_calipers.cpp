// Chapter 07 on point sets: Melkman's polygon hull against CGAL::convex_hull_2 and t2::convex_hull;
// antipodal pairs, diameter and width against brute force in exact rationals (the definitions,
// not the calipers); the T² cases of the diameter.
#include <gtest/gtest.h>

#include <set>

#include "hull_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/hull/calipers.hpp"
#include "t2/hull/diameter.hpp"
#include "t2/hull/melkman.hpp"
#include "cgal/cgal_oracle.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using gen::Kind;
using testing::polygon_of;
using testing::at;
using testing::pos;
using testing::q;
using testing::same_cycle;
using testing::sq;
using Q2 = testing::Pos;  // a drawn position, exactly (oracle.hpp)

// CGAL's hull of front points, as indices (each vertex the first equal input point).
std::vector<std::size_t> cgal_hull(const std::vector<Point>& P) { return testing::cgal::hull_2(P); }

TEST(Melkman, RandomPolygonsOfEveryKindLikeCgal) {
  for (Kind k : {Kind::simple_polygon, Kind::star_polygon, Kind::convex_polygon, Kind::monotone_polygon})
    for (std::uint64_t s = 1; s <= 12; ++s)
      for (std::size_t n : {3, 4, 7, 40, 300}) {
        Polygon P = polygon_of(k, n, s);
        ASSERT_TRUE(is_simple(P)) << gen::name(k) << " n " << n << " seed " << s;  // test_gen.cpp
        const auto want = at(P, cgal_hull(P));
        EXPECT_TRUE(same_cycle(at(P, melkman(P)), want)) << gen::name(k) << " n " << n << " seed " << s;
        std::reverse(P.begin(), P.end());  // clockwise input: the same hull, counter-clockwise
        EXPECT_TRUE(same_cycle(at(P, polygon_hull(P)), want)) << gen::name(k) << " reversed, seed " << s;
        std::rotate(P.begin(), P.begin() + static_cast<std::ptrdiff_t>(s % P.size()), P.end());
        EXPECT_TRUE(same_cycle(at(P, melkman(P)), at(P, convex_hull(P)))) << gen::name(k) << " rotated";
      }
}

TEST(Melkman, DegeneratePolygons) {
  // A square with vertices inside its edges and repeated vertices: only the four corners.
  const Polygon sq{Point(1, 0, 0), Point(1, 1, 0), Point(2, 4, 0), Point(1, 2, 0), Point(1, 2, 2), Point(1, 2, 2),
                   Point(1, 1, 2), Point(1, 0, 2), Point(1, 0, 1), Point(1, 0, 0)};
  EXPECT_TRUE(same_cycle(at(sq, melkman(sq)), {Point(1, 0, 0), Point(1, 2, 0), Point(1, 2, 2), Point(1, 0, 2)}));
  // Starting in the middle of a collinear run, and a pocket whose lid holds a later vertex.
  const Polygon run{Point(1, 1, 0), Point(1, 2, 0), Point(1, 2, 2), Point(1, 0, 2), Point(1, 0, 0)};
  EXPECT_TRUE(same_cycle(at(run, melkman(run)), {Point(1, 0, 0), Point(1, 2, 0), Point(1, 2, 2), Point(1, 0, 2)}));
  const Polygon pocket{Point(1, 0, 0), Point(1, 4, 0), Point(1, 4, 4), Point(1, 3, 1), Point(1, 2, 4), Point(1, 0, 4)};
  EXPECT_TRUE(same_cycle(at(pocket, melkman(pocket)), at(pocket, cgal_hull(pocket))));
  // All collinear (not simple, but degenerate input must not crash): the two ends.
  const Polygon line{Point(1, 0, 0), Point(1, 1, 1), Point(1, 3, 3), Point(1, 2, 2)};
  EXPECT_TRUE(same_cycle(at(line, melkman(line)), {Point(1, 0, 0), Point(1, 3, 3)}));
  const Polygon one{Point(1, 1, 1), Point(2, 2, 2), Point(1, 1, 1)};
  EXPECT_EQ(melkman(one).size(), 1u);
}

TEST(Melkman, BackSideAndAcrossOmega) {
  for (std::uint64_t s = 1; s <= 6; ++s) {
    const Polygon P = polygon_of(Kind::simple_polygon, 60, s);
    Polygon back, image;
    for (const auto& p : P) {
      back.push_back(antipode(p));
      // A projective map of determinant 1, exact in doubles (w' = x, x' = -w, y' = y), that
      // sends the part x < 0 behind: it keeps the polygon simple, Δ and so the hull.
      image.push_back(Point(p.x(), -p.w(), p.y()));
    }
    EXPECT_TRUE(same_cycle(at(back, polygon_hull(back)), at(back, convex_hull(back, HullAlgorithm::merge))));
    EXPECT_TRUE(same_cycle(at(image, polygon_hull(image)), at(image, convex_hull(image, HullAlgorithm::merge))));
    EXPECT_TRUE(same_cycle(at(image, polygon_hull(image)), at(image, cgal_hull(P)))) << "seed " << s;
  }
  const Polygon none{Point(1, 0, 0), Point(1, 1, 0), Point(-1, 0, 0)};
  EXPECT_THROW(polygon_hull(none), NoHull);
}

// Brute force: a, b (vertices of the convex polygon H, as rationals) are antipodal when two
// distinct parallel lines through them hold H; it suffices to try the directions of the edges at
// a and at b (the ends of the arcs of outer normals, one of which is in their intersection).
bool brute_antipodal(const std::vector<Q2>& H, std::size_t a, std::size_t b) {
  const std::size_t h = H.size();
  const auto sub = [](const Q2& u, const Q2& v) { return Q2{Rational(u[0] - v[0]), Rational(u[1] - v[1])}; };
  const auto cross = [](const Q2& u, const Q2& v) { return sgn(u[0] * v[1] - u[1] * v[0]); };
  for (std::size_t e : {(a + h - 1) % h, a, (b + h - 1) % h, b}) {
    const Q2 d = sub(H[(e + 1) % h], H[e]);
    const int s = cross(d, sub(H[b], H[a]));
    if (s == 0) continue;  // one line, not two
    bool holds = true;
    for (const auto& v : H) holds = holds && cross(d, sub(v, H[a])) * s >= 0 && cross(d, sub(v, H[b])) * s <= 0;
    if (holds) return true;
  }
  return false;
}

std::vector<Point> points_of(Kind k, std::size_t n, std::uint64_t seed) {
  gen::Options o;
  o.n = n;
  o.seed = seed;
  return gen::points(k, o);
}

TEST(Calipers, AntipodalPairsDiameterAndWidthAgainstBruteForce) {
  std::vector<std::vector<Point>> inputs;
  for (Kind k : {Kind::uniform, Kind::disk, Kind::circle, Kind::grid, Kind::duplicates, Kind::boundary})
    for (std::uint64_t s = 1; s <= 4; ++s) inputs.push_back(points_of(k, 9 + 9 * s, s));
  inputs.push_back({Point(1, 0, 0), Point(1, 2, 0), Point(1, 2, 1), Point(1, 0, 1)});  // rectangle
  inputs.push_back({Point(1, 0, 0), Point(1, 2, 0), Point(1, 3, 1), Point(1, 2, 2), Point(1, 0, 2), Point(1, -1, 1)});
  for (const auto& P0 : inputs)
    for (bool back : {false, true}) {
      std::vector<Point> P = P0;
      if (back)
        for (auto& p : P) p = antipode(p);
      const auto H = convex_hull(P);
      if (H.size() < 3) continue;  // two distinct points: SmallAndDegenerateSets
      std::vector<Q2> R;  // the hull as drawn, counter-clockwise
      for (std::size_t i : cgal_hull(P0)) R.push_back(pos(P0[i]));
      std::set<std::pair<Q2, Q2>> want, got;
      for (std::size_t a = 0; a < R.size(); ++a)
        for (std::size_t b = 0; b < R.size(); ++b)
          if (a != b && brute_antipodal(R, a, b)) want.insert({R[a], R[b]});
      for (const auto& [a, b] : antipodal_pairs(P, H)) got.insert({pos(P[a]), pos(P[b])}), got.insert({pos(P[b]), pos(P[a])});
      EXPECT_EQ(got, want) << P.size() << " points, back " << back;
      EXPECT_LE(got.size(), 3 * R.size());  // at most 3h/2 unordered pairs
      Rational far = 0;  // the diameter: the largest distance of all pairs
      for (const auto& a : P)
        for (const auto& b : P) far = std::max(far, sq(pos(a), pos(b)));
      const auto d = diameter(P);
      ASSERT_TRUE(d.has_value());
      EXPECT_EQ(sq(pos(P[d->first]), pos(P[d->second])), far);
      Rational narrow = -1;  // the width: over hull edges, the largest distance to the edge's line
      for (std::size_t e = 0; e < R.size(); ++e) {
        const Q2 &u = R[e], &v = R[(e + 1) % R.size()];
        Rational worst = 0;
        for (const auto& p : P) {
          const Q2 c = pos(p);
          const Rational t = (v[0] - u[0]) * (c[1] - u[1]) - (v[1] - u[1]) * (c[0] - u[0]);
          worst = std::max(worst, Rational(t * t / sq(u, v)));
        }
        if (narrow < 0 || worst < narrow) narrow = worst;
      }
      const auto w = width(P);
      ASSERT_TRUE(w.has_value());
      const Q2 u = pos(P[w->from]), v = pos(P[w->to]), c = pos(P[w->vertex]);
      const Rational t = (v[0] - u[0]) * (c[1] - u[1]) - (v[1] - u[1]) * (c[0] - u[0]);
      EXPECT_EQ(t * t / sq(u, v), narrow);
    }
}

TEST(Calipers, SmallAndDegenerateSets) {
  EXPECT_FALSE(diameter(std::vector<Point>{}).has_value());
  const std::vector<Point> one{Point(1, 1, 1), Point(2, 2, 2)};
  EXPECT_EQ(diameter(one)->first, diameter(one)->second);
  EXPECT_FALSE(width(one).has_value());
  const std::vector<Point> seg{Point(1, 0, 0), Point(1, 1, 1), Point(1, 3, 3), Point(1, 2, 2)};
  const auto d = diameter(seg);
  EXPECT_EQ(std::minmax(d->first, d->second), std::minmax(std::size_t{0}, std::size_t{2}));
  EXPECT_FALSE(width(seg).has_value());  // collinear: width 0
  const std::vector<std::size_t> two{0, 2};
  EXPECT_EQ(antipodal_pairs(seg, two).size(), 1u);
  EXPECT_THROW(width(std::vector<Point>{Point(1, 0, 0), Point(-1, 1, 0), Point(1, 0, 1)}), BadInput);
}

TEST(Calipers, DiameterInT2) {
  // Front and back: the farthest pair is the front-back pair nearest as drawn (beyond infinity).
  const std::vector<Point> mixed{Point(1, 0, 0), Point(1, 10, 0), Point(-1, -3, 0), Point(-1, -9, 0)};
  auto d = diameter(mixed);  // drawn: 0, 10 in front; 3, 9 behind: nearest front-back is 10 and 9
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(std::minmax(d->first, d->second), std::minmax(std::size_t{1}, std::size_t{3}));
  const std::vector<Point> anti{Point(1, 0, 0), Point(1, 5, 5), Point(-1, -5, -5), Point(-1, -1, 0)};
  d = diameter(anti);  // a point and its antipode: the farthest of all
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(std::minmax(d->first, d->second), std::minmax(std::size_t{1}, std::size_t{2}));
  // A point of Omega is +infinity from a proper point; two different ones leave no answer.
  const std::vector<Point> inf{Point(1, 0, 0), Point(1, 5, 5), Point(0, 1, 0), Point(0, 2, 0)};
  d = diameter(inf);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(inf[d->second].w(), 0.0);
  EXPECT_THROW(diameter(std::vector<Point>{Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)}), Undefined);
  // Brute force in rationals for random front-back sets: min over front-back of |A - B|.
  for (std::uint64_t s = 1; s <= 5; ++s) {
    gen::Options o;
    o.n = 40;
    o.seed = s;
    o.back = 0.4;
    const auto P = gen::points(Kind::both_sides, o);
    Rational best = -1;
    for (const auto& a : P)
      for (const auto& b : P)
        if (a.w() > 0 && b.w() < 0 && (best < 0 || sq(pos(a), pos(b)) < best)) best = sq(pos(a), pos(b));
    const auto e = diameter(P);
    EXPECT_EQ(sq(pos(P[e->first]), pos(P[e->second])), best);
    EXPECT_LT(P[e->first].w() * P[e->second].w(), 0.0);
  }
}

}  // namespace
}  // namespace t2
