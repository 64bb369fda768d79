// The candidates of the proximity problems (t2/proximity/sites.hpp).
#include "t2/proximity/sites.hpp"

#include <algorithm>

#include "t2/kernel/lexicographic.hpp"
#include "t2/triangulation/delaunay.hpp"

namespace t2 {
namespace {

using Index = ProximitySites::Index;

/// One side: `list` the input indices of its sites (ascending), `pts` their positions as front
/// points (the back ones drawn: antipodes). Adds its duplicates, edges and extremes to `s`.
void add_side(const std::vector<Index>& list, std::vector<Point> pts, ProximitySites& s, std::vector<Index>& kept_sites,
              std::vector<Index>& extremes, const SideView& view) {
  if (list.empty()) return;
  const Triangulation tr = delaunay(std::move(pts));
  if (view) view(tr, list);
  std::vector<char> dropped(list.size(), 0);
  for (auto [d, k] : tr.duplicates()) {  // k is the smallest local index, so the smallest input index
    s.kept[list[d]] = list[k];
    dropped[d] = 1;
  }
  for (Index k = 0; k < list.size(); ++k)
    if (!dropped[k]) kept_sites.push_back(list[k]);
  if (tr.dimension() == 2) {
    for (Index h : tr.edges()) {
      const Index a = tr.org(h), b = tr.dest(h);
      if (a == Triangulation::infinite || b == Triangulation::infinite) continue;
      s.edges.emplace_back(std::min(list[a], list[b]), std::max(list[a], list[b]));
    }
    for (auto [a, b] : tr.hull_edges()) extremes.push_back(list[a]);
  } else {  // collinear (or one site): consecutive sites along the line
    std::vector<Index> order;
    for (Index k = 0; k < list.size(); ++k)
      if (!dropped[k]) order.push_back(k);
    std::sort(order.begin(), order.end(),
              [&](Index a, Index b) { return compare_xy(tr.point(a), tr.point(b)) == NEGATIVE; });
    for (std::size_t m = 1; m < order.size(); ++m)
      s.edges.emplace_back(std::min(list[order[m - 1]], list[order[m]]), std::max(list[order[m - 1]], list[order[m]]));
    for (Index k : order) extremes.push_back(list[k]);
  }
  std::sort(extremes.begin(), extremes.end());
}

}  // namespace

ProximitySites proximity_sites(std::span<const Point> points, const SideView& view) {
  ProximitySites s;
  const Index n = static_cast<Index>(points.size());
  s.kept.resize(n);
  for (Index k = 0; k < n; ++k) s.kept[k] = k;
  std::vector<Index> front, back, omega;
  for (Index k = 0; k < n; ++k) (points[k].w() > 0 ? front : points[k].w() < 0 ? back : omega).push_back(k);
  std::vector<Point> fp, bp;
  fp.reserve(front.size());
  bp.reserve(back.size());
  for (Index k : front) fp.push_back(points[k]);
  for (Index k : back) bp.push_back(antipode(points[k]));
  add_side(front, std::move(fp), s, s.front, s.front_extremes, view);
  add_side(back, std::move(bp), s, s.back, s.back_extremes, view);
  if (!omega.empty()) {  // equal directions: the one of smallest index is kept (delaunay_t2.hpp)
    Triangulation merged;
    std::vector<Index> z = detail::omega_order(points, omega, merged);
    for (auto [d, k] : merged.duplicates()) s.kept[d] = k;
    std::sort(z.begin(), z.end());
    s.omega = std::move(z);
  }
  return s;
}

}  // namespace t2
