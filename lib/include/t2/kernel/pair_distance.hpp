#pragma once
/// @file pair_distance.hpp
/// @brief The order of the distances of *pairs* of sites of T² that the spanning tree and the
/// closest pair use (chapter 12): the kernel's `compare_distance(a, b, c, d)` (distance.hpp),
/// completed for pairs of two points of Ω and for equal points.
///
/// **The convention, and why.** A pair {a, b} weighs, in increasing order:
///  - 0 when a = b (equal points of T², on Ω too: a point is at distance 0 from itself);
///  - *finite* when a and b are proper on one side: [1, |A − B|²], ordered by |A − B|;
///  - *infinite* when at least one of a, b is on Ω: +∞ — all such pairs weigh the same;
///  - *beyond infinity* when a and b are proper on opposite sides: [−1, |A − B|²], the larger
///    |A − B| the nearer.
/// These are the three cases of seed 000 §5.4 (finite, infinite, beyond infinity), and for at
/// most one point of a pair on Ω the order is exactly the kernel's four-point comparison
/// (distance.hpp), which also puts every +∞ pair level. The seed puts a pair of two directions
/// in the infinite case too, and so does this order, although the kernel does not give that
/// pair a T¹ value (its distance is an angle). Why not break the ties between infinite pairs
/// by the three-point predicate of §4.3.1, as Algorithm 12 suggests? That predicate compares
/// only pairs with a common point and is not the restriction of any one order of pairs: with c
/// on Ω it ranks two front points by the sweep rule (u·A), with a on Ω and c proper by the
/// angle at the origin — two different functions of the same pair {a, c} — so Kruskal's
/// sorting would have no total order to follow. The ties are broken by the indices instead
/// (see the algorithms), which is deterministic and never undefined.

#include <cstdint>
#include <span>
#include <utility>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

/// The class of the distance of the pair {a, b} in the order of the file comment: 0 equal
/// points or one side, 1 at least one point on Ω (distinct points), 2 opposite sides.
inline int pair_class(const Point& a, const Point& b) {
  const Sign sa = sign_of(a.w()), sb = sign_of(b.w());
  if (sa == ZERO && sb == ZERO) return a == b ? 0 : 1;
  if (sa == ZERO || sb == ZERO) return 1;
  return sa == sb ? 0 : 2;
}

/// Compares d(a, b) with d(c, d) in the order of the file comment: NEGATIVE when {a, b} is the
/// nearer pair, ZERO when they weigh the same. Exact; never throws.
inline Sign compare_pair_distance(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int kab = pair_class(a, b), kcd = pair_class(c, d);
  if (kab != kcd) return kab < kcd ? NEGATIVE : POSITIVE;
  if (kab == 1) return ZERO;
  if (kab == 0 && (a.w() == 0 || c.w() == 0)) {  // two equal points of Ω: distance 0
    const bool za = a.w() == 0 || a == b, zc = c.w() == 0 || c == d;
    return za == zc ? ZERO : za ? NEGATIVE : POSITIVE;
  }
  return compare_distance(a, b, c, d);
}

/// The pair (i, j) of sites of `P` against (k, l): the order of `compare_pair_distance`, ties
/// broken by the pairs (min, max) in lexicographic order. True when (i, j) comes first.
inline bool pair_before(std::span<const Point> P, std::uint32_t i, std::uint32_t j, std::uint32_t k,
                        std::uint32_t l) {
  const Sign s = compare_pair_distance(P[i], P[j], P[k], P[l]);
  if (s != ZERO) return s == NEGATIVE;
  const auto a = i < j ? std::pair(i, j) : std::pair(j, i), b = k < l ? std::pair(k, l) : std::pair(l, k);
  return a < b;
}

/// A double key of the squared length of a finite pair (a, b proper on one side), for sorting
/// before the exact order decides: when |a_w| = |b_w| = 1, dx = fl(x_a w_a − x_b w_b) is the
/// Cartesian difference rounded once (the products by ±1 are exact, and a difference of
/// distinct doubles never rounds to zero), so the key fl(fl(dx²) + fl(dy²)) is within
/// 4u(1 + u) of |A − B|² relatively, u = 2⁻⁵³ — unless a square under- or overflows. So
/// two keys k₁ ≤ k₂ with k₂ − k₁ > 2⁻⁴⁰·k₂ are in the exact order. Returns −1 where that bound
/// does not hold (|w| ≠ 1, or a key outside [2⁻⁹⁰⁰, 2⁹⁰⁰]): the caller then compares exactly.
inline double finite_key(const Point& a, const Point& b) {
  if (!((a.w() == 1 || a.w() == -1) && (b.w() == 1 || b.w() == -1))) return -1;
  const double dx = a.x() * a.w() - b.x() * b.w(), dy = a.y() * a.w() - b.y() * b.w();
  const double key = dx * dx + dy * dy;
  return key >= 0x1p-900 && key <= 0x1p900 ? key : -1;
}

/// Two keys of `finite_key` too close for their order to be trusted (k₁ ≤ k₂).
inline bool keys_near(double k1, double k2) { return k2 - k1 <= 0x1p-40 * k2; }

}  // namespace t2
