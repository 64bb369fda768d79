#pragma once
// Exercise 15: the API you implement in dominance.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex15 {

// Chapter 15, section 3: a rectangle of T² lies on one side, and a point p = [w, x, y] with
// w ≠ 0 is *drawn* at (x/w, y/w) (a back point [-1, -2, -3] is drawn at (2, 3)). Points of Ω
// (w = 0) are on neither side and are never counted here.

/// Q(q), the dominance count (chapter 15, section 1): the number of points p of P on the side of
/// q (sign of w) whose drawn coordinates satisfy p.x ≤ q.x and p.y ≤ q.y, with < instead of ≤
/// in x when strict_x and in y when strict_y (Lemma 1's Q⁻). Repeated points count as often as
/// they occur. Exact for every finite input. Throws t2::Undefined when q is on Ω.
long dominance(const std::vector<t2::Point>& P, const t2::Point& q, bool strict_x, bool strict_y);

/// N(r): the number of points of P in the closed rectangle r = [lo.x, hi.x] × [lo.y, hi.y] of
/// the side of lo and hi (drawn coordinates; the caller guarantees lo.x ≤ hi.x and lo.y ≤ hi.y
/// there). Compute it from four dominance counts (Lemma 1). Throws t2::Undefined when lo or hi
/// is on Ω, or when they are on different sides (no rectangle of T² has them as corners).
long count(const std::vector<t2::Point>& P, const t2::Point& lo, const t2::Point& hi);

}  // namespace ex15
