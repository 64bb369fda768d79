// `t2 info`: runs the built tool on good and bad scene files and checks stdout, stderr and the
// exit status. Expected sides and coordinates are computed by hand or by the rational oracle.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_testing.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

namespace fs = std::filesystem;

using testing::has;
using testing::Result;
using testing::slurp;

class CliInfo : public testing::CliTest {};


TEST_F(CliInfo, SidesNormalizedAndCartesianCoordinates) {
  write("s.t2",
        "# three sides\n"
        "4 8 -4\n"       // [4, 8, -4] = [1, 2, -1]: front, at (2, -1)
        "-2 4 6\n"       // back, normalized [-1, 2, 3], at (4/-2, 6/-2) = (-2, -3)
        "0 -3 1.5\n"     // at infinity, normalized [0, -1, 0.5]
        "label Q 0.5 0.25\n");
  const Result r = t2("info s.t2");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(has(r.out, "s.t2: 4 points, 0 segments, 0 polygons\n")) << r.out;
  std::istringstream lines(r.out);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(lines, line))
    if (line.starts_with("#")) rows.push_back(line);
  ASSERT_EQ(rows.size(), 4u) << r.out;
  auto row_has = [&](int i, std::initializer_list<const char*> parts) {
    for (const char* p : parts) EXPECT_TRUE(has(rows[i], p)) << "row " << i << ": " << rows[i] << "\nwant: " << p;
  };
  row_has(0, {"#1", " 2 ", "front", "[1, 2, -1]", "(2, -1)"});
  row_has(1, {"#2", " 3 ", "back", "[-1, 2, 3]", "(-2, -3)"});
  row_has(2, {"#3", " 4 ", "infinity", "[0, -1, 0.5]"});
  EXPECT_FALSE(has(rows[2], "(")) << "a point at infinity has no Cartesian coordinates: " << rows[2];
  row_has(3, {"#4", " 5 ", " Q ", "front", "[1, 0.5, 0.25]", "(0.5, 0.25)"});
  EXPECT_FALSE(has(r.out, "orient")) << "no --pairs, no orientations";
}

TEST_F(CliInfo, CoordinatesThatOverflowADoubleAreSaidSo) {
  // Valid points whose x/w does not fit in a double: the point is still listed, its side and
  // orientations are still exact.
  write("o.t2", "1e-300 1e300 0\n-4.9406564584124654e-324 1 1\n1 2\n");
  const Result r = t2("info --pairs o.t2");
  EXPECT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line;
  int rows = 0;
  while (std::getline(lines, line)) {
    if (line.starts_with("#1") || line.starts_with("#2")) {
      ++rows;
      EXPECT_TRUE(has(line, line.starts_with("#1") ? "front" : "back")) << line;
      EXPECT_TRUE(has(line, "(overflows double)")) << line;
      EXPECT_FALSE(has(line, "inf ") || has(line, "inf]") || has(line, "inf)")) << line;
    }
  }
  EXPECT_EQ(rows, 2) << r.out;
  const Point a(1e-300, 1e300, 0), b(-4.9406564584124654e-324, 1, 1), c(1, 1, 2);
  const Sign s = testing::sign_oracle(testing::det3_oracle(a, b, c));
  EXPECT_TRUE(has(r.out, std::string("orient(#1, #2, #3) = ") + (s > 0 ? "+1" : s < 0 ? "-1" : "0"))) << r.out;
}

TEST_F(CliInfo, PairsGiveTheExactOrientationOfConsecutiveTriples) {
  // Nearly collinear front points (the naive double determinant misjudges such triples) and
  // points of every side; the expected signs come from the rational oracle.
  const Point pts[] = {Point(1, 0.1, 0.1), Point(1, 0.2, 0.2), Point(1, 0.30000000000000004, 0.3),
                       Point(-1, 3, 1), Point(0, 1, -2), Point(2, 0.2, 0.2)};
  std::string text;
  for (const auto& p : pts) text += to_string(p.w()) + " " + to_string(p.x()) + " " + to_string(p.y()) + "\n";
  write("p.t2", text);
  const Result r = t2("info --pairs p.t2");
  ASSERT_EQ(r.status, 0) << r.err;
  for (int i = 0; i + 2 < 6; ++i) {
    const Sign s = testing::sign_oracle(testing::det3_oracle(pts[i], pts[i + 1], pts[i + 2]));
    const std::string want = "orient(#" + std::to_string(i + 1) + ", #" + std::to_string(i + 2) + ", #" +
                             std::to_string(i + 3) + ") = " + (s > 0 ? "+1" : s < 0 ? "-1" : "0") +
                             "   (lines " + std::to_string(i + 1) + ", " + std::to_string(i + 2) + ", " +
                             std::to_string(i + 3) + ")\n";
    EXPECT_TRUE(has(r.out, want)) << r.out << "\nwant: " << want;
  }
}

