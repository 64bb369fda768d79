// Exercise 06b, wrong solution: the plane's hull. Andrew's monotone chain on the drawn points
// (x/w, y/w), with exact orientations there and collinear points dropped. It is right for front
// points, and wrong as soon as a point is on the back (drawn where its antipode is) or on Ω
// (skipped: it has no drawing).
#include "hull.hpp"

#include <algorithm>

#include <t2/kernel/orient.hpp>

namespace ex06b {

std::vector<long> hull(const std::vector<t2::Point>& P) {
  std::vector<std::pair<t2::Point, long>> S;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P[i].w() != 0) S.push_back({t2::Point::cartesian(P[i].x() / P[i].w(), P[i].y() / P[i].w()), long(i)});
  std::sort(S.begin(), S.end(), [](const auto& a, const auto& b) {
    return a.first.x() != b.first.x() ? a.first.x() < b.first.x() : a.first.y() < b.first.y();
  });
  S.erase(std::unique(S.begin(), S.end(), [](const auto& a, const auto& b) { return a.first == b.first; }), S.end());
  if (S.size() <= 2) {
    std::vector<long> r;
    for (const auto& s : S) r.push_back(s.second);
    return r;
  }
  std::vector<std::pair<t2::Point, long>> H;
  for (int pass = 0; pass < 2; ++pass) {  // the lower chain left to right, then the upper right to left
    const std::size_t floor = H.size();
    for (const auto& s : S) {
      while (H.size() >= floor + 2 && t2::orient(H[H.size() - 2].first, H.back().first, s.first) <= 0) H.pop_back();
      H.push_back(s);
    }
    H.pop_back();
    std::reverse(S.begin(), S.end());
  }
  std::vector<long> r;
  for (const auto& h : H) r.push_back(h.second);
  return r;
}

}  // namespace ex06b
