#pragma once
/// @file number.hpp
/// @brief The coordinate types of the library: `double` for input, GMP integers for exact
/// constructions, GMP rationals as the oracle of the exact predicates.
///
/// T² needs no division: join, meet, midpoint and intersection are polynomials in the
/// homogeneous coordinates. With `Integer` coordinates every construction is exact; with
/// `double` coordinates constructions round (like CGAL's "exact predicates, inexact
/// constructions" kernel), but every predicate still returns the exact sign of its input.

#include <gmpxx.h>

#include <cmath>
#include <string>

#include "t2/kernel/error.hpp"
#include "t2/kernel/sign.hpp"

namespace t2 {

/// Arbitrary-precision integer (GMP).
using Integer = mpz_class;
/// Arbitrary-precision rational (GMP); every finite `double` converts to it exactly.
using Rational = mpq_class;

/// The sign of a GMP integer.
inline Sign sign_of(const Integer& v) { return static_cast<Sign>(sgn(v)); }
/// The sign of a GMP rational.
inline Sign sign_of(const Rational& v) { return static_cast<Sign>(sgn(v)); }

/// The exact rational value of a finite double.
Rational to_rational(double v);

/// Decimal text of a double: the shortest form that reads back exactly; -0 prints as 0.
std::string to_string(double v);
/// Decimal text of an integer.
std::string to_string(const Integer& v);

/// Checks that a coordinate is finite; throws BadInput naming `what` otherwise.
void require_finite(double v, const char* what);
/// Integers are always finite.
inline void require_finite(const Integer&, const char*) {}

}  // namespace t2
