// Exercise 04b, public tests: run them with `t2 check 04b`.
#include <gtest/gtest.h>

#include "det2.hpp"

namespace {

TEST(Public, SmallIntegers) {
  EXPECT_EQ(ex04b::det2_sign(3, 2, 1, 1), t2::POSITIVE) << "3·1 − 2·1 = 1";
  EXPECT_EQ(ex04b::det2_sign(2, 4, 1, 2), t2::ZERO) << "2·2 − 4·1 = 0";
  EXPECT_EQ(ex04b::det2_sign(0, 1, 1, 5), t2::NEGATIVE) << "0·5 − 1·1 = −1";
}

TEST(Public, ProductsThatRoundTheSameWay) {
  // a·d = (1 + 2⁻⁵²)² = 1 + 2⁻⁵¹ + 2⁻¹⁰⁴ and b·c = 1 + 2⁻⁵¹: both round to 1 + 2⁻⁵¹.
  const double a = 1 + 0x1p-52, b = 1 + 0x1p-51;
  EXPECT_EQ(ex04b::det2_sign(a, b, 1, a), t2::POSITIVE)
      << "a·d − b·c = 2⁻¹⁰⁴ > 0, below the rounding of either product. Hint: "
         "std::fma(a, d, -p) is the rounding error of p = a·d, exactly.";
}

}  // namespace
