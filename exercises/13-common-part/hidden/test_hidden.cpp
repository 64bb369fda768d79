// Exercise 13, hidden tests. Oracle: the library's exact intersection of two segments
// (segment.hpp's `intersection` on big-integer points, which the solution may not call), and
// every answered point is also checked to lie on both segments (`contains`, exact). Inputs: back
// segments, segments through and on Ω, pairs whose lines meet at a point of one segment and
// the antipode of the other, collinear pieces, shared endpoints and one-point segments, and
// random segments with endpoints on both sides and on Ω.
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <variant>

#include <t2/kernel/point.hpp>
#include <t2/kernel/segment.hpp>

#include "common.hpp"

namespace {

using t2::ExactPoint;
using t2::Point;

// "" when ex13::common(a, b, c, d) is the common part of the two segments, else what is wrong.
std::string judge(const Point& a, const Point& b, const Point& c, const Point& d) {
  const t2::ExactSegment s(t2::to_exact(a), t2::to_exact(b)), t(t2::to_exact(c), t2::to_exact(d));
  const auto want = t2::intersection(s, t);
  const auto got = ex13::common(a, b, c, d);
  std::ostringstream why;
  why << t2::to_string(s) << " and " << t2::to_string(t) << ": ";
  for (const auto& p : got)
    if (!t2::contains(s, p) || !t2::contains(t, p)) return why.str() + "a point not on both segments";
  if (std::holds_alternative<std::monostate>(want))
    return got.empty() ? "" : why.str() + "they do not meet";
  if (const auto* p = std::get_if<ExactPoint>(&want))
    return got.size() == 1 && got[0] == *p ? "" : why.str() + "they meet in one point";
  const auto& piece = std::get<t2::ExactSegment>(want);
  if (got.size() != 2) return why.str() + "they share a piece";
  const bool same = (got[0] == piece.source() && got[1] == piece.target()) ||
                    (got[1] == piece.source() && got[0] == piece.target());
  return same ? "" : why.str() + "the ends of the shared piece";
}

TEST(Hidden, BackSide) {
  // Two back segments crossing; a front and a back segment whose drawings cross; a back
  // segment and a front one sharing no point though [-1, 0, 0] and [1, 0, 0] are drawn alike.
  EXPECT_EQ(judge(Point(-2, 0, 0), Point(-2, -8, -4), Point(-1, 0, -2), Point(-1, -4, 0)), "");
  EXPECT_EQ(judge(Point::cartesian(0, 0), Point::cartesian(4, 2), Point(-1, 0, -2), Point(-1, -4, 0)), "");
  EXPECT_EQ(judge(Point(-1, 0, 0), Point(-1, -3, 1), Point::cartesian(0, 0), Point::cartesian(5, 5)), "");
  EXPECT_EQ(judge(Point(-3, -3, 0), Point(-3, 3, 0), Point(-1, 0, 1), Point(-1, 0, -1)), "");
}

TEST(Hidden, ThroughAndOnOmega) {
  // From the front point (0, -2) down through [0, 0, -1] to the back point [-1, 0, -2] (drawn at
  // (0, 2), reached from above); a back segment crossing its back part; a quarter of Ω; a front
  // segment its drawing crosses; pieces of Ω; rays towards Ω from both sides.
  const Point up0 = Point::cartesian(0, -2), up1(-1, 0, -2);
  EXPECT_EQ(judge(up0, up1, Point(-1, -1, -3), Point(-1, 1, -3)), "");
  EXPECT_EQ(judge(up0, up1, Point::at_infinity(1, 0), Point::at_infinity(0, 1)), "");
  EXPECT_EQ(judge(up0, up1, Point::cartesian(-1, 1), Point::cartesian(1, 1)), "");  // drawn across, but on the front
  EXPECT_EQ(judge(Point::at_infinity(1, 0), Point::at_infinity(1, 3), Point::at_infinity(1, 1), Point::at_infinity(-1, 7)), "");
  EXPECT_EQ(judge(Point::cartesian(1, 1), Point::at_infinity(1, 1), Point::cartesian(5, 0), Point::cartesian(5, 30)), "");
  EXPECT_EQ(judge(Point::cartesian(1, 1), Point::at_infinity(1, 1), Point(-1, 5, 0), Point(-1, 5, 30)), "");
}

TEST(Hidden, AntipodalCrossings) {
  // The lines meet at ±L; L lies on one segment and ¬L on the other: in the plane's straddle
  // test the four orientations agree, in T² the segments do not meet.
  EXPECT_EQ(judge(Point::cartesian(-1, 0), Point::cartesian(1, 0), Point(-1, 0, 1), Point(-1, 0, -1)), "");
  EXPECT_EQ(judge(Point::cartesian(-1, 0), Point::cartesian(1, 0), Point::cartesian(0, -1), Point::cartesian(0, 1)), "");
  EXPECT_EQ(judge(Point(-1, 3, 1), Point::cartesian(2, 2), Point::cartesian(0, 7), Point(-3, 1, 1)), "");
  EXPECT_EQ(judge(Point::at_infinity(1, 0), Point::at_infinity(0, 1), Point::at_infinity(-1, -1), Point::cartesian(0, 0)), "");
  EXPECT_EQ(judge(Point::at_infinity(1, 0), Point::at_infinity(0, 1), Point::at_infinity(1, 1), Point::cartesian(0, 0)), "");
}

TEST(Hidden, CollinearPieces) {
  // Overlap without a shared endpoint; one inside the other; a shared endpoint only; collinear
  // and disjoint; one-point segments on and off a segment; a piece across Ω; antipodal pieces.
  EXPECT_EQ(judge(Point::cartesian(0, 0), Point::cartesian(4, 4), Point::cartesian(6, 6), Point::cartesian(1, 1)), "");
  EXPECT_EQ(judge(Point::cartesian(0, 0), Point::cartesian(8, 4), Point(2, 4, 2), Point(2, 12, 6)), "");
  EXPECT_EQ(judge(Point::cartesian(0, 0), Point::cartesian(3, 0), Point::cartesian(3, 0), Point::cartesian(7, 0)), "");
  EXPECT_EQ(judge(Point::cartesian(0, 0), Point::cartesian(3, 0), Point::cartesian(4, 0), Point::cartesian(7, 0)), "");
  EXPECT_EQ(judge(Point(4, 8, 4), Point(4, 8, 4), Point::cartesian(0, 0), Point::cartesian(4, 2)), "");
  EXPECT_EQ(judge(Point::cartesian(2, 1), Point::cartesian(2, 1), Point(-1, 0, 0), Point(-1, -4, -2)), "");
  EXPECT_EQ(judge(Point::cartesian(0, 0), Point(-1, -2, 0), Point::cartesian(3, 0), Point(-1, -7, 0)), "");
  EXPECT_EQ(judge(Point::cartesian(1, 0), Point::cartesian(5, 0), Point(-1, -2, 0), Point(-1, -4, 0)), "");
}

TEST(Hidden, RandomAgainstTheLibrary) {
  // Small integer coordinates (many collinear and shared points), w in {-2, -1, 0, 1, 2}.
  std::mt19937_64 g(1313);
  auto pick = [&] {
    for (;;) {
      const double w = double(int(g() % 5) - 2), x = double(int(g() % 7) - 3), y = double(int(g() % 7) - 3);
      if (w != 0 || x != 0 || y != 0) return Point(w, x, y);
    }
  };
  int n = 0;
  for (int k = 0; k < 3000; ++k) {
    const Point a = pick(), c = pick();
    const Point b = g() % 8 == 0 ? a : pick(), d = g() % 8 == 0 ? c : pick();
    if (b == t2::antipode(a) || d == t2::antipode(c)) continue;
    const std::string e = judge(a, b, c, d);
    EXPECT_EQ(e, "");
    if (!e.empty() && ++n > 3) break;
  }
}

}  // namespace
