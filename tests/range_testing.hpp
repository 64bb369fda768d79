#pragma once
// The inputs and oracles of the range-search tests (test_kdtree.cpp, test_range_tree.cpp):
// points of T² on a small grid (coordinates repeat and fall on rectangle sides) with several
// weights on both sides, duplicates and points of Ω; rectangles on both sides, finite or
// reaching Ω; and the answer by definition, `contains` (bbox.hpp) one point at a time, exactly.
// Front inputs of doubles also have two independent oracles: Boost.Geometry's rtree and
// nanoflann's kd-tree (a radius search around the box, filtered by double comparisons, which
// are exact on doubles).
#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <nanoflann.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "t2/kernel/bbox.hpp"

namespace range_testing {

using t2::ExactIsoRect;
using t2::ExactT1;
using t2::Integer;
using t2::Point;

/// The indices of the points in r, ascending, by `contains`.
inline std::vector<std::size_t> brute(const std::vector<Point>& P, const ExactIsoRect& r) {
  std::vector<std::size_t> in;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (t2::contains(r, t2::to_exact(P[i]))) in.push_back(i);
  return in;
}

/// Points drawn at k/(2|w|)-multiples of a grid: weights ±1, ±2, ±3 (so the drawn position k/3
/// is no double), points of Ω in all eight directions, and duplicates.
inline std::vector<Point> mixed_points(std::mt19937_64& rng, int n) {
  std::uniform_int_distribution<int> c(-4, 4), kind(0, 9), w(1, 3);
  std::vector<Point> P;
  for (int k = 0; k < n; ++k) {
    const int x = c(rng), y = c(rng), t = kind(rng);
    if (t == 0) {
      if (x != 0 || y != 0) P.emplace_back(0, x, y);
    } else {
      const double s = t <= 5 ? w(rng) : -w(rng);
      P.emplace_back(s, x, y);  // drawn at (x/s, y/s): thirds and halves
    }
    if (k % 7 == 3) P.push_back(P.back());  // a duplicate
  }
  return P;
}

/// A rectangle on either side: corner a on the grid of sixths, extents finite (zero included),
/// +∞ or −∞.
inline ExactIsoRect rect(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> c(-30, 30), e(-30, 30), side(0, 1), inf(0, 9);
  const Integer s = side(rng) ? 6 : -6;
  const t2::ExactPoint a(s, c(rng), c(rng));
  auto extent = [&] {
    const int v = inf(rng);
    if (v == 0) return ExactT1(0, 1);
    if (v == 1) return ExactT1(0, -1);
    return ExactT1(6, e(rng));
  };
  return ExactIsoRect(a, extent(), extent());
}

/// Checks a structure S (count, report) against `brute` on mixed inputs, and that enough
/// answers hold back points and points of Ω for the check to mean something.
template <class S>
void check_mixed(unsigned seed, int rounds) {
  std::mt19937_64 rng(seed);
  int back_hits = 0, omega_hits = 0, queries = 0;
  for (int round = 0; round < rounds; ++round) {
    const std::vector<Point> P = mixed_points(rng, 3 + round * 5);
    const S tree(P);
    for (int q = 0; q < 150; ++q) {
      const ExactIsoRect r = rect(rng);
      const std::vector<std::size_t> want = brute(P, r);
      ASSERT_EQ(tree.report(r), want) << t2::to_string(r) << ", round " << round;
      ASSERT_EQ(tree.count(r), want.size()) << t2::to_string(r) << ", round " << round;
      ++queries;
      bool back = false, omega = false;
      for (std::size_t i : want) back |= P[i].w() < 0, omega |= P[i].w() == 0;
      back_hits += back;
      omega_hits += omega;
    }
  }
  EXPECT_EQ(queries, rounds * 150);
  EXPECT_GT(back_hits, queries / 10) << "the rectangles must find back points";
  EXPECT_GT(omega_hits, queries / 20) << "the rectangles must reach points of Ω";
}

/// Front points with double coordinates (w = 1), rounded to a grid of 1/64 so that many lie on
/// the rectangles' sides, and their rectangles (corners of the same grid, exact).
struct FrontCase {
  std::vector<Point> points;
  std::vector<std::array<double, 4>> boxes;  // x0 y0 x1 y1, x0 <= x1, y0 <= y1
};

inline FrontCase front_case(unsigned seed, int n, int queries) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> c(-256, 256), e(0, 96);
  FrontCase f;
  for (int k = 0; k < n; ++k) f.points.push_back(Point::cartesian(c(rng) / 64.0, c(rng) / 64.0));
  for (int q = 0; q < queries; ++q) {
    const double x0 = c(rng) / 64.0, y0 = c(rng) / 64.0;
    f.boxes.push_back({x0, y0, x0 + e(rng) / 64.0, y0 + e(rng) / 64.0});
  }
  return f;
}

/// The rectangle of a box, exactly.
inline ExactIsoRect exact_rect(const std::array<double, 4>& b) {
  return t2::iso_rect(t2::to_exact(Point::cartesian(b[0], b[1])), t2::to_exact(Point::cartesian(b[2], b[3])));
}

