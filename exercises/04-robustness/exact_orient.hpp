#pragma once
// Exercise 04: the API you implement in exact_orient.cpp. Do not change this file.
#include <t2/kernel/point_type.hpp>
#include <t2/kernel/sign.hpp>

namespace ex04 {

/// The exact sign of the determinant |p; q; r| of the homogeneous coordinates, for every
/// finite double input (tiny, huge, nearly collinear). Write it yourself: do not call
/// t2::orient or t2::sign_of_poly (t2::to_exact and t2::Integer are allowed).
t2::Sign orient_exact(const t2::Point& p, const t2::Point& q, const t2::Point& r);

}  // namespace ex04
