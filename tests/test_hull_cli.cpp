// t2 gen and t2 hull from the command line: indices, every algorithm, stdin, exit statuses,
// the picture, and reproducible files.
#include "cli_testing.hpp"

namespace t2::testing {
namespace {

class HullCli : public CliTest {};

TEST_F(HullCli, IndicesCounterClockwiseOfTheScenePoints) {
  // A square with a point inside, one inside an edge, a duplicate corner and a labelled corner.
  write("sq.t2", "0 0\n2 0\n1 1\n1 0\n2 4 0\nlabel D 0 2\n2 2\n");
  for (const char* a : {"automatic", "merge", "jarvis", "graham", "quickhull", "monotone", "chan"}) {
    const Result r = t2(std::string("hull sq.t2 --algorithm ") + a);
    EXPECT_EQ(r.status, 0) << a << r.err;
    // The cycle 0 1 6 5 (or 0 4 6 5: 4 is 1 again), from any start.
    std::string cyc = r.out;
    for (auto& c : cyc)
      if (c == '\n') c = ' ';
    const std::string twice = cyc + cyc;
    EXPECT_TRUE(has(twice, "0 1 6 5 ") || has(twice, "0 4 6 5 ")) << a << ": " << r.out;
  }
}

TEST_F(HullCli, StandardInputAndNoHull) {
  Result r = t2("hull -", "0 0\n1 0\n0 1\n");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "0\n1\n2\n");
  r = t2("hull -", "1 1\n3 0 0\n-1 -1 -1\n");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "p0 and p2 are antipodal")) << r.err;
  EXPECT_TRUE(r.out.empty());
  r = t2("hull - --algorithm fast", "0 0\n");
  EXPECT_EQ(r.status, 2);
  r = t2("hull -", "0 0\nsegment\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "<stdin>:2")) << r.err;
}

TEST_F(HullCli, GeneratedBothSidesAndThePicture) {
  Result g = t2("gen both-sides --n 50 --seed 3 -o pts.t2");
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_EQ(t2("gen both-sides --n 50 --seed 3").out, slurp(dir_ / "pts.t2"));  // same bytes
  const Result m = t2("hull pts.t2 --algorithm merge --svg h.svg --model both");
  EXPECT_EQ(m.status, 0) << m.err;
  EXPECT_TRUE(has(slurp(dir_ / "h.svg"), "<svg"));
  const Result j = t2("hull pts.t2 --algorithm jarvis");
  EXPECT_EQ(std::count(m.out.begin(), m.out.end(), '\n'), std::count(j.out.begin(), j.out.end(), '\n'));
  EXPECT_GE(std::count(m.out.begin(), m.out.end(), '\n'), 3);
}

TEST_F(HullCli, GenErrors) {
  EXPECT_EQ(t2("gen nope").status, 2);
  EXPECT_EQ(t2("gen segments --n 4 --crossings 9").status, 2);
  EXPECT_EQ(t2("gen both-sides --back 2").status, 2);
  EXPECT_TRUE(files().empty());
}

}  // namespace
}  // namespace t2::testing
