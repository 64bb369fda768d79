#pragma once
// Exercise 04b: the API you implement in det2.cpp. Do not change this file.
#include <t2/kernel/sign.hpp>

namespace ex04b {

/// The exact sign of a·d − b·c for finite doubles whose absolute values are 0 or between 2⁻⁴⁰⁰
/// and 2⁴⁰⁰ (so no product overflows and no rounding error underflows). Use doubles only: no
/// big integers, no rationals, no wider floating-point type (see exercise.txt).
t2::Sign det2_sign(double a, double b, double c, double d);

}  // namespace ex04b
