// t2::delaunay with sites on Ω among proper ones (delaunay_t2.hpp, face_disk.hpp): against the
// O(n⁴) brute force with in_face_disk, the exact certificates, the planar limit (each site on Ω
// replaced by a front point far along its direction: the planar Delaunay triangulation, checked
// against CGAL in test_delaunay, has the same triangles), and Undefined where a side is empty.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "delaunay_t2_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/face_disk.hpp"

namespace t2 {
namespace {

using testing::brute_force;
using testing::expect_brute_force;
using testing::expect_t2_delaunay;
using testing::proper_faces;
using testing::random_sides;
using testing::Tri;
using testing::triangle_set;
using Index = Triangulation::Index;

/// `k` random directions on Ω (in the open half dx > 0 when `half`), appended to `pts`.
void add_omega(std::vector<Point>& pts, std::size_t k, bool half, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 7919);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t j = 0; j < k; ++j) {
    const double dx = u(rng), dy = u(rng);
    pts.push_back(Point::at_infinity(half ? std::abs(dx) + 1e-3 : dx, dy));
  }
}

bool has_side(const std::vector<Point>& pts, int s) {
  return std::any_of(pts.begin(), pts.end(), [&](const Point& p) { return sign_of(p.w()) == s; });
}

// Front, back and Ω: the sites on Ω own arcs of Ω, the rings of faces and the band meet there.
TEST(DelaunayOmega, BothSidesAndOmegaAgainstBruteForce) {
  int cases = 0, with_hull = 0, gaps = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    auto pts = random_sides(3 + seed % 9, 0.2 + 0.6 * double(seed % 5) / 4, seed);
    add_omega(pts, 1 + seed % 5, seed % 3 == 0, seed);
    if (seed % 7 == 0) pts.push_back(antipode(pts.back()));  // a gap of exactly π
    if (!has_side(pts, 1) || !has_side(pts, -1)) continue;
    SCOPED_TRACE(seed);
    expect_brute_force(pts);
    ++cases;
    const Triangulation tr = delaunay(pts);
    with_hull += !tr.hull_edges().empty();
    for (const Tri& t : tr.finite_triangles())  // a face with a front, a back and an Ω vertex
      gaps += sign_of(pts[t[0]].w()) * sign_of(pts[t[1]].w()) * sign_of(pts[t[2]].w()) == 0 &&
              (pts[t[0]].w() > 0 || pts[t[1]].w() > 0 || pts[t[2]].w() > 0) &&
              (pts[t[0]].w() < 0 || pts[t[1]].w() < 0 || pts[t[2]].w() < 0);
  }
  EXPECT_GT(cases, 150);
  EXPECT_GT(with_hull, 5);
  EXPECT_GT(gaps, 20);
}

// One side and Ω in an open half of Ω: all sites in an open hemisphere, a hull with Ω on it.
TEST(DelaunayOmega, OneSideAndOmegaAgainstBruteForce) {
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    auto pts = random_sides(3 + seed % 10, seed % 2 == 0 ? 0.0 : 1.0, seed);
    add_omega(pts, 1 + seed % 6, true, seed);
    SCOPED_TRACE(seed);
    expect_brute_force(pts);
    EXPECT_FALSE(delaunay(pts).hull_edges().empty());
  }
  gen::Options o;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    o.n = 6 + seed % 10;
    o.seed = seed;
    expect_brute_force(gen::points(gen::Kind::infinity, o));
  }
  o.n = 1000;
  expect_t2_delaunay(delaunay(gen::points(gen::Kind::infinity, o)), 100);
}

TEST(DelaunayOmega, LargeMixed) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    auto pts = random_sides(700, 0.4, seed);
    add_omega(pts, 30 * seed, false, seed);
    expect_t2_delaunay(delaunay(pts), 50);
  }
}

