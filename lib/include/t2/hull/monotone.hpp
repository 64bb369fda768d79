#pragma once
/// @file monotone.hpp
/// @brief Andrew's monotone chain in a chart of T², and the Akl–Toussaint throw-away.

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <type_traits>
#include <vector>

#include "t2/hull/chart_sort.hpp"
#include "t2/hull/traits.hpp"

namespace t2 {

namespace detail {

// The chain so far: positions in the sorted points s (8 bytes a vertex: on a circle, where
// every point is a vertex, a copy of the points would be the largest array), and their input
// indices only when a trace watches (what it is shown).
struct Chain {
  std::span<const Indexed> s;   // the sorted points
  std::vector<std::size_t> at;  // the chain: positions in s
  std::vector<std::size_t> idx;  // the same as input indices, for a trace
  const Point& point(std::size_t k) const { return s[at[k]].p; }
};

// One chain of the monotone chain: pops the points that do not turn left, pushes s[j].
template <class K, class Tr>
void chain_step(Chain& h, std::size_t floor, std::size_t j, Tr& trace) {
  while (h.at.size() >= floor + 2 && K::orient(h.point(h.at.size() - 2), h.point(h.at.size() - 1), h.s[j].p) <= 0) {
    if constexpr (trace::traced<Tr>) {
      trace(trace::about(trace::Event::pop, {h.idx.back()}, h.idx));
      h.idx.pop_back();
    }
    h.at.pop_back();
  }
  h.at.push_back(j);
  if constexpr (trace::traced<Tr>) {
    h.idx.push_back(h.s[j].i);
    trace(trace::about(trace::Event::push, {h.s[j].i}, h.idx));
  }
}

}  // namespace detail

/// Andrew's monotone chain on the points P[i], i in `idx`, in the chart `chart` (traits.hpp):
/// the indices of the strict hull vertices, counter-clockwise, starting at the first in the
/// chart's order. O(n log n). The points must lie where the chart is valid.
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> monotone_chain(std::span<const Point> P, std::vector<std::size_t> idx, const Chart& chart,
                                        Tr&& trace = {}) {
  //> hull-monotone
  const ChartOrder<K> order{chart};
  // the points with their indices, sorted by the chart's order, repeats dropped
  const std::vector<detail::Indexed> s = detail::sorted_in_chart<K>(P, idx, order);
  std::vector<std::size_t>().swap(idx);  // not needed any more: its memory back now
  detail::Chain h{s, {}, {}};
  const std::size_t n = s.size();
  if (n < 3) {  // no point, one point, or a segment
    for (const auto& e : s) idx.push_back(e.i);
    return idx;
  }
  h.at.reserve(n + 1);
  for (std::size_t j = 0; j < n; ++j)
    detail::chain_step<K>(h, 0, j, trace);  // lower chain, left to right
  const std::size_t lower = h.at.size() - 1;  // the upper chain keeps it
  for (std::size_t j = n - 1; j-- > 0;)
    detail::chain_step<K>(h, lower, j, trace);
  h.at.pop_back();  // the first point again
  for (std::size_t& k : h.at) k = s[k].i;  // positions to input indices, in place
  //< hull-monotone
  return std::move(h.at);
}

namespace detail {

// The throw-away polygon of front points with w = 1 (the common case): the points extreme in
// the eight directions ±x, ±y, ±x±y, counter-clockwise. The diagonal sums are rounded, which
// only makes a vertex a little less extreme: any input points will do as vertices.
inline std::vector<std::size_t> octagon(std::span<const Point> P) {
  std::size_t e[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  double best[8];
  for (int k = 0; k < 8; ++k) best[k] = -1e308;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P[i].x(), y = P[i].y();
    const double v[8] = {-x, -x - y, -y, x - y, x, x + y, y, y - x};  // counter-clockwise from the left
    for (int k = 0; k < 8; ++k)
      if (v[k] > best[k]) best[k] = v[k], e[k] = i;
  }
  return {std::begin(e), std::end(e)};
}

}  // namespace detail

/// The Akl–Toussaint throw-away before the monotone chain: points extreme in a few directions
/// (in the chart's order: x and y; for plain front points also the diagonals) span a polygon
/// Q, and the points strictly inside it are no hull vertices: they are dropped in one pass.
/// A point is dropped when it lies strictly left of every edge of Q (Δ > 0 on each): then the
/// edges wind around it, so it lies inside the hull of Q's vertices, whatever the order they
/// came in. Most points are dropped by four plain comparisons first: a box whose corners pass
/// that test lies inside Q (the set left of every edge is convex). Same answer as
/// `monotone_chain`.
template <class K = HullTraits, class Tr = NoTrace>
std::vector<std::size_t> akl_toussaint(std::span<const Point> P, const Chart& chart, Tr&& trace = {}) {
  const ChartOrder<K> order{chart};
  std::vector<std::size_t> keep;
  if (P.empty()) return keep;
  const bool plain = chart.front && std::all_of(P.begin(), P.end(), [](const Point& p) { return p.w() == 1; });
  std::vector<std::size_t> e;
  if (plain) {
    e = detail::octagon(P);
  } else {  // least and greatest in (x, y), least and greatest in (y, x)
    std::size_t m[4] = {0, 0, 0, 0};
    const auto yx = [&](const Point& p, const Point& q) {
      const Sign s = orient_to<K>(p, q, chart.x_inf);
      return s != ZERO ? s : order.compare(p, q);
    };
    for (std::size_t i = 1; i < P.size(); ++i) {
      if (order.less(P[i], P[m[0]])) m[0] = i;
      if (order.less(P[m[2]], P[i])) m[2] = i;
      if (yx(P[i], P[m[1]]) < 0) m[1] = i;
      if (yx(P[m[3]], P[i]) < 0) m[3] = i;
    }
    e.assign(std::begin(m), std::end(m));
  }
  std::vector<Point> Q;  // repeated corners dropped
  for (std::size_t c : e)
    if (Q.empty() || !K::equal(Q.back(), P[c])) Q.push_back(P[c]);
  while (Q.size() > 1 && K::equal(Q.back(), Q.front())) Q.pop_back();
  const auto inside = [&](const Point& p) {
    for (std::size_t k = 0; k < Q.size(); ++k)
      if (K::orient(Q[k], Q[(k + 1) % Q.size()], p) <= 0) return false;
    return true;
  };
  // The box, two candidates, each shrunk a little at a time until its four corners pass: the
  // one within the vertices extreme in x and y (left: −x and the two left diagonals; and so
  // on), good for a square; and the square in the largest circle inside Q around the median of a
  // sample of the points, good for heavy tails. Each is computed in doubles and kept only if verified.
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool box = false;
  if (plain && Q.size() >= 3) {
    const auto verified = [&](double a0, double a1, double b0, double b1, double& area) {
      const auto finite = [](auto... v) { return (std::isfinite(v) && ...); };  // no overflow
      for (double f = 1.0 / 256; f < 0.5 && a0 < a1 && b0 < b1 && finite(a0, a1, b0, b1); f *= 2) {
        if (inside(Point::cartesian(a0, b0)) && inside(Point::cartesian(a1, b0)) && inside(Point::cartesian(a1, b1)) &&
            inside(Point::cartesian(a0, b1))) {
          area = (a1 - a0) * (b1 - b0);
          if (!box || area > (x1 - x0) * (y1 - y0)) x0 = a0, x1 = a1, y0 = b0, y1 = b1, box = true;
          return;
        }
        const double dx = f * (a1 - a0), dy = f * (b1 - b0);
        a0 += dx, a1 -= dx, b0 += dy, b1 -= dy;
      }
    };
    double area = 0;
    const auto X = [&](int k) { return P[e[static_cast<std::size_t>(k)]].x(); };
    const auto Y = [&](int k) { return P[e[static_cast<std::size_t>(k)]].y(); };
    verified(std::max({X(7), X(0), X(1)}), std::min({X(3), X(4), X(5)}), std::max({Y(1), Y(2), Y(3)}),
             std::min({Y(5), Y(6), Y(7)}), area);
    std::vector<double> sx, sy;  // the centre: the median of a sample of the points
    for (std::size_t i = 0; i < P.size(); i += std::max<std::size_t>(1, P.size() / 63)) sx.push_back(P[i].x()), sy.push_back(P[i].y());
    std::nth_element(sx.begin(), sx.begin() + static_cast<std::ptrdiff_t>(sx.size() / 2), sx.end());
    std::nth_element(sy.begin(), sy.begin() + static_cast<std::ptrdiff_t>(sy.size() / 2), sy.end());
    const double cx = sx[sx.size() / 2], cy = sy[sy.size() / 2];
    double r = 1e308;  // the distance from (cx, cy) to the nearest edge line of Q
    for (std::size_t k = 0; k < Q.size(); ++k) {
      const Point &a = Q[k], &b = Q[(k + 1) % Q.size()];
      const double ex = b.x() - a.x(), ey = b.y() - a.y(), len = std::hypot(ex, ey);
      if (len > 0) r = std::min(r, std::fabs(ex * (cy - a.y()) - ey * (cx - a.x())) / len);
    }
    if (std::isfinite(r)) verified(cx - r * 0.7, cx + r * 0.7, cy - r * 0.7, cy + r * 0.7, area);
  }
  const auto dropped = [&](const Point& p) {
    if (box && p.x() > x0 && p.x() < x1 && p.y() > y0 && p.y() < y1) return true;  // in the box
    return Q.size() >= 3 && inside(p);
  };
  // Is the pass worth it? It is tried on a sample of about 1024 points spread over the input:
  // when it drops fewer than half of them (on a circle it drops none), it costs more than it
  // saves, and every point goes on to the monotone chain.
  const std::size_t stride = std::max<std::size_t>(1, P.size() / 1024);
  std::size_t tried = 0, hits = 0;
  for (std::size_t i = 0; i < P.size(); i += stride) ++tried, hits += dropped(P[i]) ? 1 : 0;
  if (2 * hits < tried) {
    keep.resize(P.size());
    std::iota(keep.begin(), keep.end(), std::size_t{0});
  } else {
    keep.reserve(P.size() / 8);
    for (std::size_t i = 0; i < P.size(); ++i)
      if (!dropped(P[i])) keep.push_back(i);
  }
  return monotone_chain<K>(P, std::move(keep), chart, trace);
}

// The default instantiations are compiled once, in lib/src/hull/convex_hull.cpp.
#ifndef T2_FILTER_STATS  // a program that counts the exact stages compiles its own copy
/// @cond INSTANTIATIONS
extern template std::vector<std::size_t> monotone_chain<HullTraits, NoTrace>(std::span<const Point>,
                                                                             std::vector<std::size_t>, const Chart&,
                                                                             NoTrace&&);
extern template std::vector<std::size_t> monotone_chain<HullTraits, NoTrace&>(std::span<const Point>,
                                                                              std::vector<std::size_t>, const Chart&,
                                                                              NoTrace&);
/// @endcond
#endif

}  // namespace t2
