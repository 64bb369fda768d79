// t2::convex_hull on input all over T²: projective images of front sets (their hulls are the
// images of the front hulls, which CGAL computes), exact brute force for small sets, hull
// existence against an exact brute-force hemisphere test, and the points a NoHull names.
#include <gtest/gtest.h>

#include <random>

#include "cgal/cgal_oracle.hpp"
#include "hull_testing.hpp"
#include "t2/gen/generate.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::all_algorithms;
using testing::at;
using testing::same_cycle;

const int kScale = testing::scale();

// An integer 3×3 matrix of positive determinant, acting on [w, x, y].
struct Map {
  long m[3][3];
  Point operator()(const Point& p) const {
    const double v[3] = {p.w(), p.x(), p.y()};
    double r[3];
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];  // exact: small integers
    return Point(r[0], r[1], r[2]);
  }
  long det() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
};

Map random_map(std::mt19937_64& rng) {
  for (;;) {
    Map M;
    for (auto& row : M.m)
      for (long& e : row) e = static_cast<long>(rng() % 11) - 5;
    if (M.det() > 0) return M;
  }
}

// Small integer front points (exact images under small integer maps).
std::vector<Point> integer_points(std::mt19937_64& rng, std::size_t n, long range) {
  std::vector<Point> P;
  for (std::size_t i = 0; i < n; ++i)
    P.push_back(Point::cartesian(static_cast<double>(static_cast<long>(rng() % (2 * range + 1)) - range),
                                 static_cast<double>(static_cast<long>(rng() % (2 * range + 1)) - range)));
  return P;
}

void expect_image_hull(const std::vector<Point>& front, const Map& M, const std::string& what) {
  std::vector<Point> image;
  for (const auto& p : front) image.push_back(M(p));
  const auto want = at(image, testing::cgal::hull_2(front));
  for (HullAlgorithm a : all_algorithms()) {
    const auto got = at(image, convex_hull(image, a));
    EXPECT_TRUE(same_cycle(got, want)) << what << ", " << name(a) << "\ngot  " << testing::text(got)
                                       << "\nwant " << testing::text(want);
  }
}

TEST(HullT2, ProjectiveImagesOfFrontSets) {
  std::mt19937_64 rng(11);
  int both = 0;
  for (int t = 0; t < 60 * kScale; ++t) {
    const Map M = random_map(rng);
    const auto front = integer_points(rng, 5 + rng() % 200, t % 3 == 0 ? 3 : 30);  // range 3: many collinear
    expect_image_hull(front, M, "trial " + std::to_string(t));
    std::vector<Point> image;
    for (const auto& p : front) image.push_back(M(p));
    const bool back = std::any_of(image.begin(), image.end(), [](const Point& p) { return p.w() < 0; });
    const bool fwd = std::any_of(image.begin(), image.end(), [](const Point& p) { return p.w() > 0; });
    both += back && fwd;
  }
  EXPECT_GT(both, 10 * kScale);  // many trials put the hull across Ω
}

TEST(HullT2, ProjectiveImagesOfCircleAndGrid) {
  std::mt19937_64 rng(12);
  for (int t = 0; t < 6 * kScale; ++t) {
    gen::Options o;
    o.n = 300;
    o.seed = static_cast<std::uint64_t>(t + 1);
    // Pythagorean points [c, a, b] (c < 2²⁵) under entries ≤ 5: coordinates < 2⁵³, exact.
    expect_image_hull(gen::points(gen::Kind::circle, o), random_map(rng), "circle " + std::to_string(t));
    expect_image_hull(gen::points(gen::Kind::grid, o), random_map(rng), "grid " + std::to_string(t));
    expect_image_hull(gen::points(gen::Kind::duplicates, o), random_map(rng), "duplicates " + std::to_string(t));
  }
}

