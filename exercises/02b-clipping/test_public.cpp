// Exercise 02b, public tests: run them with `t2 check 02b`.
#include <gtest/gtest.h>

#include <t2/kernel/point.hpp>

#include "clip.hpp"

namespace {

using t2::Point;

bool same(const t2::ExactPoint& p, long w, long x, long y) {
  return p.x() * w == p.w() * x && p.y() * w == p.w() * y && p.x() * y == p.y() * x &&
         p.w() * w + p.x() * x + p.y() * y > 0;
}

TEST(Public, AFrontSegmentCutByALine) {
  // From (0, 0) to (4, 0), kept where x ≤ 2: the line ⟨2, -1, 0⟩ is 2w − x ≥ 0.
  const auto r = ex02b::clip(Point(1, 0, 0), Point(1, 4, 0), 2, -1, 0);
  ASSERT_EQ(r.size(), 2u) << "a piece of the segment is kept: its two ends";
  EXPECT_TRUE(same(r[0], 1, 0, 0)) << "it starts at p = (0, 0)";
  EXPECT_TRUE(same(r[1], 1, 2, 0)) << "and ends where the segment crosses x = 2; got " << t2::to_string(r[1]);
}

TEST(Public, TheFrontPartOfASegmentThroughInfinity) {
  // p = (0, 0) on the front, q the back point drawn at (1, 0): the segment leaves the front to
  // the left of p, crosses Ω at [0, -1, 0] and comes back on the back sheet.
  const auto r = ex02b::clip(Point(1, 0, 0), Point(-1, -1, 0), 1, 0, 0);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_TRUE(same(r[1], 0, -1, 0)) << "the front part ends on Ω in direction -x, not at (1, 0) "
                                       "nor at [0, 1, 0]. Hint: chapter 01, section 8; got "
                                    << t2::to_string(r[1]);
}

}  // namespace
