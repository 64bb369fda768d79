// Algorithm 9 of seed 000 on T²: the degenerate cases and the untraced
// entry point (triangulate_t2.hpp; the insertion itself is insert_t2.hpp).
#include "t2/triangulation/triangulate_t2.hpp"
#include "t2/triangulation/insert_t2.hpp"

#include <algorithm>
#include <numeric>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/hull/convex_hull.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/triangulation/spatial_sort.hpp"
#include "t2/triangulation/triangulate.hpp"

namespace t2 {

using Index = Triangulation::Index;

namespace {

std::string named(std::span<const Point> input, Index k) { return point_name(k) + " = " + to_string(input[k]); }

}  // namespace

void detail::collinear_t2(std::span<const Point> input, Triangulation& tr, bool one_point) {
  try {
    (void)convex_hull(input);
  } catch (const NoHull& e) {
    throw Undefined(std::string("triangulate: all points lie on one great circle, in no open half of it, so no "
                                "triangle and no hull has them as vertices: ") + e.what());
  }
  std::vector<Index> s(input.size());
  std::iota(s.begin(), s.end(), Index(0));
  std::stable_sort(s.begin(), s.end(), [&](Index a, Index b) {
    return compare_lexicographic(input[a], input[b]) == NEGATIVE;
  });
  // each point equal to the first of its run (the smallest index: the sort is stable) is a duplicate of it
  for (std::size_t k = 1, first = 0; k < s.size(); ++k) {
    if (compare_lexicographic(input[s[first]], input[s[k]]) == ZERO)
      tr.add_duplicate(s[k], s[first]);
    else
      first = k;
  }
  tr.set_dimension(one_point ? 0 : 1);
}

void detail::undefined_t2(std::span<const Point> input, Index p, Index a, Index b) {
  throw Undefined("triangulate: the antipode of " + named(input, p) + " lies inside the hull edge from " +
                  named(input, a) + " to " + named(input, b) +
                  " of the other points, which lie in the closed hemisphere of that edge's great circle: the "
                  "face beyond it would be the open hemisphere bounded by the whole circle, not a triangle");
}

TriangulationT2 triangulate_t2(std::span<const Point> input, InsertionOrder how) {
  return triangulate_t2(input, how, NoTrace{});
}

}  // namespace t2
