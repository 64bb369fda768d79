// t2 layers, t2 diameter and t2 kernel from the command line: output formats, stdin, pictures,
// exit statuses (2 bad input with file:line, 3 undefined in T²).
#include "cli_testing.hpp"

namespace t2::testing {
namespace {

class CalipersCli : public CliTest {};

TEST_F(CalipersCli, LayersOnePerLine) {
  // A square, a triangle inside it, a point in the middle; a point inside an outer edge.
  write("l.t2", "0 0\n6 0\n6 6\n0 6\n3 0\n2 2\n4 2\n3 4\n3 3\n");
  for (const char* m : {"jarvis", "graham"}) {
    const Result r = t2(std::string("layers l.t2 --method ") + m + " --svg l.svg --model plane");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 3) << r.out;
    EXPECT_EQ(r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1), "8\n") << r.out;  // the centre, alone
    EXPECT_TRUE(has(r.out, "4 6 7 5") || has(r.out, "6 7 5 4") || has(r.out, "7 5 4 6") || has(r.out, "5 4 6 7"))
        << r.out;  // the point inside the square's edge opens the second layer
    EXPECT_TRUE(has(slurp(dir_ / "l.svg"), "<svg"));
  }
  const Result bad = t2("layers -", "1 1\n3 0 0\n-1 -1 -1\n");
  EXPECT_EQ(bad.status, 3);
  EXPECT_TRUE(has(bad.err, "p0 and p2 are antipodal")) << bad.err;
  EXPECT_EQ(t2("layers -", "0 0\npolygon\n").status, 2);
  EXPECT_EQ(t2("layers -", "").out, "");
}

TEST_F(CalipersCli, DiameterAndWidth) {
  write("d.t2", "0 0\n4 0\n4 1\n0 1\n2 0.5\n");
  Result r = t2("diameter d.t2 --svg d.svg");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out == "0 2\nsquared-distance [1, 17]\nwidth 0 1 2\n" || has(r.out, "1 3\nsquared-distance [1, 17]\n"))
      << r.out;
  EXPECT_TRUE(has(r.out, "\nwidth ")) << r.out;
  EXPECT_TRUE(has(slurp(dir_ / "d.svg"), "<svg"));
  r = t2("diameter -", "0 0\n10 0\n-1 -3 0\n-1 -9 0\n");  // front and back: beyond infinity
  EXPECT_EQ(r.out, "1 3\nsquared-distance [-1, 1]\n");
  r = t2("diameter -", "0 0\n0 1 0\n");  // +infinity from a point of Omega
  EXPECT_EQ(r.out, "0 1\nsquared-distance [0, 1]\n");
  r = t2("diameter -", "0 0\n0 1 0\n0 0 1\n");
  EXPECT_EQ(r.status, 3);
  EXPECT_TRUE(has(r.err, "Omega")) << r.err;
  EXPECT_EQ(t2("diameter -", "").out, "");
  EXPECT_EQ(t2("diameter -", "1 2\n2 2 4\n").out, "0 0\nsquared-distance [1, 0]\n");
}

TEST_F(CalipersCli, KernelOfAPolygonBlock) {
  Result r = t2("kernel - --svg k.svg --model both",
                "polygon\n0 0\n4 0\n3 2\n4 4\n0 4\n1 2\nend\n");  // an hourglass: a rhombus
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(r.out, "bounded\n")) << r.out;
  EXPECT_TRUE(has(r.out, "1 2 0\n") && has(r.out, "1 3 2\n") && has(r.out, "1 2 4\n") && has(r.out, "1 1 2\n")) << r.out;
  EXPECT_TRUE(has(slurp(dir_ / "k.svg"), "<svg"));
  r = t2("kernel -", "polygon\n0 0\n0 1 0\n0 0 1\nend\n");  // the quadrant: unbounded
  // +y and +x on Omega, the origin: counter-clockwise from the least corner in the wxy order
  EXPECT_EQ(r.out, "unbounded\n0 0 1\n1 0 0\n0 1 0\n");
  r = t2("kernel -", "polygon\n0 0\n5 0\n5 3\n4 3\n4 1\n1 1\n1 3\n0 3\nend\n");  // a U
  EXPECT_EQ(r.out, "empty\n");
  r = t2("kernel -", "polygon\n0 0\n1 0\n-1 0 1\nend\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "<stdin>:1:")) << r.err;
  r = t2("kernel -", "0 0\n");
  EXPECT_EQ(r.status, 2);
  r = t2("kernel -", "polygon\n0 0\n1 0\n0 1\nend\npolygon\n0 0\n1 0\n0 1\nend\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "<stdin>:6:")) << r.err;
}

}  // namespace
}  // namespace t2::testing
