// Scene files: the parser against hand-written expectations (every error form, exact line
// numbers), random scenes written and read back bit for bit, random garbage that must either
// parse or fail with a `file:line:` ParseError, and the fuzzing corpus as a regression suite.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include <unistd.h>

#include "scene_testing.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

namespace fs = std::filesystem;
using testing::scale;

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Coordinates as written (no rescaling): the parser must not touch them.
void expect_coords(const Point& p, double w, double x, double y) {
  EXPECT_TRUE(same_bits(p.w(), w) && same_bits(p.x(), x) && same_bits(p.y(), y))
      << to_string(p) << " != [" << w << ", " << x << ", " << y << "]";
}

TEST(Scene, PlainPointsTwoAndThreeNumbers) {
  const Scene s = parse_scene("1 2\n-1 0 3\n0 1 0.5\n", "pts");
  EXPECT_EQ(s.name, "pts");
  ASSERT_EQ(s.points.size(), 3u);
  expect_coords(s.points[0].point, 1, 1, 2);
  expect_coords(s.points[1].point, -1, 0, 3);
  expect_coords(s.points[2].point, 0, 1, 0.5);
  EXPECT_EQ(s.points[0].line, 1);
  EXPECT_EQ(s.points[2].line, 3);
  EXPECT_TRUE(s.points[0].label.empty());
  EXPECT_TRUE(s.segments.empty());
  EXPECT_TRUE(s.polygons.empty());
}

TEST(Scene, CommentsBlankLinesAndLineNumbers) {
  const Scene s = parse_scene("# header\n\n   \t\n  3 4   # trailing comment\n#1 2\n\n5 6#x\n", "c");
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.points[0].line, 4);
  EXPECT_EQ(s.points[1].line, 7);
  expect_coords(s.points[1].point, 1, 5, 6);
}

TEST(Scene, EmptyAndCommentOnlyFilesAreEmptyScenes) {
  for (const char* text : {"", "\n", "# nothing\n", "\r\n\r\n", "   "}) {
    const Scene s = parse_scene(text, "e");
    EXPECT_TRUE(s.points.empty() && s.segments.empty() && s.polygons.empty()) << text;
  }
}

TEST(Scene, CrlfNoTrailingNewlineAndByteOrderMarkGiveTheSameScene) {
  const std::string lf = "# c\n1 2\nlabel A 3 4\nsegment\nA\n5 6\nend\n";
  std::string crlf;
  for (char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const std::string variants[] = {lf, crlf, lf.substr(0, lf.size() - 1), crlf.substr(0, crlf.size() - 2),
                                  "\xEF\xBB\xBF" + lf};
  for (const auto& text : variants) {
    const Scene s = parse_scene(text, "v");
    ASSERT_EQ(s.points.size(), 2u);
    ASSERT_EQ(s.segments.size(), 1u);
    expect_coords(s.points[1].point, 1, 3, 4);
    EXPECT_EQ(s.points[1].line, 3);
    EXPECT_EQ(s.segments[0].line, 4);
    EXPECT_EQ(s.segments[0].b.line, 6);
    expect_coords(s.segments[0].b.point, 1, 5, 6);
  }
  // No trailing newline after a number: the last line is still read whole.
  expect_coords(parse_scene("1 2\n3 45", "n").points[1].point, 1, 3, 45);
}

TEST(Scene, NumberForms) {
  const Scene s = parse_scene(
      "1.5e3 -2.5E-2\n+7 .5\n5. -0.125\n1e308 -1.7976931348623157e308\n4.9406564584124654e-324 1e-310\n"
      "-0 0 1\n",
      "n");
  ASSERT_EQ(s.points.size(), 6u);
  expect_coords(s.points[0].point, 1, 1500, -0.025);
  expect_coords(s.points[1].point, 1, 7, 0.5);
  expect_coords(s.points[2].point, 1, 5, -0.125);
  expect_coords(s.points[3].point, 1, 1e308, -std::numeric_limits<double>::max());
  expect_coords(s.points[4].point, 1, std::numeric_limits<double>::denorm_min(), 1e-310);
  expect_coords(s.points[5].point, -0.0, 0, 1);
}

TEST(Scene, EveryDoubleRoundTripsExactly) {
  // Random bit patterns (all finite doubles, subnormals included), printed in two ways that
  // read back exactly: shortest form and 17 significant digits.
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000 * scale(); ++i) {
    double v[3];
    for (auto& c : v) {
      do c = std::bit_cast<double>(rng());
      while (!std::isfinite(c));
    }
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) continue;
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", v[0], v[1], v[2]);
    const std::string text = buf + to_string(v[0]) + " " + to_string(v[1]) + " " + to_string(v[2]) + "\n";
    const Scene s = parse_scene(text, "r");
    ASSERT_EQ(s.points.size(), 2u);
    expect_coords(s.points[0].point, v[0], v[1], v[2]);
    // to_string prints -0 as 0: compare the second reading as values (exact for doubles).
    const Point& q = s.points[1].point;
    EXPECT_TRUE(q.w() == v[0] && q.x() == v[1] && q.y() == v[2]) << text;
  }
}

