#pragma once
/// @file calipers.hpp
/// @brief Rotating calipers on a convex polygon: antipodal pairs and the width (chapter 07).
///
/// Two vertices a, b of a convex polygon are **antipodal** when two distinct parallel lines,
/// one through a and one through b, hold the polygon between them. Turn a direction u once
/// around: the vertex farthest in direction u (its *support*) changes only when u passes the
/// outer normal of an edge, and the pairs (support of u, support of −u) are exactly the
/// antipodal pairs (each twice, as (a, b) and (b, a)). So two pointers walk the polygon, as
/// two merged sorted lists of edge directions: i is the support of u, j of −u, and the next
/// event is the edge e_i or e_j whose direction comes first; comparing them is one exact sign,
/// the turn from e_i to e_j. When e_i and e_j are parallel both advance, and the four pairs of
/// their ends are antipodal. Each pointer passes each edge once: O(h) for h vertices, at most
/// 3h/2 pairs. At the event of e_i, j is the vertex farthest from the line of e_i: the width
/// is the least of those h distances (a narrowest strip has a side along an edge).
///
/// Parallel lines meet on Ω, and distances are those of the drawn points, so the calipers work
/// on proper points of one side of T². A polygon on the back side is the antipode of a front
/// polygon with the same distances (the antipodal map reverses Δ, hence the reversed order).

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/hull/convex_hull.hpp"
#include "t2/hull/traits.hpp"

namespace t2 {

namespace detail {

// The turn from the direction of a → b to that of c → d (a, b, c, d proper, front): the sign of
// the cross product (B − A) × (D − C) of the drawn vectors, scaled by the positive a_w b_w c_w d_w.
inline Sign turn_of_directions(const Point& a, const Point& b, const Point& c, const Point& d) {
  return sign_of_poly(
      [](const auto& aw, const auto& ax, const auto& ay, const auto& bw, const auto& bx, const auto& by,
         const auto& cw, const auto& cx, const auto& cy, const auto& dw, const auto& dx, const auto& dy) {
        const auto ux = bx * aw - ax * bw, uy = by * aw - ay * bw;
        const auto vx = dx * cw - cx * dw, vy = dy * cw - cy * dw;
        return ux * vy - uy * vx;
      },
      a.w(), a.x(), a.y(), b.w(), b.x(), b.y(), c.w(), c.x(), c.y(), d.w(), d.x(), d.y());
}

// The two parts of compare_line_distances' polynomial, at namespace scope so that the
// polynomial, a lambda without captures (filter.hpp), can call them.
inline constexpr auto line_distance_term = [](const auto& aw, const auto& ax, const auto& ay, const auto& bw,
                                              const auto& bx, const auto& by, const auto& qw, const auto& qx,
                                              const auto& qy, const auto& ow) {
  const auto det = aw * (bx * qy - by * qx) - ax * (bw * qy - by * qw) + ay * (bw * qx - bx * qw);
  return det * det * ow * ow;  // Δ² times the other q_w²
};
inline constexpr auto line_length2 = [](const auto& aw, const auto& ax, const auto& ay, const auto& bw,
                                        const auto& bx, const auto& by) {
  const auto ux = bx * aw - ax * bw, uy = by * aw - ay * bw;
  return ux * ux + uy * uy;
};

// The distance from q to the line a b compared with that from q' to a' b' (all front, a ≠ b):
// dist² = Δ(a, b, q)² / (q_w² L(a, b)), L(a, b) = |B − A|² (a_w b_w)², cross-multiplied.
inline Sign compare_line_distances(const Point& a, const Point& b, const Point& q, const Point& a2, const Point& b2,
                                   const Point& q2) {
  return sign_of_poly(
      [](const auto& aw, const auto& ax, const auto& ay, const auto& bw, const auto& bx, const auto& by,
         const auto& qw, const auto& qx, const auto& qy, const auto& cw, const auto& cx, const auto& cy,
         const auto& dw, const auto& dx, const auto& dy, const auto& rw, const auto& rx, const auto& ry) {
        return line_distance_term(aw, ax, ay, bw, bx, by, qw, qx, qy, rw) * line_length2(cw, cx, cy, dw, dx, dy) -
               line_distance_term(cw, cx, cy, dw, dx, dy, rw, rx, ry, qw) * line_length2(aw, ax, ay, bw, bx, by);
      },
      a.w(), a.x(), a.y(), b.w(), b.x(), b.y(), q.w(), q.x(), q.y(), a2.w(), a2.x(), a2.y(), b2.w(), b2.x(), b2.y(),
      q2.w(), q2.x(), q2.y());
}

// The convex polygon as front points, counter-clockwise as drawn, with the input index of each.
inline std::pair<std::vector<Point>, std::vector<std::size_t>> front_copy(std::span<const Point> P,
                                                                           std::span<const std::size_t> hull) {
  std::vector<Point> Q;
  std::vector<std::size_t> at;
  const bool back = !hull.empty() && P[hull[0]].w() < 0;
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const std::size_t i = back ? hull[hull.size() - 1 - k] : hull[k];
    if (P[i].w() == 0 || (P[i].w() < 0) != back)
      throw BadInput("rotating calipers: the polygon's vertices must be proper points on one side of T2");
    Q.push_back(back ? antipode(P[i]) : P[i]);
    at.push_back(i);
  }
  return {std::move(Q), std::move(at)};
}

// The calipers' walk on Q (h ≥ 3 strict vertices, counter-clockwise, front): pair(i, j) for
// each antipodal pair met (indices into Q, some twice), edge(i, j) at the event of edge
// Q[i] → Q[i+1], j then being a farthest vertex from its line.
template <class Pair, class Edge>
void calipers(const std::vector<Point>& Q, Pair&& pair, Edge&& edge) {
  //> calipers
  const std::size_t h = Q.size();
  const auto turn = [&](std::size_t i, std::size_t j) {  // from edge e_i to edge e_j
    return turn_of_directions(Q[i % h], Q[(i + 1) % h], Q[j % h], Q[(j + 1) % h]);
  };
  std::size_t j = 0;  // the support of −u for u the outer normal of e_{h−1}
  while (j < h && turn(h - 1, j) > 0) ++j;
  std::size_t i = 0;
  pair(i, j % h);
  while (i < h) {  // one full turn of u
    const Sign s = turn(i, j);
    if (s <= 0) edge(i % h, j % h);  // e_i comes first (or with e_j): j is farthest from it
    if (s < 0) {
      ++i;
    } else if (s > 0) {
      ++j;
    } else {  // e_i ∥ e_j: both ends of each are antipodal to both ends of the other
      pair((i + 1) % h, j % h);
      pair(i % h, (j + 1) % h);
      ++i, ++j;
    }
    pair(i % h, j % h);
  }
  //< calipers
}

}  // namespace detail