/// Boost.Geometry's rtree (R*-tree, bulk loaded): the indices in the closed box, ascending.
class RtreeOracle {
 public:
  using P2 = boost::geometry::model::point<double, 2, boost::geometry::cs::cartesian>;
  using Box = boost::geometry::model::box<P2>;
  using Value = std::pair<P2, std::size_t>;
  explicit RtreeOracle(const std::vector<Point>& P) {
    std::vector<Value> v;
    for (std::size_t i = 0; i < P.size(); ++i) v.emplace_back(P2(P[i].x(), P[i].y()), i);
    tree_ = Tree(v.begin(), v.end());
  }
  std::vector<std::size_t> query(const std::array<double, 4>& b) const {
    std::vector<Value> hits;
    // covered_by: in the closed box, sides included.
    tree_.query(boost::geometry::index::covered_by(Box(P2(b[0], b[1]), P2(b[2], b[3]))), std::back_inserter(hits));
    std::vector<std::size_t> out;
    for (const auto& h : hits) out.push_back(h.second);
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  using Tree = boost::geometry::index::rtree<Value, boost::geometry::index::rstar<16>>;
  Tree tree_;
};

/// nanoflann's kd-tree (L2): the points within the disk around the box's centre through its
/// corners (a little larger: the radius is rounded up), kept when inside the box by double
/// comparisons, ascending.
class NanoflannOracle {
 public:
  explicit NanoflannOracle(const std::vector<Point>& P) : cloud_{P}, index_(2, cloud_) { index_.buildIndex(); }
  std::vector<std::size_t> query(const std::array<double, 4>& b) const {
    const double c[2] = {(b[0] + b[2]) / 2, (b[1] + b[3]) / 2};
    const double dx = b[2] - b[0], dy = b[3] - b[1];
    const double r2 = (dx * dx + dy * dy) / 4 * 1.001 + 1e-9;  // rounded up: a superset
    std::vector<std::pair<unsigned, double>> hits;  // nanoflann 1.4: 32-bit indices
    nanoflann::SearchParams params;
    index_.radiusSearch(c, r2, hits, params);
    std::vector<std::size_t> out;
    for (const auto& [i, d] : hits) {
      const Point& p = cloud_.P[i];
      if (b[0] <= p.x() && p.x() <= b[2] && b[1] <= p.y() && p.y() <= b[3]) out.push_back(i);
    }
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  struct Cloud {
    const std::vector<Point>& P;
    std::size_t kdtree_get_point_count() const { return P.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return d == 0 ? P[i].x() : P[i].y(); }
    template <class B>
    bool kdtree_get_bbox(B&) const {
      return false;
    }
  };
  using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 2>;
  Cloud cloud_;
  Index index_;
};

/// Checks S on front doubles against both oracles and `brute` on a few.
template <class S>
void check_front(unsigned seed, int n, int queries) {
  const FrontCase f = front_case(seed, n, queries);
  const S tree(f.points);
  const RtreeOracle rtree(f.points);
  const NanoflannOracle flann(f.points);
  std::size_t found = 0, on_side = 0;
  for (std::size_t q = 0; q < f.boxes.size(); ++q) {
    const auto& b = f.boxes[q];
    const ExactIsoRect r = exact_rect(b);
    const std::vector<std::size_t> got = tree.report(r);
    ASSERT_EQ(got, rtree.query(b)) << "box " << q;
    ASSERT_EQ(got, flann.query(b)) << "box " << q;
    ASSERT_EQ(tree.count(r), got.size());
    if (q < 50) {
      ASSERT_EQ(got, brute(f.points, r));
    }
    found += got.size();
    for (std::size_t i : got) on_side += f.points[i].x() == b[0] || f.points[i].x() == b[2] ||
                                         f.points[i].y() == b[1] || f.points[i].y() == b[3];
  }
  if (n < 1000) return;  // a few points: the agreement is the test
  EXPECT_GT(found, f.boxes.size()) << "the boxes must hold points";
  EXPECT_GT(on_side, f.boxes.size() / 10) << "points on the boxes' sides must be tested";
}

/// Rectangles whose bounds are no doubles (sixths and thirds) around points drawn at thirds
/// with w = 3 and at the doubles nearest them with w = 1: the exact comparison decides.
template <class S>
void check_near_thirds() {
  const double third = 1.0 / 3;  // below 1/3
  const std::vector<Point> P = {Point(3, 1, 1), Point::cartesian(third, third),
                                Point::cartesian(std::nextafter(third, 1.0), third), Point(-3, -1, -1),
                                Point(6, 2, 2)};
  const t2::ExactPoint a(3, 1, 1);  // (1/3, 1/3)
  // x, y in [1/3, +∞): the w = 3 and w = 6 points and the double above 1/3 (its y is below).
  const ExactIsoRect up(a, ExactT1(0, 1), ExactT1(0, 1));
  // x in (−∞, 1/3], y in [1/3 − 1/6, 1/3]: the thirds, the double below, not the double above.
  const ExactIsoRect down(a, ExactT1(0, -1), ExactT1(6, -1));
  const S tree(P);
  EXPECT_EQ(tree.report(up), (std::vector<std::size_t>{0, 4}));
  EXPECT_EQ(tree.report(down), (std::vector<std::size_t>{0, 1, 4}));
  EXPECT_EQ(tree.report(up), brute(P, up));
  EXPECT_EQ(tree.report(down), brute(P, down));
  const ExactIsoRect back(t2::ExactPoint(-3, -1, -1), ExactT1(0, 1), ExactT1(0, 1));
  EXPECT_EQ(tree.report(back), (std::vector<std::size_t>{3}));
}

}  // namespace range_testing
