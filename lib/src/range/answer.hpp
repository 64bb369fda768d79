#pragma once
// The answers of the range structures (kdtree.cpp, range_tree.cpp): what a structure's walk over
// its side finds, plus the points of Ω that the closed box reaches; a report ascending.

#include <algorithm>
#include <cstddef>
#include <vector>

#include "t2/kernel/bbox.hpp"
#include "t2/range/drawn.hpp"

namespace t2::range {

/// The count: `side(b)` counts the box's proper points on its side.
template <class Side>
std::size_t count_in(const ExactIsoRect& r, const OmegaPoints& omega, Side&& side) {
  const ExactBBox b = bbox(r);
  return side(b) + omega.count(b);
}

/// The report: `side(b, out)` appends the indices of the box's proper points, in any order.
template <class Side>
std::vector<std::size_t> report_in(const ExactIsoRect& r, const OmegaPoints& omega, Side&& side) {
  const ExactBBox b = bbox(r);
  std::vector<std::size_t> out;
  side(b, out);
  omega.report(b, out);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace t2::range
