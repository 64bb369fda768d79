#pragma once
// The input of the problem `range` (`t2 bench kdtree`) beyond the points (range.cpp): the
// query windows, the same for t2's structures and for the peers.

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "t2/kernel/isorect.hpp"
#include "t2/kernel/point.hpp"

namespace t2cli::algorithms {

/// One window per ten points (at least one): closed boxes {x0, y0, x1, y1} of doubles, centred
/// uniformly in the points' bounding box (a fixed seed), each 1/√(n/10) of its width and
/// height, so that a window of uniform points holds about ten. The points have w = 1.
std::vector<std::array<double, 4>> range_windows(std::span<const t2::Point> points);

/// The window of `t2 animate kdtree`: the middle half of the bounding box of the drawn positions
/// of the front points ([x0 + (x1 − x0)/4, x1 − (x1 − x0)/4], the same in y, in doubles), or of the
/// back points (a rectangle of the back side) when no point is in front; none when every point
/// is on Omega.
std::optional<t2::ExactIsoRect> animation_window(std::span<const t2::Point> points);

}  // namespace t2cli::algorithms
