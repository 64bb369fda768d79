// nearest_vertex on the T² Delaunay (triangulation_query.cpp) against brute force: every site
// compared with the answer by the exact compare_distance of T² (distance.hpp). Inputs on both
// sides, with a hull, with sites on Ω, with antipodal pairs and with the sites of one side
// collinear; queries in front, behind and on Ω, and at the sites.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/error.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/triangulation.hpp"
#include "t2_query_inputs.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using Index = Triangulation::Index;

std::vector<Point> points(std::size_t n, const std::vector<int>& ws, int side, unsigned seed) {
  return testing::side_points(n, ws, side, seed);
}

/// The sites (vertices) of tr.
std::vector<Index> sites(const Triangulation& tr) {
  std::vector<Index> s;
  for (Index v = 0; v < tr.points().size(); ++v)
    if (tr.face_of(v) != Triangulation::none) s.push_back(v);
  return s;
}

/// Brute force: the answer v is a site and no site is strictly nearer to q. For q on Ω a front
/// and a back site are not comparable (compare_distance throws): then the answer must be a site
/// on Ω at most as far as every site, and where no such site exists while both sides hold sites,
/// nearest_vertex must throw Undefined.
void check_nearest(const Triangulation& tr, const Point& q, Index hint) {
  SCOPED_TRACE(to_string(q));
  const std::vector<Index> all = sites(tr);
  bool front = false, back = false, omega_wins = false;
  for (Index s : all) front = front || tr.point(s).w() > 0, back = back || tr.point(s).w() < 0;
  if (q.w() == 0)
    for (Index z : all) {
      if (tr.point(z).w() != 0) continue;
      bool wins = true;
      for (Index s : all) wins = wins && compare_distance(tr.point(s), tr.point(z), q) != NEGATIVE;
      omega_wins = omega_wins || wins;
    }
  if (q.w() == 0 && front && back && !omega_wins) {
    EXPECT_THROW(tr.nearest_vertex(q, hint), Undefined);
    return;
  }
  const Index v = tr.nearest_vertex(q, hint);
  ASSERT_NE(v, Triangulation::infinite);
  ASSERT_NE(tr.face_of(v), Triangulation::none) << "not a vertex";
  if (q.w() == 0 && front && back) {
    ASSERT_EQ(tr.point(v).w(), 0) << "a proper site where a site on Omega is nearest";
  }
  for (Index s : all) {
    if (q.w() == 0 && tr.point(s).w() != 0 && tr.point(v).w() != 0 && (tr.point(s).w() > 0) != (tr.point(v).w() > 0))
      continue;  // not comparable (and not needed: v is one side's only kind here)
    EXPECT_NE(compare_distance(tr.point(s), tr.point(v), q), NEGATIVE) << "site " << s << " is nearer than " << v;
  }
}

/// Queries: random points of T² (front, back, Ω) on a grid twice finer, every site and its antipode.
std::vector<Point> queries(const Triangulation& tr, int side, unsigned seed) {
  std::vector<Point> q = points(250, {2, -2, 0}, 3 * side, seed + 1000);
  for (Index v : sites(tr)) {
    q.push_back(tr.point(v));
    q.push_back(antipode(tr.point(v)));
  }
  return q;
}

void check_input(const std::vector<Point>& pts, int side, unsigned seed) {
  const Triangulation tr = delaunay(pts);
  ASSERT_EQ(tr.dimension(), 2);
  ASSERT_EQ(tr.validate(), "");
  std::mt19937 rng(seed);
  for (const Point& q : queries(tr, side, seed)) check_nearest(tr, q, static_cast<Index>(rng() % tr.size()));
}

TEST(NearestT2, BothSides) {
  for (int seed = 1; seed <= 6 * testing::scale(); ++seed) {
    SCOPED_TRACE(seed);
    const int side = seed % 3 == 0 ? 3 : seed % 3 == 1 ? 20 : 1000;
    check_input(points(60 + 10 * seed, {1, -1}, side, seed), side, seed);
  }
}

TEST(NearestT2, WithAHull) {
  for (int seed = 1; seed <= 6 * testing::scale(); ++seed) {
    SCOPED_TRACE(seed);
    const int side = seed % 2 ? 4 : 1000;
    std::vector<Point> p = points(60, {1}, side, 20 + seed);
    check_input(p, side, seed);  // front only: back and Ω queries are answered by the scan
    for (int k = 0; k < 5; ++k) p.emplace_back(-1, 3.37 * side + 1.13 * k, 0.29 * side + 2.71 * k);
    check_input(p, side, seed);  // a few back sites, still a hull
  }
}

TEST(NearestT2, OmegaSites) {
  for (int seed = 1; seed <= 8 * testing::scale(); ++seed) {
    SCOPED_TRACE(seed);
    std::vector<Point> p = points(60, seed % 2 ? std::vector<int>{1, -1, 0} : std::vector<int>{1, 0}, 6, 50 + seed);
    try {
      (void)delaunay(p);
    } catch (const Undefined&) {  // Ω sites in no open half of Ω around an empty side
      continue;
    }
    check_input(p, 6, seed);
  }
}

TEST(NearestT2, AntipodalPairsAndCollinearSides) {
  for (int seed = 1; seed <= 4 * testing::scale(); ++seed) {
    SCOPED_TRACE(seed);
    std::vector<Point> p = points(40, {1, -1}, 5, 70 + seed);
    for (int k = 0; k < 4; ++k) p.push_back(antipode(p[static_cast<std::size_t>(k)]));
    check_input(p, 5, seed);
    // front sites on one line (their planar triangulation is a path), back sites around
    std::vector<Point> c;
    for (int k = 0; k < 8; ++k) c.push_back(Point::cartesian(k - 3.5, 0.5 * k - 1.25));
    for (const Point& b : points(20, {-1}, 6, 90 + seed)) c.push_back(b);
    check_input(c, 6, seed);
  }
}

}  // namespace
}  // namespace t2
