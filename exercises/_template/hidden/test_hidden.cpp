// Exercise NN, hidden tests.
#include <gtest/gtest.h>

#include "api.hpp"

namespace {

TEST(Hidden, Example) { EXPECT_FALSE(exNN::example(t2::Point(0, 1, 0))); }

}  // namespace