TEST(Scene, RandomScenesReadBackAsWritten) {
  // The oracle is the generated scene itself.
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> kind(0, 9), small(-20, 20);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (int round = 0; round < 200 * scale(); ++round) {
    std::vector<std::array<double, 3>> want;
    std::vector<int> lines;
    std::string text;
    int line = 0;
    const int n = 1 + kind(rng);
    for (int i = 0; i < n; ++i) {
      switch (kind(rng) % 4) {
        case 0: text += "# comment " + std::to_string(i) + "\n"; ++line; break;
        case 1: text += "\n"; ++line; break;
        default: break;
      }
      std::array<double, 3> c{1, u(rng), u(rng)};
      const int k = kind(rng);
      if (k < 3) c[0] = 0;                                   // at infinity
      if (k >= 3 && k < 6) c[0] = small(rng);                // front or back (or infinity)
      if (c[0] == 0 && c[1] == 0 && c[2] == 0) c[1] = 1;
      char buf[96];
      if (c[0] == 1 && k >= 6)
        std::snprintf(buf, sizeof buf, "%.17g\t%.17g", c[1], c[2]);
      else
        std::snprintf(buf, sizeof buf, " %.17g %.17g  %.17g ", c[0], c[1], c[2]);
      text += buf;
      text += kind(rng) < 2 ? "  # x\n" : "\n";
      lines.push_back(++line);
      want.push_back(c);
    }
    const Scene s = parse_scene(text, "rand");
    ASSERT_EQ(s.points.size(), want.size()) << text;
    for (std::size_t i = 0; i < want.size(); ++i) {
      expect_coords(s.points[i].point, want[i][0], want[i][1], want[i][2]);
      EXPECT_EQ(s.points[i].line, lines[i]);
    }
  }
}

TEST(Scene, LabelsSegmentsAndPolygons) {
  const Scene s = parse_scene(
      "label A 0 0\n"        // 1
      "label p' -1 2 3\n"    // 2
      "7 8\n"                // 3
      "segment\n"            // 4
      "  A\n"                // 5
      "  0 0 1\n"            // 6
      "end\n"                // 7
      "polygon # square\n"   // 8
      "0 0\n1 0\n1 1\n"      // 9-11
      "p'\n"                 // 12
      "end\n",               // 13
      "lab");
  ASSERT_EQ(s.points.size(), 3u);
  EXPECT_EQ(s.points[0].label, "A");
  EXPECT_EQ(s.points[1].label, "p'");
  EXPECT_EQ(s.points[2].label, "");
  ASSERT_NE(s.find("p'"), nullptr);
  EXPECT_EQ(s.find("p'")->line, 2);
  EXPECT_EQ(s.find("B"), nullptr);
  EXPECT_EQ(s.find(""), nullptr);
  ASSERT_EQ(s.segments.size(), 1u);
  EXPECT_EQ(s.segments[0].line, 4);
  expect_coords(s.segments[0].a.point, 1, 0, 0);
  EXPECT_EQ(s.segments[0].a.label, "A");
  EXPECT_EQ(s.segments[0].a.line, 5);  // where it is referenced
  expect_coords(s.segments[0].b.point, 0, 0, 1);
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_EQ(s.polygons[0].line, 8);
  ASSERT_EQ(s.polygons[0].vertices.size(), 4u);
  expect_coords(s.polygons[0].vertices[3].point, -1, 2, 3);
  EXPECT_EQ(s.polygons[0].vertices[3].line, 12);
  EXPECT_EQ(s.polygons[0].vertices[1].line, 10);
  // The library types: t2::Segment and t2::Polygon with the same points.
  const Segment g = s.segments[0].segment();
  expect_coords(g.source(), 1, 0, 0);
  expect_coords(g.target(), 0, 0, 1);
  const Polygon P = s.polygons[0].polygon();
  ASSERT_EQ(P.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const Point& v = s.polygons[0].vertices[i].point;
    expect_coords(P[i], v.w(), v.x(), v.y());
  }
}

