#pragma once
/// @file closest_pair.hpp
/// @brief The closest pair of sites of T² (seed 003 §4.3.2), three ways that give the same
/// answer: brute force over all pairs, the Delaunay edges of each side, and Shamos–Hoey
/// divide and conquer on each side.
///
/// **The answer.** The first pair (i, j), i < j, in the order of `pair_before`
/// (pair_distance.hpp): the nearest by the T² distance of pairs, and among equally near pairs
/// the smallest (i, j) lexicographically. So two equal sites, when there are any, are the
/// answer (distance 0); then the nearest pair on one side (finite); then a pair with a site on
/// Ω (+∞, all level: the smallest indices); last a front site and a back one (beyond infinity,
/// the pair farthest apart in the drawing). Never undefined.
///
/// **Why the Delaunay edges suffice.** Without equal sites, a closest pair on one side has no
/// third site nearer to both of its ends, so it is a Delaunay edge of its side with every pair
/// that ties with it (sites.hpp, 1); when no side has two sites, a pair at +∞ is the answer if
/// a site is on Ω, and otherwise the two sites are the only pair.
///
/// **Divide and conquer** (Shamos and Hoey). Equal sites are found by sorting each side by
/// exact x and y (`compare_xy`, the back sites drawn) and Ω by direction; then each side's
/// distinct sites, presorted once by x, are halved at the median, solved on each half, merged by
/// y, and the pairs across the dividing line within the best distance δ so far are compared: in
/// a strip of width 2δ each site meets at most 7 sites above it within δ (chapter 12). The pairs
/// are compared exactly (`pair_before`), so the ties go as above; only the choice of which pairs
/// to compare uses rounded positions, with a proved margin (closest_pair_divide.cpp).

#include <functional>
#include <span>
#include <utility>

#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

/// The closest pair by brute force: O(n²) comparisons. Throws `BadInput` for fewer than two sites.
std::pair<Triangulation::Index, Triangulation::Index> closest_pair_brute(std::span<const Point> points);

/// The closest pair from the Delaunay edges of each side (file comment): O(n log n). The same
/// answer as `closest_pair_brute`. Throws `BadInput` for fewer than two sites.
std::pair<Triangulation::Index, Triangulation::Index> closest_pair(std::span<const Point> points);

/// The closest pair by divide and conquer on each side (file comment): O(n log n) for sites
/// whose Cartesian coordinates are within 2⁵⁰⁰ (O(n²) beyond, still exact). The same answer as
/// `closest_pair_brute`. Throws `BadInput` for fewer than two sites.
std::pair<Triangulation::Index, Triangulation::Index> closest_pair_divide(std::span<const Point> points);

/// The same, telling `hook` (trace/hook.hpp), in input indices: each split of a side's sites
/// (`Event::split`), each strip (`Event::strip`), each pair compared with the closest so far
/// (`Event::compare_pair`, POSITIVE when it is the new closest). Only this overload carries
/// trace code.
std::pair<Triangulation::Index, Triangulation::Index> closest_pair_divide(
    std::span<const Point> points, const trace::AnyHook& hook);

}  // namespace t2
