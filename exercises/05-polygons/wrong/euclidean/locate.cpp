// Wrong on purpose: the textbook Euclidean ray casting on Cartesian coordinates x/w, y/w.
// It answers "inside" (+1) whatever the orientation, takes a back point for the front point
// with the same Cartesian coordinates, and calls every point at infinity "outside".
#include "locate.hpp"

namespace ex05 {

t2::Sign locate(const std::vector<t2::Point>& P, const t2::Point& q) {
  if (q.w() == 0) return t2::NEGATIVE;
  const double qx = q.x() / q.w(), qy = q.y() / q.w();
  bool inside = false;
  for (size_t i = 0, j = P.size() - 1; i < P.size(); j = i++) {
    const double xi = P[i].x() / P[i].w(), yi = P[i].y() / P[i].w();
    const double xj = P[j].x() / P[j].w(), yj = P[j].y() / P[j].w();
    if ((yi - qy) * (xj - xi) == (xi - qx) * (yj - yi) && (xi - qx) * (xj - qx) <= 0 && (yi - qy) * (yj - qy) <= 0)
      return t2::ZERO;
    if ((yi > qy) != (yj > qy) && qx < (xj - xi) * (qy - yi) / (yj - yi) + xi) inside = !inside;
  }
  return inside ? t2::POSITIVE : t2::NEGATIVE;
}

}  // namespace ex05