TEST(Scene, LabelsThatLookLikeNumberWordsAndManyLabels) {
  // "inf1" and "nancy" are names; "inf" and "NaN" read as numbers.
  const Scene s = parse_scene("label inf1 1 2\nlabel nancy 3 4\nsegment\ninf1\nnancy\nend\n", "w");
  ASSERT_EQ(s.segments.size(), 1u);
  EXPECT_EQ(s.segments[0].a.label, "inf1");
  expect_coords(s.segments[0].b.point, 1, 3, 4);
  expect_error("label inf 1 2\n", 1, "'inf' reads as a number, not a label name");
  expect_error("label NaN 1 2\n", 1, "'NaN' reads as a number");
  expect_error("info 1 2\n", 1, "unknown keyword 'info'");
  // Many labels, each referenced once: every reference finds its own point.
  std::string text;
  const int n = 5000;
  for (int i = 0; i < n; ++i) text += "label P" + std::to_string(i) + " " + std::to_string(i) + " 1\n";
  text += "polygon\n";
  for (int i = n - 1; i >= 0; --i) text += "P" + std::to_string(i) + "\n";
  text += "end\n";
  const Scene big = parse_scene(text, "big");
  ASSERT_EQ(big.polygons.size(), 1u);
  ASSERT_EQ(big.polygons[0].vertices.size(), std::size_t(n));
  for (int i = 0; i < n; ++i) {
    expect_coords(big.polygons[0].vertices[i].point, 1, n - 1 - i, 1);
    ASSERT_EQ(big.find("P" + std::to_string(i))->line, i + 1);
  }
}

TEST(Scene, ParseErrorIsBadInputWithFileAndLine) {
  try {
    (void)parse_scene("1 2\n\n1 2 3 4\n", "some/dir/x.t2");
    FAIL() << "no error";
  } catch (const BadInput& e) {
    const auto* p = dynamic_cast<const ParseError*>(&e);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->file(), "some/dir/x.t2");
    EXPECT_EQ(p->line(), 3);
    EXPECT_EQ(std::string(e.what()), "some/dir/x.t2:3: a point is 2 numbers (x y) or 3 (w x y), found 4");
  }
}

TEST(Scene, NonFiniteAndOutOfRangeNumbersAreRejected) {
  expect_error("1 2\nnan 1\n", 2, "'nan' is not a finite number");
  expect_error("1 inf\n", 1, "'inf' is not a finite number");
  expect_error("1 -inf\n", 1, "'-inf' is not a finite number");
  expect_error("Infinity 1 2\n", 1, "'Infinity' is not a finite number");
  expect_error("1 -NaN\n", 1, "'-NaN' is not a finite number");
  expect_error("1 2\n3 1e999\n", 2, "'1e999' is too large for a double");
  expect_error("-1.8e308 0\n", 1, "'-1.8e308' is too large");
  expect_error("1e-400 1\n", 1, "'1e-400' is too small for a double: it would round to 0");
  // 1e99999999999999999999 is huge in every sense; the parser must not choke on it.
  expect_error("1 1e99999999999999999999\n", 1, "too large");
  expect_error("1 " + std::string(5000, '9') + "e999999\n", 1, "too large");
}

TEST(Scene, MalformedNumbersAreRejected) {
  expect_error("1,5 2\n", 1, "'1,5' is not a number");
  expect_error("0x10 2\n", 1, "'0x10' is not a number");
  expect_error("1e 2\n", 1, "'1e' is not a number");
  expect_error("1 2x\n", 1, "'2x' is not a number");
  expect_error("1 ++2\n", 1, "'++2' is not a number");
  expect_error("1 +-2\n", 1, "'+-2' is not a number");
  expect_error("1 -\n", 1, "'-' is not a number");
  expect_error("1 .\n", 1, "'.' is not a number");
  expect_error("1 2 foo\n", 1, "'foo' is not a number");
  expect_error(std::string("1 2\x01\n"), 1, "'2\\x01' is not a number");
  expect_error(std::string("1 2\0 3\n", 7), 1, "'2\\x00' is not a number");
  // Long tokens are cut in messages.
  const ParseError e = error_of("1 " + std::string(1000, '7') + "z\n");
  EXPECT_LT(e.message().size(), 80u) << e.message();
}

