#pragma once
/// @file intersections.hpp
/// @brief The intersection points of a set of segments of T² (chapter 13): brute force, the
/// reference, on every kind of segment; Bentley–Ottmann on front segments; the circular sweep
/// of T² (seed 000, Algorithm 16) on every kind of segment.
///
/// **What is reported.** A point p is reported when it lies on two or more segments and
///   (a) p is an endpoint of one of the segments through it (a zero-length segment counts: its
///       one point is its endpoint), or
///   (b) two segments through p lie on different lines (they cross or touch at p).
/// With p come the indices of *every* segment through p, ascending. So the points inside a
/// common piece of collinear overlapping segments are not reported (there are infinitely many),
/// but the two ends of every such piece are, each with all the segments through it; and a point
/// where a third segment crosses the overlap is reported with all of them.
///
/// Why the algorithms agree on this: the brute force takes, for every pair, the crossing
/// point or the two ends of the common piece (segment.hpp's `intersection`), and gives each
/// point every segment of those pairs. A point of (a), endpoint of s, lies on every other
/// segment t through it with s ∩ t a point or a piece ending at p (p is an end of s); a point
/// of (b) lies on s and t of different lines, and any third segment through p is on a line
/// other than s's or other than t's, so it meets one of them in the single point p (two
/// segments shorter than a half circle cannot share two antipodal points). So the pairs give p
/// with every segment through it, and give no point outside (a) or (b).
///
/// **Points.** Each point is exact, W X Y integers with no common factor (the one homogeneous
/// representative of the point of T² that lies on the segments, so its side is kept), and the
/// list is sorted in the wxy order of lexicographic.hpp (back < Ω < front, then x, then y).

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

/// One reported point and the ascending indices of the segments through it.
struct IntersectionPoint {
  ExactPoint point;                   ///< W X Y without common factor
  std::vector<std::size_t> segments;  ///< every segment through the point, ascending
};

/// The algorithms of `intersections`.
enum class IntersectAlgorithm {
  brute,  ///< every pair, O(n²): every segment of T²
  sweep,     ///< Bentley–Ottmann, O((n + k) log n): front segments only
  circular,  ///< the circular sweep around a point, O((n + k) log n): every segment of T²
};

/// "brute", "sweep" or "circular".
const char* name(IntersectAlgorithm a);

/// The intersection points of `segments` (file comment), by the given algorithm. The sweep
/// throws `Undefined` (with the index of the first offending segment) unless every endpoint is
/// on the front side.
std::vector<IntersectionPoint> intersections(const std::vector<Segment>& segments,
                                             IntersectAlgorithm algorithm = IntersectAlgorithm::sweep);

/// Every pair of segments tested, O(n²) tests (with an exact bounding-box test first on front
/// pairs); every kind of segment of chapter 02, on the whole of T².
std::vector<IntersectionPoint> intersections_brute(const std::vector<Segment>& segments);

/// Bentley–Ottmann (intersect/sweep.cpp) on front segments, in O((n + k) log n) predicates.
/// Throws `Undefined` for a segment with an endpoint on Ω or behind.
std::vector<IntersectionPoint> intersections_sweep(const std::vector<Segment>& segments);

/// The same, telling `hook` (trace/hook.hpp) each reported point (`Event::found`), the status
/// after each event (`Event::sweep`, the event point exact) and each test of two neighbours
/// (`Event::neighbours`), in segment indices. Only this overload carries trace code.
std::vector<IntersectionPoint> intersections_sweep(const std::vector<Segment>& segments,
                                                   const trace::AnyHook& hook);

/// The circular sweep of T² (intersect/circular.cpp; seed 000 §5.8, Algorithm 16): a half-line
/// from a centre o to ¬o turns once around o, and the segments it crosses at its initial
/// position are cut there. Every segment of chapter 02 (front, back, through Ω, on Ω, one
/// point). The centre is [1, 0, 0] unless that lies on a segment's line, else the first point
/// [1, t, t²] that lies on none (intersect/circular_centre.cpp). O((n + I) log n) time, I the
/// number of pairs (reported point, segment through it) (chapter 13, Theorem 4).
std::vector<IntersectionPoint> intersections_circular(const std::vector<Segment>& segments);

/// The same, telling `hook` the centre and the cut segments (`Event::sweep_start`), then what
/// the traced `intersections_sweep` tells, with the status ordered from the centre out; the
/// points on the initial half-line are reported (`found`) after the turn, where they are judged.
std::vector<IntersectionPoint> intersections_circular(const std::vector<Segment>& segments,
                                                      const trace::AnyHook& hook);

/// p scaled by the positive factor that leaves W, X, Y without common factor.
ExactPoint reduced(const ExactPoint& p);

/// "W X Y  i j ..." (two spaces before the indices), without a newline.
std::string to_line(const IntersectionPoint& p);

}  // namespace t2
