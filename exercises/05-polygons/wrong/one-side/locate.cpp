// Wrong on purpose: exact, and right for every polygon whose vertices are all on one side (the
// exercise's first version), but it is planar ray casting: it takes the polygon for a front (or
// back) polygon even when its vertices are on both sides and its edges cross Ω.
// 1. A back polygon is the antipodal image of a front one, and the antipodal map reverses
//    orientation: locate(P, q) = -locate(¬P, ¬q). So only front polygons remain.
// 2. A front polygon bounds a region R of the front sheet. Points off the front (on Ω or on the
//    back) are never in R; they lie in the other region.
// 3. For a front q: on an edge -> 0; otherwise crossing number of a horizontal ray, with exact
//    predicates (orientation, and comparisons of y/w done as y·w' vs y'·w since w, w' > 0).
// 4. R is on the left of the edges iff P turns counter-clockwise; its sign is the orientation
//    of the lowest-then-leftmost vertex's corner, which is convex.
#include "locate.hpp"

#include <t2/kernel/filter.hpp>
#include <t2/kernel/orient.hpp>

namespace ex05 {

namespace {

const auto minor = [](const auto& a, const auto& b, const auto& c, const auto& d) { return a * d - b * c; };

// Sign of (a.y/a.w − b.y/b.w) for front points; likewise x.
t2::Sign cmp_y(const t2::Point& a, const t2::Point& b) { return t2::sign_of_poly(minor, a.y(), a.w(), b.y(), b.w()); }
t2::Sign cmp_x(const t2::Point& a, const t2::Point& b) { return t2::sign_of_poly(minor, a.x(), a.w(), b.x(), b.w()); }

bool on_edge(const t2::Point& a, const t2::Point& b, const t2::Point& q) {
  if (t2::orient(a, b, q) != t2::ZERO) return false;
  return cmp_x(q, a) * cmp_x(q, b) <= 0 && cmp_y(q, a) * cmp_y(q, b) <= 0;
}

t2::Sign orientation(const std::vector<t2::Point>& P) {
  size_t k = 0;
  for (size_t i = 1; i < P.size(); ++i) {
    const t2::Sign c = cmp_y(P[i], P[k]);
    if (c < 0 || (c == 0 && cmp_x(P[i], P[k]) < 0)) k = i;
  }
  const size_t n = P.size();
  return t2::orient(P[(k + n - 1) % n], P[k], P[(k + 1) % n]);
}

t2::Sign locate_front(const std::vector<t2::Point>& P, const t2::Point& q) {
  const t2::Sign o = orientation(P);
  if (q.w() <= 0) return -o;
  bool inside = false;
  for (size_t i = 0; i < P.size(); ++i) {
    const t2::Point& a = P[i];
    const t2::Point& b = P[(i + 1) % P.size()];
    if (on_edge(a, b, q)) return t2::ZERO;
    const bool a_above = cmp_y(a, q) > 0, b_above = cmp_y(b, q) > 0;
    if (a_above == b_above) continue;
    // The edge crosses the horizontal line of q; count it when it passes right of q.
    const t2::Sign s = t2::orient(a, b, q);
    if ((b_above && s > 0) || (a_above && s < 0)) inside = !inside;
  }
  return inside ? o : -o;
}

}  // namespace

t2::Sign locate(const std::vector<t2::Point>& P, const t2::Point& q) {
  if (P[0].w() < 0) {
    std::vector<t2::Point> F;
    for (const auto& p : P) F.push_back(t2::antipode(p));
    return -locate_front(F, t2::antipode(q));
  }
  return locate_front(P, q);
}

}  // namespace ex05
