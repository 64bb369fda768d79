// Exercise NN, public tests.
#include <gtest/gtest.h>

#include "api.hpp"

namespace {

TEST(Public, Example) {
  EXPECT_TRUE(exNN::example(t2::Point(-1, 0, 0))) << "hint: say what to check";
}

}  // namespace