TEST(Scene, WrongFieldCountsAndTheNullTriple) {
  expect_error("\n5\n", 2, "a point is 2 numbers (x y) or 3 (w x y), found 1");
  expect_error("1 2 3 4\n", 1, "found 4");
  expect_error("1 2 3 4 5 6\n", 1, "found 6");
  expect_error("1 2\n0 0 0\n", 2, "[0,0,0] is not a point of T2");
  expect_error("-0 0 -0\n", 1, "[0,0,0] is not a point of T2");
  EXPECT_NO_THROW((void)parse_scene("0 0\n", "origin"));  // x y = 0 0 is the front origin [1,0,0]
}

TEST(Scene, KeywordErrors) {
  expect_error("1 2\nfoo 1 2\n", 2, "unknown keyword 'foo'");
  expect_error("Segment\n", 1, "unknown keyword 'Segment'");
  expect_error("end\n", 1, "'end' without an open block (segment, polygon, line or circle)");
  expect_error("segment 1 2\n", 1, "'segment' stands alone on its line, found '1' after it");
  expect_error("polygon\n0 0\n1 0\n0 1\nend now\n", 5, "'end' stands alone on its line");
  expect_error("segment\n0 0\npolygon\n", 3, "'polygon' inside the 'segment' block opened on line 1");
  expect_error("polygon\n\nsegment\n", 3, "'segment' inside the 'polygon' block opened on line 1");
}

TEST(Scene, LabelErrors) {
  expect_error("label\n", 1, "'label' needs a name and a point");
  expect_error("label A\n", 1, "label 'A' has no point");
  expect_error("label 3 1 2\n", 1, "'3' is not a label name");
  expect_error("label a-b 1 2\n", 1, "'a-b' is not a label name");
  expect_error("label end 1 2\n", 1, "'end' is a keyword, not a label name");
  expect_error("label A 1 2\n\nlabel A 3 4\n", 3, "label 'A' is already defined on line 1");
  expect_error("label A 1 2 3 4\n", 1, "found 4");
  expect_error("label A 1 nan\n", 1, "'nan' is not a finite number");
  expect_error("label A 0 0 0\n", 1, "[0,0,0] is not a point of T2");
  expect_error("segment\nlabel A 1 2\n", 2, "'label' inside the 'segment' block opened on line 1");
  expect_error("segment\nB\n", 2, "'B' is neither a keyword nor a label defined above");
  expect_error("segment\nB\nend\nlabel B 1 1\n", 2, "'B' is neither");  // defined too late
  expect_error("label A 1 2\nsegment\nA 3\n", 3, "'A' stands alone on its line, found '3' after it");
}

TEST(Scene, BlockCountsAndUnterminatedBlocks) {
  expect_error("segment\n1 2\nend\n", 3, "a segment has exactly 2 points, this one has 1");
  expect_error("segment\n1 2\n3 4\n5 6\nend\n", 5, "a segment has exactly 2 points, this one has 3");
  expect_error("segment\nend\n", 2, "this one has 0");
  expect_error("polygon\n1 2\n3 4\nend\n", 4, "a polygon has at least 3 vertices, this one has 2");
  expect_error("1 2\nsegment\n1 2\n3 4\n", 2, "'segment' block is not closed: 'end' is missing");
  expect_error("polygon\n1 2\n3 4\n5 6\n# end\n", 1, "'polygon' block is not closed");
}

