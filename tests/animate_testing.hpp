#pragma once
// Shared helper of the animation tests: a triangulation's finite faces in the form a recorded
// step holds them, sorted, so that a step's picture and an answer compare as sets.
#include <algorithm>
#include <vector>

#include "t2/trace/step.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2::testing {

/// The finite triangles of `t` as trace triples (each counter-clockwise, as the structure
/// lists it), in increasing order.
inline std::vector<trace::Tri> sorted_triangles(const Triangulation& t) {
  std::vector<trace::Tri> out;
  for (const auto& f : t.finite_triangles()) out.push_back({f[0], f[1], f[2]});
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace t2::testing
