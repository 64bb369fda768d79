#pragma once
/// @file diameter.hpp
/// @brief The diameter of points of T²: the largest distance between two of them (chapter 07).
///
/// Seed 003 (§4.4.3) computes diam(S) as "min(AntiPairs(P))": a slip, the diameter is the
/// *maximum* distance (its own Definition 4.3 says so). **Lemma.** The diameter of a finite set
/// S of one side of T² is realized by an antipodal pair of its hull. *Proof.* Let a, b realize
/// it. Every point of S lies in the disk of radius |ab| around a, so no point lies beyond the
/// line through b perpendicular to ab (it would be farther from a than b), nor beyond the
/// perpendicular through a: these two parallel lines hold S, and a, b are hull vertices on
/// them. Among points of one side only hull vertices can be farthest, and the calipers
/// visit every antipodal pair, so the largest of O(h) pairs is the answer.
///
/// T² adds three cases, from the order of squared distances in T¹ (distance.hpp): a front and a
/// back point are "beyond infinity", farther apart than any two points of one side, and the
/// farthest such pair is the one whose drawn positions are *nearest* (a point and its antipode
/// are the farthest of all); a proper point and a point of Ω are +∞ apart; and the distance of
/// two points of Ω is an angle, not a value of T¹, so two different points of Ω leave the
/// diameter undefined.

#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/distance.hpp"
#include "t2/hull/calipers.hpp"
#include "t2/hull/convex_hull.hpp"
#include "t2/hull/traits.hpp"

namespace t2 {

/// The diameter of the points P: the indices (a, b) of a farthest pair in the order of squared
/// distances of T¹ (file comment), `std::nullopt` for no point, (a, a) when all points are
/// equal. One side of T²: the hull and the calipers, O(n log n). Front and back points: the
/// front–back pair nearest as drawn, by brute force (O(n²); chapter 11's Voronoi diagram does it
/// in O(n log n)). Points of Ω: +∞ with any proper point. Throws `Undefined` when two different
/// points lie on Ω (their distance is an angle, comparable with no other).
template <class K = HullTraits>
std::optional<std::pair<std::size_t, std::size_t>> diameter(std::span<const Point> P) {
  if (P.empty()) return std::nullopt;
  std::vector<std::size_t> front, back, omega;
  for (std::size_t i = 0; i < P.size(); ++i) (P[i].w() > 0 ? front : P[i].w() < 0 ? back : omega).push_back(i);
  for (std::size_t o : omega)
    if (!K::equal(P[o], P[omega[0]]))
      throw Undefined("diameter: p" + std::to_string(omega[0]) + " and p" + std::to_string(o) +
                      " are different points of Omega: their distance is an angle, not a value of T1, so no "
                      "largest distance exists");
  const auto as_front = [&](std::size_t i) { return P[i].w() < 0 ? antipode(P[i]) : P[i]; };
  if (!front.empty() && !back.empty()) {  // beyond infinity: the front-back pair nearest as drawn
    std::pair<std::size_t, std::size_t> best{front[0], back[0]};
    for (std::size_t f : front)
      for (std::size_t b : back)
        if (compare_distance(P[f], as_front(b), P[best.first], as_front(best.second)) < 0) best = {f, b};
    return best;
  }
  const std::vector<std::size_t>& proper = front.empty() ? back : front;
  if (!omega.empty()) return proper.empty() ? std::make_pair(omega[0], omega[0]) : std::make_pair(proper[0], omega[0]);
  //> diameter
  const std::vector<std::size_t> hull = convex_hull<K>(P);
  if (hull.size() == 1) return std::make_pair(hull[0], hull[0]);
  std::optional<std::pair<std::size_t, std::size_t>> best;
  // the largest, not the smallest (seed 003)
  for (const auto& [a, b] : antipodal_pairs(P, hull))
    if (!best ||
        compare_distance(as_front(best->first), as_front(best->second),
                                       as_front(a), as_front(b)) < 0)
      best = std::make_pair(a, b);
  //< diameter
  return best;
}

// The default instantiation is compiled once, in lib/src/hull/convex_hull.cpp.
#ifndef T2_FILTER_STATS  // a program that counts the exact stages compiles its own copy
/// @cond INSTANTIATIONS
extern template std::optional<std::pair<std::size_t, std::size_t>> diameter<HullTraits>(std::span<const Point>);
/// @endcond
#endif

}  // namespace t2