TEST(Scene, LinesAndCircles) {
  const Scene s = parse_scene(
      "label c 1 1\n"
      "line\n  0 0\n  c\nend\n"
      "circle\n  c\n  3 1\nend\n"
      "circle   # centre at infinity: a line\n  0 0 1\n  2 0\nend\n"
      "circle   # through a point of Omega: Omega itself\n  c\n  0 1 0\nend\n",
      "lc");
  ASSERT_EQ(s.lines.size(), 1u);
  ASSERT_EQ(s.circles.size(), 3u);
  EXPECT_EQ(s.lines[0].line, 2);
  EXPECT_EQ(s.lines[0].b.label, "c");
  const Line l = s.lines[0].join();  // through (0, 0) and (1, 1), oriented from the first
  EXPECT_EQ(side(l, Point(1, 0, 0)), ZERO);
  EXPECT_EQ(side(l, Point(1, 1, 1)), ZERO);
  EXPECT_EQ(side(l, Point(1, 0, 1)), POSITIVE);  // (0, 1) is to the left of (0,0) -> (1,1)
  EXPECT_EQ(s.circles[0].line, 6);
  EXPECT_EQ(s.circles[0].center.label, "c");
  EXPECT_EQ(radius_kind(s.circles[0].circle()), RadiusKind::finite);
  EXPECT_EQ(radius_kind(s.circles[1].circle()), RadiusKind::infinite);
  EXPECT_EQ(radius_kind(s.circles[2].circle()), RadiusKind::infinite);
  EXPECT_EQ(s.circles[0].circle().orientation(), POSITIVE);
  // A beyond-infinity circle is a valid scene circle.
  EXPECT_EQ(radius_kind(parse_scene("circle\n1 1\n-1 -3 -1\nend\n", "b").circles.at(0).circle()),
            RadiusKind::beyond_infinity);
}

TEST(Scene, UndefinedLinesAndCirclesAreRejected) {
  expect_error("line\n1 2\nend\n", 3, "a line has exactly 2 points, this one has 1");
  expect_error("circle\n1 2\n3 4\n5 6\nend\n", 5, "a circle has exactly 2 points, this one has 3");
  expect_error("line\n1 2\n1 2\nend\n", 3, "join(p, q) is undefined when q = p or q = antipode(p)");
  expect_error("line\n1 2\n\n-1 -1 -2\nend\n", 4, "q = [-1, -1, -2] (line 4)");
  expect_error("line\n2 4 2\n1 2 1\nend\n", 3, "join(p, q) is undefined");  // the same point, scaled
  expect_error("circle\n0 1 0\n0 0 1\nend\n", 3, "circle: undefined when both the centre");
  expect_error("line\n0 0\ncircle\n", 3, "'circle' inside the 'line' block opened on line 1");
  expect_error("circle\n0 0\n", 1, "'circle' block is not closed");
  expect_error("label circle 1 2\n", 1, "'circle' is a keyword, not a label name");
}

TEST(Scene, AntipodalEndpointsAreRejected) {
  // ¬[1, 1, 2] = [-1, -1, -2]; [2, 2, 4] is the same point as [1, 1, 2].
  expect_error("segment\n1 2\n-1 -1 -2\nend\n", 3, "segment(p, q) is undefined when q = antipode(p)");
  expect_error("segment\n2 2 4\n\n-0.5 -0.5 -1\nend\n", 4, "q = antipode(p)");
  expect_error("label A 0 1 0\nsegment\nA\n0 -3 0\nend\n", 4, "q = antipode(p)");  // at infinity
  expect_error("polygon\n0 0\n1 2\n-1 -1 -2\n5 5\nend\n", 4, "polygon edge 2-3: segment(p, q)");
  expect_error("polygon\n1 2\n0 0\n5 5\n-2 -2 -4\nend\n", 6, "closing polygon edge 4-1");
  // Equal endpoints, and points that are antipodal in x y only, are fine.
  EXPECT_NO_THROW((void)parse_scene("segment\n1 2\n1 2\nend\n", "ok"));
  EXPECT_NO_THROW((void)parse_scene("segment\n1 2\n-1 1 2\nend\n", "ok"));
  EXPECT_NO_THROW((void)parse_scene("segment\n1 2\n-1 -1 -2.0000000000000004\nend\n", "ok"));
  // Antipodes far apart as points (not in the block) are fine too: only segments and edges care.
  EXPECT_NO_THROW((void)parse_scene("1 2\n-1 -1 -2\n", "ok"));
}

