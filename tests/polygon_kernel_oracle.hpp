#pragma once
// The O(n k) kernel of a polygon, the oracle of test_polygon_kernel.cpp: the library's algorithm
// before Lee and Preparata's (git history of polygon_kernel.hpp). The closed front hemisphere
// (Ω in four quarters) cut by each edge line in turn, Sutherland–Hodgman on the whole boundary,
// no tangents and no linked list: every cut scans every corner.
#include <algorithm>
#include <vector>

#include "t2/hull/polygon_kernel.hpp"

namespace t2::testing {

// The region R cut by the closed half-plane left of l.
inline void oracle_cut(std::vector<detail::RegionEdge>& R, const ExactLine& l) {
  const std::size_t m = R.size();
  std::vector<Sign> s(m);
  bool out_side = false;
  for (std::size_t k = 0; k < m; ++k) out_side = (s[k] = sign_of(detail::value(l, R[k].start))) < 0 || out_side;
  if (!out_side) return;
  std::vector<detail::RegionEdge> out;
  for (std::size_t k = 0; k < m; ++k) {
    const detail::RegionEdge& a = R[k];
    const ExactPoint& b = R[(k + 1) % m].start;
    const Sign sa = s[k], sb = s[(k + 1) % m];
    if (sa >= 0) out.push_back({a.start, sa == 0 && sb < 0 ? l : a.line});
    if (sa > 0 && sb < 0) out.push_back({detail::crossing(a.line, l, a.start, b), l});
    if (sa < 0 && sb > 0) out.push_back({detail::crossing(a.line, l, a.start, b), a.line});
  }
  for (std::size_t k = 0; k < out.size() && out.size() > 1; ++k) {  // half a turn along l
    const ExactPoint& x = out[k].start;
    const ExactPoint& y = out[(k + 1) % out.size()].start;
    if (out[k].line == l && !(x == y) && detail::ahead(l, x, y) <= 0)
      out.insert(out.begin() + static_cast<std::ptrdiff_t>(k + 1), detail::RegionEdge{detail::cross_point(l, x), l});
  }
  R = std::move(out);
}

// The kernel's corners, counter-clockwise from any corner (V: distinct consecutive vertices,
// counter-clockwise, none on the back side).
inline std::vector<ExactPoint> oracle_kernel(const std::vector<Point>& V) {
  const ExactPoint X(0, 1, 0), Y(0, 0, 1);
  std::vector<detail::RegionEdge> R{
      {X, omega<Integer>()}, {Y, omega<Integer>()}, {antipode(X), omega<Integer>()}, {antipode(Y), omega<Integer>()}};
  for (std::size_t i = 0; i < V.size() && !R.empty(); ++i)
    oracle_cut(R, join(to_exact(V[i]), to_exact(V[(i + 1) % V.size()])));
  for (bool changed = true; changed && R.size() > 2;) {  // corners only
    changed = false;
    for (std::size_t k = 0; k < R.size() && R.size() > 2; ++k) {
      const auto& prev = R[(k + R.size() - 1) % R.size()];
      const auto& next = R[(k + 1) % R.size()];
      if (prev.line == R[k].line && detail::ahead(prev.line, prev.start, next.start) > 0) {
        R.erase(R.begin() + static_cast<std::ptrdiff_t>(k));
        changed = true;
      }
    }
  }
  // The old code's one slip: a cut across a segment kernel left its crossing twice (a corner,
  // then an edge of length zero); the repeat is dropped.
  std::vector<ExactPoint> corners;
  for (const auto& e : R)
    if (corners.empty() || !(corners.back() == e.start)) corners.push_back(e.start);
  while (corners.size() > 1 && corners.back() == corners.front()) corners.pop_back();
  return corners;
}

}  // namespace t2::testing
