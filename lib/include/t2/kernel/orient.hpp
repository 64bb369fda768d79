#pragma once
/// @file orient.hpp
/// @brief Δ(p, q, r): the orientation of three points of T² (seed 000, §4.3.4).

#include <bit>
#include <cstdint>
#include <type_traits>

#include "t2/kernel/filter.hpp"
#include "t2/kernel/detail/orient_double.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

/// The 3×3 determinant |p; q; r| of homogeneous coordinates, on any number type. The result is
/// an N when the expression converts to one (for GMP numbers this evaluates the expression
/// template before its temporaries die); else, for expansions, which grow with each operation,
/// the expression's own type.
template <class N>
constexpr auto det3(const N& a, const N& b, const N& c, const N& d, const N& e, const N& f, const N& g,
       const N& h, const N& i) {
  using R = decltype(a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g));
  if constexpr (std::is_convertible_v<R, N>) {
    return N(a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g));
  } else {
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  }
}

/// The 3×3 determinant |p; q; r| of three homogeneous triples as the filter passes them (Hom3 of
/// filter.hpp): `sign_of_poly([](const auto& p, const auto& q, const auto& r) { return det3(p, q, r);
/// }, p, q, r)` is orient(p, q, r).
template <class N>
constexpr auto det3(const Hom3<N>& p, const Hom3<N>& q, const Hom3<N>& r) {
  return det3(p.w, p.x, p.y, q.w, q.x, q.y, r.w, r.x, r.y);
}

namespace detail {

/// True when every argument is exactly 1.0: compared as bit patterns, one branch for all.
inline bool all_one(auto... w) {
  constexpr std::uint64_t one = 0x3FF0000000000000;  // the bits of 1.0
  return ((std::bit_cast<std::uint64_t>(static_cast<double>(w)) ^ one) | ...) == 0;
}

/// Δ of three homogeneous triples of doubles: the Cartesian formulas when every w is 1 (three
/// comparisons), the homogeneous ones otherwise (orient_double.hpp).
inline Sign orient_double(double a, double b, double c, double d, double e, double f, double g, double h,
                          double i) {
  if (all_one(a, d, g)) return orient2(b, c, e, f, h, i);
  return orient3(a, b, c, d, e, f, g, h, i);
}

/// Δ of three points that are not all Cartesian: out of line, so that the Cartesian fast path
/// of `orient` keeps only its own loads and operations (about a third of its time otherwise).
[[gnu::noinline]] inline Sign orient_homogeneous(const Point& p, const Point& q, const Point& r) {
  return orient3(p.w(), p.x(), p.y(), q.w(), q.x(), q.y(), r.w(), r.x(), r.y());
}

}  // namespace detail

/// Δ(p, q, r) = sign of the determinant of the three homogeneous triples.
/// POSITIVE when p lies on the positive (left) side of the oriented line q∨r — for three front
/// points this is the usual counter-clockwise turn; ZERO when the three are collinear (which
/// includes p = ±q). Exact for every finite input: on `double` coordinates a fast path with a
/// proven error bound and exact expansion stages (orient_double.hpp); on `Integer` coordinates
/// the same when every coordinate fits in 52 bits (the conversion to double is exact), else
/// sign_of_poly's bound on big integers (filter.hpp), then GMP.
template <class T>
Sign orient(const BasicPoint<T>& p, const BasicPoint<T>& q, const BasicPoint<T>& r) {
  if constexpr (std::is_same_v<T, double>) {
    //> orient-dispatch
    if (detail::all_one(p.w(), q.w(), r.w())) [[likely]]
      return detail::orient2(p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
    return detail::orient_homogeneous(p, q, r);
    //< orient-dispatch
  } else {
    if (detail::fits_filter(p.w()) && detail::fits_filter(p.x()) && detail::fits_filter(p.y()) &&
        detail::fits_filter(q.w()) && detail::fits_filter(q.x()) && detail::fits_filter(q.y()) &&
        detail::fits_filter(r.w()) && detail::fits_filter(r.x()) && detail::fits_filter(r.y()))
      return detail::orient_double(p.w().get_d(), p.x().get_d(), p.y().get_d(), q.w().get_d(), q.x().get_d(),
                                   q.y().get_d(), r.w().get_d(), r.x().get_d(), r.y().get_d());
    return sign_of_poly([](const auto& a, const auto& b, const auto& c) { return det3(a, b, c); }, p, q, r);
  }
}

/// True when p, q, r lie on a common line of T².
template <class T>
bool collinear(const BasicPoint<T>& p, const BasicPoint<T>& q, const BasicPoint<T>& r) {
  return orient(p, q, r) == ZERO;
}

}  // namespace t2
