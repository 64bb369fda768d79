// Algorithm 12 in T² (t2/proximity/spanning_tree.hpp).
#include "t2/proximity/spanning_tree.hpp"

#include <algorithm>
#include <bit>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/pair_distance.hpp"
#include "t2/proximity/sites.hpp"
#include "t2/proximity/union_find.hpp"
#include "t2/triangulation/spatial_sort.hpp"

namespace t2 {
namespace {

using Index = Triangulation::Index;
using Edge = std::pair<Index, Index>;

/// Tells `hook` that Kruskal takes (tree_edge) or drops (cycle_edge) the edge e; nothing for NoTrace.
template <class H>
void tell_edge(H& hook, trace::Event what, const Edge& e, const UnionFind& uf) {
  tell(hook, [&] {
    trace::Report r = trace::about(what, {e.first, e.second});
    r.forest = &uf;
    return r;
  });
}

/// Sorts the finite edges by `pair_before`: by `finite_key` when every edge has one, each run
/// of near keys (`keys_near`) then re-sorted exactly; otherwise exactly throughout.
void sort_finite(std::span<const Point> P, std::vector<Edge>& edges) {
  const auto exact = [&](const Edge& e, const Edge& f) { return pair_before(P, e.first, e.second, f.first, f.second); };
  // Positive doubles sort as their bit patterns: a radix sort of (key, edge) pairs.
  std::vector<detail::SortKey> k(edges.size());
  for (std::size_t m = 0; m < edges.size(); ++m) {
    const double key = finite_key(P[edges[m].first], P[edges[m].second]);
    if (key < 0) {
      std::sort(edges.begin(), edges.end(), exact);
      return;
    }
    k[m] = {std::bit_cast<std::uint64_t>(key), static_cast<std::uint32_t>(m)};
  }
  detail::radix_sort(k, 64);
  {
    std::vector<Edge> sorted(edges.size());
    for (std::size_t m = 0; m < k.size(); ++m) sorted[m] = edges[k[m].index];
    edges.swap(sorted);
  }
  const auto key = [&](std::size_t m) { return std::bit_cast<double>(k[m].key); };
  for (std::size_t first = 0; first < k.size();) {
    std::size_t last = first + 1;
    while (last < k.size() && keys_near(key(last - 1), key(last))) ++last;
    if (last - first > 1) std::sort(edges.begin() + first, edges.begin() + last, exact);
    first = last;
  }
}

/// Kruskal's pairs at +∞ (at least one site on Ω), all of one weight, in the order of their
/// indices: for each i ascending, the first site j > i of every other component that makes an
/// eligible pair with i (j on Ω when i is proper); their joins in the order of j.
template <class H>
void join_infinite(std::span<const Point> P, UnionFind& uf, std::vector<Edge>& tree, H& hook) {
  struct Group {
    std::vector<Index> members;  // ascending
    bool omega;
  };
  std::vector<Group> groups;  // the components now: one per side with sites, one per site of Ω
  std::vector<Index> root_group(P.size(), Triangulation::none);
  for (Index i = 0; i < P.size(); ++i) {
    const Index r = uf.find(i);
    if (root_group[r] == Triangulation::none) {
      root_group[r] = static_cast<Index>(groups.size());
      groups.push_back({{}, P[i].w() == 0});
    }
    groups[root_group[r]].members.push_back(i);
  }
  std::vector<std::pair<Index, Index>> offers;  // (j, current root)
  for (Index i = 0; i < P.size() && uf.sets() > 1; ++i) {
    const bool i_omega = P[i].w() == 0;
    const Index ri = uf.find(i);
    offers.clear();
    for (const Group& g : groups) {
      if (!(i_omega || g.omega)) continue;
      const auto it = std::upper_bound(g.members.begin(), g.members.end(), i);
      if (it == g.members.end()) continue;
      const Index r = uf.find(*it);
      if (r != ri) offers.emplace_back(*it, r);
    }
    std::sort(offers.begin(), offers.end());
    for (auto [j, r] : offers)
      if (uf.join(i, j)) {
        tree.emplace_back(i, j);
        tell_edge(hook, trace::Event::tree_edge, tree.back(), uf);
      }
  }
}

//> minimum-spanning-tree
template <class H>
std::vector<Edge> spanning_tree(std::span<const Point> P, H& hook) {
  std::vector<Edge> tree;
  if (P.size() < 2) return tree;
  SideView view;
  if constexpr (trace::traced<H>)
    view = [&](const Triangulation& tr, std::span<const Index> input_of) {
      trace::Report r = trace::about(trace::Event::candidates, {});
      r.tr = &tr;
      r.input_of = input_of;
      hook(r);
    };
  ProximitySites s = proximity_sites(P, view);
  UnionFind uf(P.size());
  // Weight 0: each equal site joins the first of them, in the order of the pairs (kept, i).
  std::vector<Edge> equal;
  for (Index i = 0; i < P.size(); ++i)
    if (s.kept[i] != i) equal.emplace_back(s.kept[i], i);
  std::sort(equal.begin(), equal.end());
  for (const Edge& e : equal)
    if (uf.join(e.first, e.second)) {
      tree.push_back(e);
      tell_edge(hook, trace::Event::tree_edge, e, uf);
    }
  // Finite: Kruskal on the Delaunay edges of each side.
  sort_finite(P, s.edges);
  for (const Edge& e : s.edges) {
    const bool joined = uf.join(e.first, e.second);
    if (joined) tree.push_back(e);
    tell_edge(hook, joined ? trace::Event::tree_edge : trace::Event::cycle_edge, e, uf);
    if (uf.sets() == 1) break;
  }
  // +∞: the sites on Ω.
  if (!s.omega.empty()) join_infinite(P, uf, tree, hook);
  // Beyond infinity: the nearest pair across the sides, between hull vertices (sites.hpp, 2).
  if (uf.sets() > 1) {
    Edge best{Triangulation::none, Triangulation::none};
    for (Index a : s.front_extremes)
      for (Index b : s.back_extremes)
        if (best.first == Triangulation::none || pair_before(P, std::min(a, b), std::max(a, b), best.first, best.second))
          best = {std::min(a, b), std::max(a, b)};
    uf.join(best.first, best.second);
    tree.push_back(best);
    tell_edge(hook, trace::Event::tree_edge, best, uf);
  }
  return tree;
}
//< minimum-spanning-tree

}  // namespace

std::vector<Edge> minimum_spanning_tree(std::span<const Point> P) {
  NoTrace none;
  return spanning_tree(P, none);
}

std::vector<Edge> minimum_spanning_tree(std::span<const Point> P, const trace::AnyHook& hook) {
  return spanning_tree(P, hook);
}

}  // namespace t2
