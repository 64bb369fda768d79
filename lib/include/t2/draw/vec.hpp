#pragma once
/// @file vec.hpp
/// @brief The two vector types of the drawing layer: `Vec3` (space, the spherical model) and
/// `Vec2` (the picture: model units or pixels), with the few operations drawing needs.
///
/// Drawing is floating point by nature; nothing here decides a predicate of T².

#include <algorithm>
#include <cmath>

namespace t2::draw {

/// A vector of space (the spherical model): (x, y, w) coordinates of a point of T².
struct Vec3 {
  double x = 0;  ///< first coordinate (the x of [w, x, y])
  double y = 0;  ///< second coordinate (the y of [w, x, y])
  double z = 0;  ///< third coordinate (the w of [w, x, y]: up is the front side)
};

/// A point or vector of the picture plane. In model units (the views' `place` and `project`)
/// x runs to the right and y up; in pixels (`Shape::pts`) x runs to the right and y down.
struct Vec2 {
  double x = 0;  ///< horizontal coordinate
  double y = 0;  ///< vertical coordinate
};

/// a + b.
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
/// a − b.
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
/// s·a.
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
/// −a.
inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
/// The dot product a · b.
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// The cross product a × b.
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// a / |a| for a vector of moderate length (its squared length must not overflow).
inline Vec3 unit(const Vec3& a) {
  const double n = std::sqrt(dot(a, a));
  return {a.x / n, a.y / n, a.z / n};
}
/// a / |a| for a vector of any finite length: scaled by its largest coordinate first, so that
/// coordinates near the limits of double neither overflow nor underflow.
inline Vec3 unit_scaled(const Vec3& a) {
  const double m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
  return unit({a.x / m, a.y / m, a.z / m});
}

/// a + b.
inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
/// a − b.
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
/// s·a.
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
/// −a.
inline Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
/// The dot product a · b.
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// The length |a| (without overflow).
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }
/// a / |a|.
inline Vec2 unit(Vec2 a) { return (1 / norm(a)) * a; }

}  // namespace t2::draw
