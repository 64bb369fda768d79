// t2 range from the command line: the four algorithms agree, rectangles on the back and reaching Ω,
// the points of Ω, and the exit statuses of bad and undefined rectangles.
#include "cli_testing.hpp"

namespace t2::testing {
namespace {

class RangeCli : public CliTest {};

// p0..p3 on the front, p4 on the back (drawn at (1, 1)), p5 and p6 on Ω.
constexpr const char* kPoints = "0 0\n1 1\n2 0\n1 1\n-1 -1 -1\n0 1 1\n0 -1 0\n";

TEST_F(RangeCli, ListsAndCountsWithBothAlgorithms) {
  write("p.t2", kPoints);
  write("r.txt",
        "# x0 y0 x1 y1, then w0 x0 y0 w1 x1 y1\n"
        "0 0 1 1\n"           // p0, p1, p3 (corner and duplicate)
        "2 2 -1 -1\n"         // the same set from the other corners: p0 .. p3
        "-1 1 1 -1 -1 -1\n"   // the back square (−1, −1)..(1, 1) as drawn: p4
        "1 0 0 0 1 1\n"       // the front quadrant x, y >= 0 up to Ω: p0 .. p3 and [0, 1, 1]
        "\n"
        "-1 0 0 0 1 1\n");    // the back quadrant towards [0, 1, 1], drawn towards (−, −): [0, 1, 1]
  for (const char* a : {"brute", "kdtree", "rangetree"}) {
    Result r = t2(std::string("range p.t2 r.txt --algorithm ") + a);
    EXPECT_EQ(r.status, 0) << a << r.err;
    EXPECT_EQ(r.out, "0 1 3\n0 1 2 3\n4\n0 1 2 3 5\n5\n") << a;
  }
  Result r;
  for (const char* a : {"brute", "locus", "kdtree", "rangetree"}) {
    r = t2(std::string("range p.t2 r.txt --count --algorithm ") + a);
    EXPECT_EQ(r.status, 0) << a << r.err;
    EXPECT_EQ(r.out, "3\n4\n1\n5\n1\n") << a;
  }
}

// The rectangle is made from its corners as written: x1 is 1, not x0 + (x1 − x0) rounded in
// doubles (here 1e16 + 1 rounds to an even number, and the far side would move to 0 or 2).
TEST_F(RangeCli, TheCornersAreTakenExactly) {
  write("p.t2", "0.5 0.5\n1 0.5\n1.5 0.5\n");
  write("r.txt", "-1e16 0 1 1\n");
  for (const char* a : {"brute", "locus", "kdtree", "rangetree"}) {
    const Result r = t2(std::string("range p.t2 r.txt --count --algorithm ") + a);
    EXPECT_EQ(r.out, "2\n") << a << r.err;
  }
  EXPECT_EQ(t2("range p.t2 r.txt --algorithm kdtree").out, "0 1\n");
}

TEST_F(RangeCli, BadLinesExitTwoAndUndefinedRectanglesExitThree) {
  write("p.t2", kPoints);
  write("bad.txt", "0 0 1 1\n0 0 1\n");
  Result r = t2("range p.t2 bad.txt");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "bad.txt:2:")) << r.err;
  write("word.txt", "0 0 one 1\n");
  r = t2("range p.t2 word.txt");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "word.txt:1:")) << r.err;
  write("sides.txt", "1 0 0 -1 1 1\n");  // corners on both sides
  r = t2("range p.t2 sides.txt --count");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "sides.txt:1:")) << r.err;
  r = t2("range p.t2 sides.txt --algorithm locus");
  EXPECT_EQ(r.status, 2) << "locus without --count";
}

}  // namespace
}  // namespace t2::testing
