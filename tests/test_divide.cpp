// t2::delaunay_divide (Guibas and Stolfi's divide and conquer on the quad-edge): the exact
// certificates of delaunay_certificates.hpp, CGAL's triangles on general and degenerate front
// input (cgal_delaunay.hpp), and the same triangle set and duplicates as the incremental
// algorithm and Lawson's flips on uniform, grid, cocircular, collinear and duplicate input.
#include <gtest/gtest.h>

#include <random>

#include "cgal/cgal_delaunay.hpp"
#include "delaunay_certificates.hpp"
#include "delaunay_inputs.hpp"
#include "t2/triangulation/divide.hpp"
#include "t2/triangulation/lawson.hpp"

namespace t2 {
namespace {

using testing::expect_delaunay;
using testing::scale;
using testing::triangle_set;

// Divide and conquer passes the certificates and gives the incremental algorithm's and
// Lawson's triangles and duplicates.
void expect_three_agree(const std::vector<Point>& pts) {
  const Triangulation d = delaunay_divide(pts);
  expect_delaunay(d, pts.size() <= 3000);
  const Triangulation inc = delaunay(pts), flip = delaunay_by_flips(pts);
  EXPECT_EQ(d.dimension(), inc.dimension());
  EXPECT_TRUE(triangle_set(d) == triangle_set(inc)) << "divide and incremental differ";
  EXPECT_TRUE(triangle_set(d) == triangle_set(flip)) << "divide and flip differ";
  EXPECT_EQ(d.hull_edges(), inc.hull_edges());
  EXPECT_EQ(d.duplicates(), inc.duplicates());
}

TEST(Divide, UniformEqualsCgal) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const auto pts = testing::gen_points(gen::Kind::uniform, 3000 * scale(), seed);
    const Triangulation d = delaunay_divide(pts);
    expect_delaunay(d, false);
    testing::expect_cgal_triangles(d, pts);
  }
}

TEST(Divide, SmallSetsEqualCgal) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const auto pts = testing::gen_points(gen::Kind::uniform, 2 + seed % 20, seed);
    const Triangulation d = delaunay_divide(pts);
    expect_delaunay(d);
    testing::expect_cgal_triangles(d, pts);
  }
}

TEST(Divide, ThreeAlgorithmsAgreeOnUniformAndClustered) {
  expect_three_agree(testing::gen_points(gen::Kind::uniform, 3000 * scale(), 5));
  expect_three_agree(testing::gen_points(gen::Kind::normal, 2000 * scale(), 6, 32));
  expect_three_agree(testing::gen_points(gen::Kind::kuzmin, 2000 * scale(), 7));
}

// Cocircular: every square of a grid, 324 integer points on one circle, exact [c, a, b] points
// on the unit circle, Kettner et al.'s classroom example; CGAL agrees too.
TEST(Divide, ThreeAlgorithmsAgreeOnCocircular) {
  for (std::size_t n : {4, 9, 10, 100, 900, 2500}) {
    const auto pts = testing::grid_points(n, n);
    expect_three_agree(pts);
    testing::expect_cgal_triangles(delaunay_divide(pts), pts);
  }
  for (std::size_t inner : {0, 200}) {
    const auto pts = testing::lattice_circle_points(inner, inner + 1);
    expect_three_agree(pts);
    testing::expect_cgal_triangles(delaunay_divide(pts), pts);
  }
  gen::Options o;
  o.n = 300;
  o.seed = 3;
  expect_three_agree(gen::points(gen::Kind::circle, o));
  expect_three_agree(testing::classroom_points(8));
}

// Collinear: all points on a line (no triangle), a line plus one point (a fan), hull edges with
// many collinear points, vertical lines (equal x: the sort's tie on y).
TEST(Divide, ThreeAlgorithmsAgreeOnCollinear) {
  std::vector<Point> line;
  for (int k = 0; k < 50; ++k) line.push_back(Point::cartesian(k % 7 * 3.0 + 1, k % 7 * 6.0 - 2));
  expect_three_agree(line);
  EXPECT_EQ(delaunay_divide(line).dimension(), 1);
  line.push_back(Point::cartesian(0, 5));
  expect_three_agree(line);
  std::vector<Point> frame;
  for (int k = -20; k <= 20; ++k) frame.push_back(Point::cartesian(k, 0));
  for (int k = -20; k <= 20; ++k) frame.push_back(Point::cartesian(k, 20));
  for (int k = 1; k < 20; ++k) frame.push_back(Point::cartesian(-20, k));
  for (int k = 1; k < 20; ++k) frame.push_back(Point::cartesian(0, k));
  expect_three_agree(frame);
  std::vector<Point> columns;  // three vertical lines
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 30; ++y) columns.push_back(Point::cartesian(x * 5, y * y));
  expect_three_agree(columns);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    expect_three_agree(testing::gen_points(gen::Kind::boundary, 400, seed));
    expect_three_agree(testing::gen_points(gen::Kind::segment, 100, seed));
  }
}

// Duplicates, with scaled coordinates (w ≠ 1) among them.
TEST(Divide, ThreeAlgorithmsAgreeOnDuplicates) {
  auto pts = testing::gen_points(gen::Kind::uniform, 500, 7);
  std::mt19937_64 rng(8);
  for (std::size_t k = 0; k < 300; ++k) pts.push_back(pts[rng() % pts.size()]);
  pts.push_back(Point(2, 2 * pts[0].x(), 2 * pts[0].y()));
  expect_three_agree(pts);
  EXPECT_EQ(delaunay_divide(pts).duplicates().size(), 301u);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    expect_three_agree(testing::gen_points(gen::Kind::duplicates, 800, seed));
    expect_three_agree(testing::gen_points(gen::Kind::grid, 2000, seed));
  }
}

TEST(Divide, DegenerateSizesAndBackPoints) {
  EXPECT_EQ(delaunay_divide(std::vector<Point>{}).dimension(), -1);
  const Triangulation one = delaunay_divide(std::vector<Point>{Point::cartesian(1, 2), Point(3, 3, 6)});
  EXPECT_EQ(one.dimension(), 0);
  EXPECT_EQ(one.duplicates().size(), 1u);
  const std::vector<Point> tri = {Point::cartesian(0, 0), Point::cartesian(0, 1), Point::cartesian(1, 0)};
  EXPECT_EQ(triangle_set(delaunay_divide(tri)), (std::vector<testing::Tri>{{0, 2, 1}}));
  const std::vector<Point> back = {Point::cartesian(0, 0), Point(-1, 0, 1), Point::cartesian(1, 0)};
  EXPECT_THROW(delaunay_divide(back), Undefined);
}

}  // namespace
}  // namespace t2
