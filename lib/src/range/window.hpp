#pragma once
// A query rectangle as the range structures compare it (kdtree.cpp, range_tree.cpp): four
// exact bounds on drawn coordinates, each able to answer "bound ≤ x/w?" and "x/w ≤ bound?"
// exactly and, for the usual input w = 1, with one comparison of doubles.
//
// Why one comparison of doubles is exact. Let B be a bound (an exact rational, a T¹ value) and
// x a double. Then x ≤ B iff x ≤ ⌊B⌋, the largest double not above B: if x ≤ ⌊B⌋ then x ≤ B;
// if x ≤ B then x is a double not above B, so x ≤ ⌊B⌋ by maximality. Likewise B ≤ x iff
// ⌈B⌉ ≤ x. The two neighbours are found once per query (GMP); then no comparison rounds.
// For w ≠ 1 the same neighbours filter the exact test: x/w ≤ ⌊B⌋ decides "yes", x/w > ⌈B⌉
// decides "no" (both by the kernel's exact T¹ compare on doubles), and only x/w strictly
// between the two neighbours of a B that is not a double goes to big integers.

#include <cstdint>

#include "t2/kernel/bbox.hpp"
#include "t2/kernel/t1.hpp"
#include "t2/range/drawn.hpp"

namespace t2::range {

/// One end of an interval of drawn coordinates: an extended value (T¹, w ≥ 0).
class Bound {
 public:
  explicit Bound(const ExactT1& v);
  /// Is this bound ≤ x/w (w > 0)?
  bool at_most(double x, double w) const {
    if (w == 1) return ceil_ <= x;
    return slow_at_most(x, w);
  }
  /// Is x/w ≤ this bound (w > 0)?
  bool at_least(double x, double w) const {
    if (w == 1) return x <= floor_;
    return slow_at_least(x, w);
  }
  /// True for −∞ (w = 0, x < 0).
  bool minus_infinity() const { return v_.w() == 0 && v_.x() < 0; }
  /// True for +∞.
  bool plus_infinity() const { return v_.w() == 0 && v_.x() > 0; }

 private:
  bool slow_at_most(double x, double w) const;
  bool slow_at_least(double x, double w) const;
  ExactT1 v_;
  double floor_, ceil_;  // the largest double ≤ v and the smallest ≥ v (±inf beyond)
};

/// The closed rectangle [lo[0], hi[0]] × [lo[1], hi[1]] of drawn coordinates on one side.
struct Window {
  int side;         ///< 0 front, 1 back: the side of the box's corner
  Bound lo[2], hi[2];  ///< per axis (0 x, 1 y)

  /// The window of the box b's proper part.
  explicit Window(const ExactBBox& b);
  /// Is the drawn point in the closed window?
  bool contains(const DrawnPoint& p) const {
    return lo[0].at_most(p.x, p.w) && hi[0].at_least(p.x, p.w) && lo[1].at_most(p.y, p.w) &&
           hi[1].at_least(p.y, p.w);
  }
};

/// The sign of a.c − b.c for coordinate `axis` (0 x, 1 y) of two drawn points, exactly.
inline Sign compare_axis(const DrawnPoint& a, const DrawnPoint& b, int axis) {
  const double ca = axis ? a.y : a.x, cb = axis ? b.y : b.x;
  if (a.w == b.w) return ca < cb ? NEGATIVE : cb < ca ? POSITIVE : ZERO;  // same positive weight
  return compare(T1(a.w, ca), T1(b.w, cb));
}

/// The composite order of de Berg et al. (§5.5): by `axis`, then by the other axis, then by
/// index. No two points are equal in it, which is what the kd-tree's √n bound needs.
inline bool composite_less(const DrawnPoint& a, const DrawnPoint& b, int axis) {
  Sign s = compare_axis(a, b, axis);
  if (s == ZERO) s = compare_axis(a, b, 1 - axis);
  return s == ZERO ? a.index < b.index : s == NEGATIVE;
}

}  // namespace t2::range