/// The antipodal pairs of a convex polygon: `hull` holds indices into P of its strict vertices,
/// counter-clockwise in T² (as `convex_hull` gives them), all proper points on one side of T².
/// Each pair once, as (smaller index, larger), sorted. One vertex gives no pair, two give one.
/// O(h) (plus the sort). Throws `BadInput` for points on Ω or on both sides.
inline std::vector<std::pair<std::size_t, std::size_t>> antipodal_pairs(std::span<const Point> P,
                                                                        std::span<const std::size_t> hull) {
  const auto [Q, at] = detail::front_copy(P, hull);
  std::vector<std::pair<std::size_t, std::size_t>> out;
  if (Q.size() == 2) out.emplace_back(std::min(at[0], at[1]), std::max(at[0], at[1]));
  if (Q.size() < 3) return out;
  detail::calipers(
      Q,
      [&out, &at = at](std::size_t a, std::size_t b) {  // bindings captured by name, as clang 14 needs
        if (a != b) out.emplace_back(std::min(at[a], at[b]), std::max(at[a], at[b]));
      },
      [](std::size_t, std::size_t) {});
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// A narrowest strip: the hull edge from `from` to `to` and the vertex `vertex` farthest from its
/// line (indices into the input); the width is that vertex's distance from the line.
struct Width {
  std::size_t from;    ///< the edge's first vertex
  std::size_t to;      ///< the edge's second vertex
  std::size_t vertex;  ///< the vertex on the other side of the strip
};

/// The width of the points P (the least distance between two parallel lines holding them all),
/// by the calipers on their hull: O(n log n). Proper points on one side of T² only (else
/// `BadInput`); `std::nullopt` when the hull has fewer than three vertices (the width is 0).
/// The traits K are those of the hull (traits.hpp).
template <class K = HullTraits>
std::optional<Width> width(std::span<const Point> P) {
  for (const Point& p : P)
    if (p.w() == 0 || (p.w() < 0) != (P[0].w() < 0))
      throw BadInput("width: the points must be proper points on one side of T2");
  const std::vector<std::size_t> hull = convex_hull<K>(P);
  if (hull.size() < 3) return std::nullopt;
  const auto [Q, at] = detail::front_copy(P, hull);
  const std::size_t h = Q.size();
  std::optional<std::pair<std::size_t, std::size_t>> best;  // (edge, vertex) in Q
  detail::calipers(Q, [](std::size_t, std::size_t) {},
                   [&best, &Q = Q, h](std::size_t e, std::size_t v) {
                     if (!best || detail::compare_line_distances(Q[e], Q[(e + 1) % h], Q[v], Q[best->first],
                                                                 Q[(best->first + 1) % h], Q[best->second]) < 0)
                       best = std::make_pair(e, v);
                   });
  return Width{at[best->first], at[(best->first + 1) % h], at[best->second]};
}

// The default instantiation is compiled once, in lib/src/hull/convex_hull.cpp.
#ifndef T2_FILTER_STATS  // a program that counts the exact stages compiles its own copy
/// @cond INSTANTIATIONS
extern template std::optional<Width> width<HullTraits>(std::span<const Point>);
/// @endcond
#endif

}  // namespace t2
