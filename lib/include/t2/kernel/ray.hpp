#pragma once
/// @file ray.hpp
/// @brief Rays of T² (seed 000, §4.1.4): segments with one end at infinity.
///
/// A ray leaves a proper point p and ends at a point of Ω, its direction. In the planar
/// model it is the usual half-line of p's side, drawn up to the horizon. Because it is a
/// segment, `contains` is `on_segment` and a ray's image under an affine map is a ray.

#include <string>
#include <utility>

#include "t2/kernel/error.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/kernel/vector.hpp"

namespace t2 {

/// The ray from the proper point `source()` to the point at infinity `target()`.
template <class T>
class BasicRay {
 public:
  using Coordinate = T;  ///< the number type of the coordinates

  /// The ray from p in direction d. Throws `Undefined` when p is on Ω (from a point at
  /// infinity the segment to d would be an arc of Ω, not a ray).
  BasicRay(BasicPoint<T> p, const BasicDirection<T>& d) : p_(std::move(p)), d_(d) {
    if (p_.w() == 0) throw Undefined("ray(p, d) is undefined when p is at infinity");
  }
  /// The ray from p to the point at infinity d (a point of Ω). Throws `Undefined` when p
  /// is on Ω or d is not.
  BasicRay(BasicPoint<T> p, const BasicPoint<T>& d) : BasicRay(std::move(p), BasicDirection<T>(d)) {}
  /// The ray from p through q: p's direction towards q (see `direction(p, q)`). For q on the
  /// other side of T² the ray passes Ω before reaching q, so q is not on it. Throws
  /// `Undefined` when p is on Ω, or q = p, or q = ¬p.
  static BasicRay through(const BasicPoint<T>& p, const BasicPoint<T>& q) {
    if (p.w() == 0) throw Undefined("ray(p, q) is undefined when p is at infinity");
    return BasicRay(p, t2::direction(p, q));
  }
  const BasicPoint<T>& source() const { return p_; }             ///< the proper end
  BasicPoint<T> target() const { return d_.point(); }            ///< the end on Ω
  const BasicDirection<T>& direction() const { return d_; }      ///< the direction
  /// The ray as a segment (a proper point and a point at infinity are never antipodal).
  BasicSegment<T> segment() const { return BasicSegment<T>(p_, d_.point()); }

 private:
  BasicPoint<T> p_;
  BasicDirection<T> d_;
};

/// Rays with `double` coordinates.
using Ray = BasicRay<double>;
/// Rays with big-integer coordinates.
using ExactRay = BasicRay<Integer>;

/// Is r on the ray (source and end at infinity included)? Exact.
template <class T>
bool contains(const BasicRay<T>& ray, const BasicPoint<T>& r) {
  return contains(ray.segment(), r);
}

/// Equal rays: same source, same direction.
template <class T>
bool operator==(const BasicRay<T>& a, const BasicRay<T>& b) {
  return a.source() == b.source() && a.direction() == b.direction();
}

/// "ray([w, x, y] -> [0, dx, dy])".
template <class T>
std::string to_string(const BasicRay<T>& r) {
  return "ray(" + to_string(r.source()) + " -> " + to_string(r.target()) + ")";
}

}  // namespace t2