// The planar limit: each site on Ω at a common radius t along its direction, in front.
TEST(DelaunayOmega, FrontAndOmegaIsThePlanarLimit) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    auto pts = random_sides(5 + seed % 25, 0.0, seed);
    const std::size_t n = pts.size();
    add_omega(pts, 1 + seed % 7, true, seed);
    std::vector<Point> far(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(n));
    for (std::size_t j = n; j < pts.size(); ++j) {
      const double r = std::hypot(pts[j].x(), pts[j].y());
      far.push_back(Point::cartesian(1e7 * pts[j].x() / r, 1e7 * pts[j].y() / r));
    }
    SCOPED_TRACE(seed);
    const auto t2_faces = triangle_set(delaunay(pts));
    EXPECT_EQ(t2_faces, triangle_set(delaunay(far)));
    EXPECT_TRUE(std::any_of(t2_faces.begin(), t2_faces.end(), [&](const Tri& t) { return t[2] >= n; }));
  }
}

// A side without sites and sites on Ω in no open half of it: Undefined, naming the points.
TEST(DelaunayOmega, EmptySideAroundOmegaIsUndefined) {
  std::vector<Point> pts = {Point::cartesian(0, 0), Point::cartesian(1, 0.25), Point::cartesian(0.125, 1),
                            Point::at_infinity(1, 0), Point::at_infinity(-1, 1), Point::at_infinity(-1, -1)};
  try {
    delaunay(pts);
    ADD_FAILURE() << "no exception";
  } catch (const Undefined& e) {
    EXPECT_NE(std::string(e.what()).find("3, 4 and 5"), std::string::npos) << e.what();
  }
  pts.erase(pts.begin() + 4, pts.end());
  pts.push_back(Point::at_infinity(-2, 0));  // an antipodal pair: a closed half, not an open one
  try {
    delaunay(pts);
    ADD_FAILURE() << "no exception";
  } catch (const Undefined& e) {
    EXPECT_NE(std::string(e.what()).find("3 and 4 (antipodal)"), std::string::npos) << e.what();
  }
  for (Point& p : pts) p = antipode(p);  // behind only: the same
  EXPECT_THROW(delaunay(pts), Undefined);
  pts.push_back(Point::cartesian(0.5, 0.5));  // a front site: defined
  expect_brute_force(pts);
}

// The disk of a face with two vertices on Ω: the limit of the circles through far points.
TEST(DelaunayOmega, TwoOnOmegaDiskIsTheLimit) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int inside = 0;
  for (int k = 0; k < 300; ++k) {
    const Point p = Point::cartesian(u(rng), u(rng)), d = Point::cartesian(u(rng), u(rng));
    double a1 = u(rng) * 3, a2 = a1 + 0.2 + std::abs(u(rng)) * 2.5;  // an arc shorter than π
    const Point z1 = Point::at_infinity(std::cos(a1), std::sin(a1)), z2 = Point::at_infinity(std::cos(a2), std::sin(a2));
    const Sign s = in_face_disk(p, z1, z2, d);
    const double t = 1e6;
    const Point f1 = Point::cartesian(t * z1.x(), t * z1.y()), f2 = Point::cartesian(t * z2.x(), t * z2.y());
    EXPECT_EQ(in_circle(p, f1, f2, d), s) << k;
    inside += s == POSITIVE;
    EXPECT_EQ(in_face_disk(z1, z2, p, d), s);  // rotation invariant
    const double a3 = (a1 + a2) / 2 + u(rng) * 1.5;  // on Ω: inside exactly between z1 and z2
    const Sign on = in_face_disk(p, z1, z2, Point::at_infinity(std::cos(a3), std::sin(a3)));
    EXPECT_EQ(on, std::abs(a3 - (a1 + a2) / 2) < (a2 - a1) / 2 ? POSITIVE : NEGATIVE);
  }
  EXPECT_GT(inside, 30);
  EXPECT_LT(inside, 270);
  EXPECT_THROW(in_face_disk(Point::cartesian(0, 0), Point::at_infinity(1, 0), Point::at_infinity(-1, 0),
                            Point::cartesian(1, 1)),
               Undefined);
}

}  // namespace
}  // namespace t2
