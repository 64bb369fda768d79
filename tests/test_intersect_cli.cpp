// t2 intersect from the command line: the line format, both algorithms, stdin, exit statuses
// and the picture.
#include "cli_testing.hpp"

namespace t2::testing {
namespace {

class IntersectCli : public CliTest {};

// Two crossing segments, a third overlapping the first from the crossing on, and a zero-length
// one at the crossing.
constexpr const char* kScene =
    "segment\n0 0\n2 2\nend\n"
    "segment\n0 2\n2 0\nend\n"
    "segment\n2 2 2\n3 3\nend\n"
    "segment\n1 1\n1 1\nend\n";

TEST_F(IntersectCli, OneLinePerPointWithEverySegmentThroughIt) {
  write("x.t2", kScene);
  for (const char* a : {"sweep", "brute"}) {
    const Result r = t2(std::string("intersect x.t2 --algorithm ") + a);
    EXPECT_EQ(r.status, 0) << a << r.err;
    EXPECT_EQ(r.out, "1 1 1  0 1 2 3\n1 2 2  0 2\n") << a;  // 2 overlaps 0 from (1, 1) to (2, 2)
  }
  const Result r = t2("intersect - --svg x.svg --model plane", kScene);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(slurp(dir_ / "x.svg"), "<svg")) << "no picture";
}

TEST_F(IntersectCli, BackSegmentsAreForTheBruteForceAndBadFilesExitTwo) {
  const std::string back = "segment\n-1 0 0\n-1 2 2\nend\nsegment\n-1 0 2\n-1 2 0\nend\n";
  Result r = t2("intersect -", back);
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "front segments only")) << r.err;
  r = t2("intersect - --algorithm brute", back);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "-1 1 1  0 1\n");
  r = t2("intersect -", "segment\n0 0\nend\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "<stdin>:")) << r.err;
}

}  // namespace
}  // namespace t2::testing
