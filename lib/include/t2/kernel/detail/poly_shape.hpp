#pragma once
/// @file poly_shape.hpp
/// @brief What filter.hpp derives about a predicate's polynomial ahead of time: the shape of
/// the polynomial (monomial count, roundings, degrees per argument) and the error bound made
/// from it. The theorem and its proof are in filter.hpp's file comment.

#include <array>
#include <cmath>
#include <cstddef>

namespace t2::detail {
/// The most arguments a filtered polynomial takes.
inline constexpr int kMaxPolyArgs = 32;

/// What the filter derives about a polynomial ahead of time (see filter.hpp's file comment): the
/// lambda evaluated on these instead of numbers, once, at compile time.
struct PolyShape {
  double count = 0;  ///< the number of monomials of the tree multiplied out
  int depth = 0;     ///< the most roundings any monomial meets (k)
  double ops = 0;    ///< the number of operations of the tree
  std::array<int, kMaxPolyArgs> degree{};  ///< the degree dᵢ in each argument
  int total = 0;              ///< the total degree D
  bool per_argument = true;   ///< every monomial has the degrees `degree`
  bool homogeneous = true;    ///< every monomial has the total degree `total`

  /// A coordinate of argument i.
  static constexpr PolyShape leaf(std::size_t i) {
    PolyShape s;
    s.count = 1;
    s.degree[i] = 1;
    s.total = 1;
    return s;
  }
  /// Sum: one more rounding; the degrees must agree.
  friend constexpr PolyShape operator+(const PolyShape& a, const PolyShape& b) { return sum(a, b); }
  /// Difference: as a sum.
  friend constexpr PolyShape operator-(const PolyShape& a, const PolyShape& b) { return sum(a, b); }
  /// Negation: exact.
  friend constexpr PolyShape operator-(const PolyShape& a) { return a; }
  /// Product: the roundings of both factors plus one; the degrees add.
  friend constexpr PolyShape operator*(const PolyShape& a, const PolyShape& b) {
    PolyShape r;
    r.count = a.count * b.count;
    r.depth = a.depth + b.depth + 1;
    r.ops = a.ops + b.ops + 1;
    for (int i = 0; i < kMaxPolyArgs; ++i) r.degree[i] = a.degree[i] + b.degree[i];
    r.total = a.total + b.total;
    r.per_argument = a.per_argument && b.per_argument;
    r.homogeneous = a.homogeneous && b.homogeneous;
    return r;
  }

 private:
  /// A sum or difference of a and b.
  static constexpr PolyShape sum(const PolyShape& a, const PolyShape& b) {
    PolyShape r = a;
    r.count = a.count + b.count;
    r.depth = (a.depth > b.depth ? a.depth : b.depth) + 1;
    r.ops = a.ops + b.ops + 1;
    r.per_argument = a.per_argument && b.per_argument && a.degree == b.degree;
    r.homogeneous = a.homogeneous && b.homogeneous && a.total == b.total;
    return r;
  }
};

/// The error bound of a polynomial, derived from its PolyShape (see filter.hpp's file comment).
struct StaticBound {
  double c = HUGE_VAL;                     ///< C = count·k·u·(1 + 2⁻⁴⁰); +∞ when there is no bound
  double c2 = HUGE_VAL;                    ///< C₂ = k·u·(1 + 2⁻⁴⁰) of the semi-static bound
  double c3 = HUGE_VAL;                    ///< C₃ = (k + 3D)·u·(1 + 2⁻⁴⁰): the same on big integers
  std::array<int, kMaxPolyArgs> degree{};  ///< the exponent dᵢ of each argument's maximum
  bool per_argument = false;               ///< false: one maximum M of all, to the power `total`
  int total = 0;                           ///< the total degree D
  double count = 0;                        ///< the number of monomials
  double range = 0;                        ///< 2ᴿ, R = ⌊900/D⌋: the maxima must lie in [1/range, range]
};
}  // namespace t2::detail
