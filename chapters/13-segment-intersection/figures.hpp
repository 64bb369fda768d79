#pragma once
// Chapter 13's example segment sets and its figures (both models).
#include <t2/t2.hpp>

#include <filesystem>
#include <vector>

namespace chapter13 {

/// Five small groups, one per case of what is reported: a crossing, an endpoint inside another
/// segment, two collinear segments overlapping, a one-point segment on a segment, and three
/// segments through one point.
std::vector<t2::Segment> degenerate_cases();
/// Segments of T²: a front one, a back one drawn across it, one crossing Ω, one on Ω and one on
/// the back crossing the back one, so that two points of T² are drawn at the same place.
std::vector<t2::Segment> two_sided();
/// Four segments: three through one point, and an endpoint of the fourth inside the first, near
/// it (the input on which CGAL 5.5's sweep loses a point).
std::vector<t2::Segment> beside_triple_point();
/// Six front segments for the picture of the sweep's status.
std::vector<t2::Segment> sweep_example();

/// Segments of every kind around the origin, for the picture of the circular sweep at 135°.
std::vector<t2::Segment> circular_example();

/// Writes the chapter's figures into `dir`.
void figures(const std::filesystem::path& dir);

}  // namespace chapter13