TEST(Scene, ReadSceneFromFileAndMissingFile) {
  const fs::path dir = fs::temp_directory_path() / ("t2_scene_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path f = dir / "s.t2";
  std::ofstream(f) << "1 2\n3 4 5 6\n";
  try {
    (void)read_scene(f);
    ADD_FAILURE();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), f.string());
    EXPECT_EQ(e.line(), 2);
  }
  std::ofstream(f) << "1 2\n3 4 5\n";
  EXPECT_EQ(read_scene(f).points.size(), 2u);
  try {
    (void)read_scene(dir / "missing.t2");
    ADD_FAILURE();
  } catch (const ParseError&) {
    ADD_FAILURE() << "a missing file is not a parse error";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("missing.t2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)read_scene(dir), BadInput);  // a directory
  fs::remove_all(dir);
}

// Either a scene or a ParseError with `name:line: `; anything else (another exception, a
// crash, a sanitizer report) fails.
void parses_or_fails_cleanly(const std::string& text, const std::string& name) {
  try {
    const Scene s = parse_scene(text, name);
    for (const auto& l : s.lines) EXPECT_NO_THROW((void)l.join()) << name;  // accepted means defined
    for (const auto& c : s.circles) EXPECT_NO_THROW((void)c.circle()) << name;
    EXPECT_NO_THROW((void)parse_scene(to_string(s), "written")) << name;  // its text reads back
  } catch (const ParseError& e) {
    const std::string prefix = name + ":" + std::to_string(e.line()) + ": ";
    EXPECT_EQ(std::string(e.what()).substr(0, prefix.size()), prefix);
    EXPECT_GE(e.line(), 1);
    EXPECT_FALSE(e.message().empty());
  }
}

TEST(Scene, RandomGarbageParsesOrFailsWithFileAndLine) {
  const std::string pieces[] = {"1", "-2.5", "0", " ", "\t", "\n", "\r\n", "#", "e", "e9", "999", ".",
                                "+", "-", "nan", "inf", "label", "A", "B", "segment", "polygon", "line", "circle",
                                "end", "\x00", "\xff", "'", "1e-400", "0 0 0", "-1 -1 -2", "style", "=", "color=", "red",
                                "#d62728", "\"", "label=\"", "width=2", "fill=none"};
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::size_t> pick(0, std::size(pieces) - 1), len(0, 60);
  for (int i = 0; i < 3000 * scale(); ++i) {
    std::string text;
    for (std::size_t k = len(rng); k > 0; --k) text += pieces[pick(rng)];
    parses_or_fails_cleanly(text, "g");
  }
}

TEST(Scene, CorpusAndExamplesParseOrFailCleanly) {
  int files = 0;
  for (const char* sub : {"fuzz/corpus/scene", "data/examples"}) {
    const fs::path dir = fs::path(T2_SOURCE_DIR) / sub;
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      const std::string name = entry.path().filename().string();
      if (std::string(sub) == "data/examples" && entry.path().extension() == ".t2")
        EXPECT_NO_THROW((void)parse_scene(ss.str(), name)) << "example " << name << " must be valid";
      else
        parses_or_fails_cleanly(ss.str(), name);
      ++files;
    }
  }
  EXPECT_GE(files, 10);
}

// The table of block kinds (scene.cpp): every keyword it lists opens a block whose size is
// checked at its 'end', and the messages that list the keywords list exactly the table's.
TEST(Scene, BlockKindsComeFromOneTable) {
  const auto kinds = scene_block_keywords();
  EXPECT_EQ(kinds, (std::vector<std::string_view>{"segment", "polygon", "line", "circle"}));
  std::string listed;
  for (auto k : kinds) {
    listed += std::string(k) + ", ";
    // One point is too few for every kind: the error is at the line of 'end'.
    const ParseError e = error_of("# a block\n" + std::string(k) + "\n1 2\nend\n");
    EXPECT_EQ(e.file(), "f.t2");
    EXPECT_EQ(e.line(), 4) << e.what();
    EXPECT_TRUE(e.message().starts_with("a " + std::string(k) + " has ")) << e.what();
    EXPECT_TRUE(e.message().ends_with(", this one has 1")) << e.what();
  }
  // An unknown kind is refused with file:line, and the message lists every kind of the table.
  const ParseError u = error_of("1 2\n\nhexagon\n1 2\nend\n");
  EXPECT_EQ(u.line(), 3) << u.what();
  EXPECT_EQ(u.message(), "unknown keyword 'hexagon' (the keywords are label, style, " + listed + "end)");
  EXPECT_EQ(std::string(u.what()), "f.t2:3: " + u.message());
  const ParseError end = error_of("end\n");
  EXPECT_EQ(end.message(), "'end' without an open block (segment, polygon, line or circle)");
}

}  // namespace
}  // namespace t2