TEST_F(CliInfo, PairsUseLabelsAndHandleShortScenes) {
  write("l.t2", "label A 0 0\nlabel B 1 0\nlabel C 0 1\n");
  Result r = t2("info l.t2 --pairs");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(has(r.out, "orient(A, B, C) = +1   (lines 1, 2, 3)\n")) << r.out;
  write("two.t2", "0 0\n1 1\n");
  r = t2("info --pairs two.t2");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(has(r.out, "fewer than 3 points")) << r.out;
}

TEST_F(CliInfo, SegmentsAndPolygonsAreSummarized) {
  write("b.t2", "label A 0 0\nsegment\nA\n-1 -2 -1\nend\npolygon\n0 0\n0 1 0\n-1 0 1\n1 1\nend\n");
  const Result r = t2("info b.t2");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(r.out, "b.t2: 1 point, 1 segment, 1 polygon\n")) << r.out;
  EXPECT_TRUE(has(r.out, "segment (line 2): front [1, 0, 0] to back [-1, -2, -1]\n")) << r.out;
  EXPECT_TRUE(has(r.out, "polygon (line 6): 4 vertices (2 front, 1 at infinity, 1 back)\n")) << r.out;
}

TEST_F(CliInfo, StandardInputAndOutputFile) {
  const std::string text = "1 2\n-1 1 1\n0 1 0\n";
  write("s.t2", text);
  const Result file = t2("info s.t2 --pairs");
  ASSERT_EQ(file.status, 0);
  const Result in = t2("info - --pairs", text);
  EXPECT_EQ(in.status, 0) << in.err;
  EXPECT_TRUE(in.out.starts_with("<stdin>: 3 points")) << in.out;
  EXPECT_EQ(in.out.substr(in.out.find('\n')), file.out.substr(file.out.find('\n')));
  const Result o = t2("info s.t2 --pairs -o out/report.txt");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out, "");
  EXPECT_EQ(slurp(dir_ / "out" / "report.txt"), file.out);
  // Nothing but the report is left in the output folder (the write was atomic: temp + rename).
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "out"), fs::directory_iterator()), 1);
}

TEST_F(CliInfo, BadScenesExitTwoWithFileAndLine) {
  struct Case {
    const char* text;
    const char* where;
    const char* what;
  } cases[] = {
      {"1 2\n\n1 nan\n", "bad.t2:3: ", "'nan' is not a finite number"},
      {"1 1e999\n", "bad.t2:1: ", "too large"},
      {"1 2\n0 0 0\n", "bad.t2:2: ", "[0,0,0] is not a point of T2"},
      {"1 2 3 4\n", "bad.t2:1: ", "found 4"},
      {"1\r\n2\r\n", "bad.t2:1: ", "found 1"},
      {"ellipse 1 2\n", "bad.t2:1: ", "unknown keyword 'ellipse'"},
      {"segment\n1 2\n-1 -1 -2\nend\n", "bad.t2:3: ", "segment(p, q) is undefined when q = antipode(p)"},
      {"\npolygon\n0 0\n", "bad.t2:2: ", "'end' is missing"},
  };
  for (const auto& c : cases) {
    write("bad.t2", c.text);
    const Result r = t2("info bad.t2");
    EXPECT_EQ(r.status, 2) << c.text;
    EXPECT_EQ(r.out, "") << c.text;
    EXPECT_TRUE(r.err.starts_with(c.where)) << r.err << "\nwant: " << c.where;
    EXPECT_TRUE(has(r.err, c.what)) << r.err << "\nwant: " << c.what;
  }
  const Result in = t2("info -", "1 2\n3\n");
  EXPECT_EQ(in.status, 2);
  EXPECT_TRUE(in.err.starts_with("<stdin>:2: ")) << in.err;
}

TEST_F(CliInfo, MissingFileAndBadUsageExitTwo) {
  Result r = t2("info nowhere.t2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(has(r.err, "nowhere.t2")) << r.err;
  EXPECT_TRUE(has(r.err, "No such file or directory")) << r.err;
  write("s.t2", "1 2\n");
  for (const char* args : {"info", "info s.t2 s.t2", "info --frobnicate s.t2", "info s.t2 -o"}) {
    r = t2(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(has(r.err, "t2 info: ")) << args << ": " << r.err;
    EXPECT_EQ(r.out, "") << args;
  }
  r = t2("info --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(r.out.starts_with("Usage: t2 info")) << r.out;
}

TEST_F(CliInfo, EveryExampleSceneIsValid) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(T2_SOURCE_DIR) / "data" / "examples")) {
    if (e.path().extension() != ".t2") continue;
    const Result r = t2("info --pairs '" + e.path().string() + "'");
    EXPECT_EQ(r.status, 0) << e.path() << ": " << r.err;
    EXPECT_TRUE(r.out.starts_with(e.path().string() + ": ")) << r.out;
    ++n;
  }
  EXPECT_GE(n, 2);
}

}  // namespace
}  // namespace t2
