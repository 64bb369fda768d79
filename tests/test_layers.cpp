// Convex layers, both ways of seed 003, against repeated CGAL::convex_hull_2 (front input) and
// against repeated t2::convex_hull by the merge (T² input).
#include <gtest/gtest.h>

#include "hull_testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/hull/layers.hpp"
#include "cgal/cgal_oracle.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using gen::Kind;
using testing::at;
using testing::same_cycle;

// The layers by their definition (CGAL's hull, then every point equal to one of its vertices
// removed, again and again), as points of P.
std::vector<std::vector<Point>> cgal_layers(const std::vector<Point>& P) {
  std::vector<std::vector<Point>> layers;
  for (const auto& layer : testing::cgal::layers_2(P)) layers.push_back(at(P, layer));
  return layers;
}

void expect_layers(const std::vector<Point>& P, const std::vector<std::vector<Point>>& want, const std::string& what) {
  for (LayersMethod m : {LayersMethod::jarvis, LayersMethod::graham}) {
    const auto got = convex_layers(P, m);
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t j = 0; j < want.size(); ++j)
      EXPECT_TRUE(same_cycle(at(P, got[j]), want[j])) << what << " layer " << j << ": " << testing::text(at(P, got[j]))
                                                      << "\nwant " << testing::text(want[j]);
  }
}

TEST(Layers, FrontInputLikeRepeatedCgalHulls) {
  for (Kind k : {Kind::uniform, Kind::disk, Kind::circle, Kind::grid, Kind::duplicates, Kind::segment, Kind::boundary,
                 Kind::kuzmin})
    for (std::uint64_t s = 1; s <= 4; ++s) {
      gen::Options o;
      o.n = 60 + 40 * s;
      o.seed = s;
      const auto P = gen::points(k, o);
      expect_layers(P, cgal_layers(P), std::string(gen::name(k)) + " seed " + std::to_string(s));
    }
}

TEST(Layers, SmallCases) {
  EXPECT_TRUE(convex_layers(std::vector<Point>{}).empty());
  // A square around a triangle around a point, a point inside an outer edge (it goes one deeper),
  // and a repeated corner (removed with its corner).
  const std::vector<Point> P{Point(1, 0, 0), Point(1, 6, 0), Point(1, 6, 6), Point(1, 0, 6), Point(1, 3, 0),
                             Point(1, 2, 2), Point(1, 4, 2), Point(1, 3, 4), Point(1, 3, 3), Point(2, 12, 12)};
  const auto L = convex_layers(P);
  ASSERT_EQ(L.size(), 3u);
  EXPECT_EQ(L[0].size(), 4u);
  EXPECT_TRUE(same_cycle(at(P, L[1]), {Point(1, 3, 0), Point(1, 4, 2), Point(1, 3, 4), Point(1, 2, 2)}));
  EXPECT_EQ(at(P, L[2]), std::vector<Point>{Point(1, 3, 3)});
}

TEST(Layers, T2InputLikeRepeatedMergeHulls) {
  for (std::uint64_t s = 1; s <= 5; ++s) {
    gen::Options o;
    o.n = 80;
    o.seed = s;
    for (Kind k : {Kind::both_sides, Kind::infinity}) {
      const auto P = gen::points(k, o);
      std::vector<std::vector<Point>> want;
      std::vector<Point> left = P;
      while (!left.empty()) {
        const auto layer = at(left, convex_hull(left, HullAlgorithm::merge));
        std::vector<Point> rest;
        for (const auto& p : left)
          if (std::none_of(layer.begin(), layer.end(), [&](const Point& v) { return v == p; })) rest.push_back(p);
        want.push_back(layer);
        left = rest;
      }
      expect_layers(P, want, std::string(gen::name(k)) + " seed " + std::to_string(s));
    }
    o.n = 30;
    EXPECT_THROW(convex_layers(gen::points(Kind::antipodal, o)), NoHull);
  }
}

}  // namespace
}  // namespace t2