// Random small sets with tiny integer coordinates on every side of T²: degenerate on purpose.
std::vector<Point> small_t2_set(std::mt19937_64& rng, std::size_t n, long r) {
  std::vector<Point> P;
  while (P.size() < n) {
    const long w = static_cast<long>(rng() % (2 * r + 1)) - r, x = static_cast<long>(rng() % (2 * r + 1)) - r,
               y = static_cast<long>(rng() % (2 * r + 1)) - r;
    if (w != 0 || x != 0 || y != 0) P.emplace_back(w, x, y);
  }
  return P;
}

TEST(HullT2, ExistenceAndVerticesAgainstBruteForce) {
  std::mt19937_64 rng(13);
  int with = 0, without = 0;
  for (int t = 0; t < 1500 * kScale; ++t) {
    const std::size_t n = 1 + rng() % 9;
    auto P = small_t2_set(rng, n, t % 2 ? 1 : 2);
    if (t % 3 == 0)  // keep half of T²: sets with a hull are common then
      for (auto& p : P)
        if (p.w() < 0 || (p.w() == 0 && p.x() < 0)) p = antipode(p);
    const bool none = testing::brute_no_hull(P);
    EXPECT_EQ(has_hull(std::span<const Point>(P)), !none) << testing::text(P);
    if (none) {
      ++without;
      for (HullAlgorithm a : all_algorithms()) {
        try {
          convex_hull(P, a);
          ADD_FAILURE() << name(a) << " found a hull of " << testing::text(P);
        } catch (const NoHull& e) {
          // The points it names have no hull by themselves.
          EXPECT_TRUE(testing::brute_no_hull(at(P, e.witnesses()))) << e.what() << " in " << testing::text(P);
          EXPECT_LE(e.witnesses().size(), 4u);
        }
      }
    } else {
      ++with;
      const auto want = testing::brute_hull(P);
      for (HullAlgorithm a : all_algorithms()) {
        const auto got = at(P, convex_hull(P, a));
        EXPECT_TRUE(same_cycle(got, want)) << name(a) << " on " << testing::text(P) << "\ngot  " << testing::text(got)
                                           << "\nwant " << testing::text(want);
      }
    }
  }
  EXPECT_GT(with, 300 * kScale);
  EXPECT_GT(without, 300 * kScale);
}

TEST(HullT2, GeneratedT2Kinds) {
  for (auto k : {gen::Kind::both_sides, gen::Kind::infinity}) {
    gen::Options o;
    o.n = 400;
    const auto P = gen::points(k, o);
    const auto ref = at(P, convex_hull(P, HullAlgorithm::merge));
    EXPECT_GE(ref.size(), 3u);
    for (HullAlgorithm a : all_algorithms()) EXPECT_TRUE(same_cycle(at(P, convex_hull(P, a)), ref)) << name(a);
  }
  gen::Options o;
  o.n = 100;
  const auto A = gen::points(gen::Kind::antipodal, o);
  EXPECT_THROW(convex_hull(A), Undefined);
}

TEST(HullT2, MessagesNameThePoints) {
  const std::vector<Point> pair{Point::cartesian(0, 0), Point::cartesian(1, 0), Point(-1, 0, 0)};
  try {
    convex_hull(pair);
    FAIL();
  } catch (const Undefined& e) {
    EXPECT_NE(std::string(e.what()).find("p0 and p2 are antipodal"), std::string::npos) << e.what();
  }
  // Three points of Ω spread around it: only a closed hemisphere holds them.
  const std::vector<Point> omega{Point(0, 1, 0), Point(0, -1, 1), Point(0, -1, -1)};
  EXPECT_THROW(convex_hull(omega), NoHull);
  // The antipode of a back point inside a front triangle.
  const std::vector<Point> four{Point::cartesian(-2, -1), Point::cartesian(2, -1), Point::cartesian(0, 2), Point(-1, 0, 0)};
  try {
    convex_hull(four);
    FAIL();
  } catch (const NoHull& e) {
    EXPECT_EQ(e.witnesses().size(), 4u) << e.what();
  }
}

}  // namespace
}  // namespace t2
