#pragma once
// Exercise 06: the API you implement in hemisphere.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex06 {

/// An open hemisphere that holds every point of P, as the coefficients [W, X, Y] of a line of
/// T² (returned in an ExactPoint: its w(), x(), y() are W, X, Y) with W·w + X·x + Y·y > 0 exactly
/// for every point [w, x, y] of P. P is not empty; its points may lie on the front, on the back
/// and on Ω, and may repeat. Throws t2::Undefined when no open hemisphere holds P.
t2::ExactPoint hemisphere(const std::vector<t2::Point>& P);

/// A certificate that no open hemisphere holds P: the indices (0-based, different) of two,
/// three or four points of P for which some combination Σ λᵢ pᵢ with λᵢ ≥ 0, not all zero, is the
/// zero vector. Empty when an open hemisphere holds P. P is not empty.
std::vector<long> witness(const std::vector<t2::Point>& P);

}  // namespace ex06
