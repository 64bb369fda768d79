// The spanning tree, nearest neighbours and closest pair of front sites against peers: Boost
// Graph's Kruskal on CGAL's Delaunay edges (an exact triangulation, another union–find and
// another sort), and, for the neighbours, CGAL's triangulation read as a graph. Integer
// coordinates keep the squared lengths exact in doubles, so Boost's weights tie where ours do;
// the trees are compared by their sorted exact weights (every minimum tree has the same ones).
// nanoflann (issue 25) is not installed on this machine (`dpkg -l libnanoflann-dev`): left out.
#include <gtest/gtest.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/kruskal_min_spanning_tree.hpp>
#include <random>
#include <set>

#include "cgal/cgal_oracle.hpp"
#include "proximity_oracle.hpp"
#include "t2/proximity/closest_pair.hpp"
#include "t2/proximity/nearest_neighbors.hpp"
#include "t2/proximity/spanning_tree.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

using testing::Edge;

TEST(ProximityCgal, KruskalOnCgalDelaunayEdges) {
  for (int seed = 0; seed < 20 * testing::scale(); ++seed) {
    std::mt19937 rng(seed);
    const int range = seed % 2 ? 30 : 3000;  // many ties, then few
    std::uniform_int_distribution<int> c(-range, range);
    std::vector<Point> P;
    const int n = 50 + 100 * (seed % 5);
    for (int k = 0; k < n; ++k) P.emplace_back(1, c(rng), c(rng));
    // CGAL's triangulation of the distinct sites (t2's duplicates say which ones: a repeat is
    // written as the first of its equal sites, whose edges are then its own).
    const auto dups = delaunay(P).duplicates();
    const auto tris = testing::cgal::delaunay_triangles(P, dups);
    std::set<Edge> edges;
    for (const auto& t : tris)
      for (int i = 0; i < 3; ++i) edges.emplace(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
    for (auto [d, k] : dups) edges.emplace(k, d);  // distance 0
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                        boost::property<boost::edge_weight_t, double>>;
    Graph g(P.size());
    for (auto [a, b] : edges) {
      const double dx = P[a].x() - P[b].x(), dy = P[a].y() - P[b].y();
      boost::add_edge(a, b, dx * dx + dy * dy, g);  // integers below 2^53: exact
    }
    std::vector<boost::graph_traits<Graph>::edge_descriptor> mst;
    boost::kruskal_minimum_spanning_tree(g, std::back_inserter(mst));
    std::vector<Edge> theirs;
    for (const auto& e : mst)
      theirs.emplace_back(static_cast<std::uint32_t>(boost::source(e, g)), static_cast<std::uint32_t>(boost::target(e, g)));
    const std::vector<Edge> ours = minimum_spanning_tree(P);
    ASSERT_EQ(theirs.size(), P.size() - 1) << "CGAL's edges do not connect the sites";
    EXPECT_EQ(testing::tree_weights(P, ours), testing::tree_weights(P, theirs)) << "seed " << seed;
    // Nearest neighbours: the nearest distance over CGAL's edges at each site equals ours.
    const auto nn = all_nearest_neighbors(P);
    std::vector<double> near(P.size(), -1);
    for (auto [a, b] : edges) {
      const double d = testing::pair_weight(P[a], P[b]).second.get_d();
      for (auto v : {a, b})
        if (near[v] < 0 || d < near[v]) near[v] = d;
    }
    for (std::uint32_t i = 0; i < P.size(); ++i)
      if (near[i] >= 0) {
        EXPECT_EQ(testing::pair_weight(P[i], P[nn[i]]).second.get_d(), near[i]) << i;
      }
    // The closest pair is the shortest of CGAL's edges.
    const Edge cp = closest_pair(P);
    double shortest = -1;
    for (auto [a, b] : edges) {
      const double d = testing::pair_weight(P[a], P[b]).second.get_d();
      if (shortest < 0 || d < shortest) shortest = d;
    }
    EXPECT_EQ(testing::pair_weight(P[cp.first], P[cp.second]).second.get_d(), shortest);
  }
}

}  // namespace
}  // namespace t2
