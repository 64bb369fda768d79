// Exercise 01b, public tests: run them with `t2 check 01b`.
#include <gtest/gtest.h>

#include "order.hpp"

namespace {

TEST(Public, FrontNumbersInTheirUsualOrder) {
  EXPECT_EQ(ex01b::compare(1, 2, 1, 3), t2::NEGATIVE) << "the front 2 comes before the front 3";
  EXPECT_EQ(ex01b::compare(2, 6, 1, 3), t2::ZERO) << "[2, 6] and [1, 3] are one point, the front 3";
  EXPECT_EQ(ex01b::compare(1, 0, 1, 5), t2::NEGATIVE) << "the order starts at the front zero [1, 0]";
}

TEST(Public, InfinityAndTheBackCopy) {
  EXPECT_EQ(ex01b::compare(1, 1e9, 0, 1), t2::NEGATIVE)
      << "+inf = [0, 1] comes after every positive front number";
  EXPECT_EQ(ex01b::compare(-1, -3, 1, 3), t2::POSITIVE)
      << "[-1, -3] is the back 3, half a turn after the front 3. Hint: draw (w, x) as a vector "
         "and go round counter-clockwise from (1, 0).";
}

}  // namespace
