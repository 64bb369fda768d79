// `t2 draw` and `t2 figures`: runs the built tool and checks exit statuses, messages, and the
// files it leaves behind (none on error).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "t2/draw.hpp"
#include "t2/kernel/scene.hpp"
#include "cli_testing.hpp"
#include "testing.hpp"

namespace t2 {
namespace {

namespace fs = std::filesystem;

using testing::has;
using testing::Result;
using testing::slurp;

class CliDraw : public testing::CliTest {};

const fs::path kExamples = fs::path(T2_SOURCE_DIR) / "data" / "examples";

TEST_F(CliDraw, DrawsAnExampleSceneInEveryModelAndFormat) {
  const std::string scene = "'" + (kExamples / "triangle.t2").string() + "'";
  const Result svg = t2("draw " + scene + " -o both.svg");
  ASSERT_EQ(svg.status, 0) << svg.err;
  EXPECT_EQ(svg.out, "");
  const std::string both = slurp(dir_ / "both.svg");
  EXPECT_TRUE(both.starts_with("<?xml")) << both.substr(0, 100);
  // The same picture as the library draws for the same items (labels A, B, C, D appear).
  for (const char* label : {"plane", "sphere"}) {
    const Result r = t2(std::string("draw ") + scene + " --model " + label + " -o " + label + ".svg");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(slurp(dir_ / (std::string(label) + ".svg")).starts_with("<?xml"));
    EXPECT_NE(slurp(dir_ / (std::string(label) + ".svg")), both);
  }
  EXPECT_NE(slurp(dir_ / "plane.svg"), slurp(dir_ / "sphere.svg"));
  // The view moves the sphere.
  ASSERT_EQ(t2("draw " + scene + " --model sphere --view 60,10 -o other.svg").status, 0);
  EXPECT_NE(slurp(dir_ / "other.svg"), slurp(dir_ / "sphere.svg"));
  // Formats from the extension or from --format; same input, same bytes.
  ASSERT_EQ(t2("draw " + scene + " -o p.png").status, 0);
  EXPECT_TRUE(slurp(dir_ / "p.png").starts_with("\x89PNG"));
  ASSERT_EQ(t2("draw " + scene + " -o d.pdf").status, 0);
  EXPECT_TRUE(slurp(dir_ / "d.pdf").starts_with("%PDF"));
  ASSERT_EQ(t2("draw " + scene + " --format png -o p2.img").status, 0);
  EXPECT_EQ(slurp(dir_ / "p2.img"), slurp(dir_ / "p.png"));
  ASSERT_EQ(t2("draw " + scene + " -o again.svg").status, 0);
  EXPECT_EQ(slurp(dir_ / "again.svg"), both);
}

TEST_F(CliDraw, TheToolKeepsTheSideOfEveryPoint) {
  // The example's labelled point D is on the back side, so the library draws it hollow (the
  // display list says so) ...
  const Scene s = read_scene(kExamples / "triangle.t2");
  const ScenePoint* d = s.find("D");
  ASSERT_NE(d, nullptr);
  EXPECT_LT(d->point.w(), 0);
  draw::Figure f;
  f.add(d->point);
  int hollow = 0;
  for (const auto& sh : draw::display_list(f, draw::PlaneView()))
    if (sh.kind == draw::ShapeKind::marker && sh.hollow) ++hollow;
  EXPECT_EQ(hollow, 1);
  // ... and the tool does not lose the side: a point and its antipode sit at the same spot of
  // the plane, yet their pictures differ (hollow or filled), in both models; the same point
  // written with a positive factor gives the same picture.
  write("p.t2", "2 1 1\n");
  write("np.t2", "-2 -1 -1\n");
  write("p3.t2", "6 3 3\n");
  for (const char* m : {"plane", "sphere"}) {
    const std::string opt = std::string(" --model ") + m + " -o ";
    ASSERT_EQ(t2("draw p.t2" + opt + "p.svg").status, 0);
    ASSERT_EQ(t2("draw np.t2" + opt + "np.svg").status, 0);
    ASSERT_EQ(t2("draw p3.t2" + opt + "p3.svg").status, 0);
    EXPECT_NE(slurp(dir_ / "p.svg"), slurp(dir_ / "np.svg")) << m;
    EXPECT_EQ(slurp(dir_ / "p.svg"), slurp(dir_ / "p3.svg")) << m;
  }
}

TEST_F(CliDraw, ABadSceneExitsTwoWithFileAndLineAndWritesNothing) {
  write("bad.t2", "1 2\n\nsegment\n1 2\n-1 -1 -2\nend\n");
  for (const char* out : {"out.svg", "out.png", "sub/out.pdf"}) {
    const Result r = t2(std::string("draw bad.t2 -o ") + out);
    EXPECT_EQ(r.status, 2) << out;
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(r.err.starts_with("bad.t2:5: ")) << r.err;
    EXPECT_TRUE(has(r.err, "segment(p, q) is undefined when q = antipode(p)")) << r.err;
  }
  write("bad2.t2", "1 2\n1 nan\n");
  const Result r = t2("draw bad2.t2 --model sphere -o out.svg");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.err.starts_with("bad2.t2:2: ")) << r.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"bad.t2", "bad2.t2"}));
}

TEST_F(CliDraw, LinesAndCirclesOfEveryRadiusKindAreDrawn) {
  const std::string scene = "'" + (kExamples / "circles.t2").string() + "'";
  ASSERT_EQ(t2("draw " + scene + " --model plane -o all.svg").status, 0);
  // Each block adds to the picture: without it the drawing differs.
  const std::string text = slurp(kExamples / "circles.t2");
  for (const char* block : {"circle", "line"}) {
    const auto at = text.rfind(std::string("\n") + block + " ");
    ASSERT_NE(at, std::string::npos) << block;
    const auto end = text.find("end\n", at);
    write("less.t2", text.substr(0, at + 1) + text.substr(end + 4));
    const Result r = t2("draw less.t2 --model plane -o less.svg");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir_ / "less.svg"), slurp(dir_ / "all.svg")) << block;
  }
  // The scene holds what the example says, and its circles are stroked in the tool's red.
  const Scene s = read_scene(kExamples / "circles.t2");
  ASSERT_EQ(s.circles.size(), 3u);
  ASSERT_EQ(s.lines.size(), 1u);
  EXPECT_TRUE(has(slurp(dir_ / "all.svg"), "stroke:rgb(83.921569%,15.294118%,15.686275%)"));  // #d62728
}

TEST_F(CliDraw, FarPointsAreDrawnAndHugeCirclesAreRefusedWithTheirLine) {
  // A proper point beyond 1e308 from the origin: drawn like the point at infinity in its direction.
  write("far.t2", "segment\n1e-300 1e300 1e300\n1 1e300 -1e300\nend\n1e-300 1e300 1e300\n");
  for (const char* m : {"plane", "sphere"}) {
    const Result r = t2(std::string("draw far.t2 --model ") + m + " -o far.svg");
    EXPECT_EQ(r.status, 0) << m << ": " << r.err;
  }
  write("huge.t2", "1 1\n\ncircle\n1e-300 1e300 1e300\n1 1e300 -1e300\nend\n");
  const Result r = t2("draw huge.t2 -o huge.svg");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.err.starts_with("huge.t2:3: ")) << r.err;
  EXPECT_TRUE(has(r.err, "beyond the range of double")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "huge.svg"));
}

TEST_F(CliDraw, BadUsageExitsTwoAndWritesNothing) {
  write("s.t2", "1 2\n");
  for (const char* args : {"draw", "draw s.t2", "draw s.t2 -o", "draw s.t2 -o a.jpg", "draw s.t2 --format gif -o a.svg",
                           "draw s.t2 --model cube -o a.svg", "draw s.t2 --view 95,0 -o a.svg",
                           "draw s.t2 --view 10 -o a.svg", "draw s.t2 --frob -o a.svg",
                           "draw nowhere.t2 -o a.svg"}) {
    const Result r = t2(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  EXPECT_EQ(files(), (std::vector<std::string>{"s.t2"}));
  const Result h = t2("draw --help");
  EXPECT_EQ(h.status, 0);
  EXPECT_TRUE(h.out.starts_with("Usage: t2 draw")) << h.out;
}

TEST_F(CliDraw, FiguresCheckPassesOnThisRepository) {
  const Result r = t2("figures --check --jobs 2");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(has(r.out, "all up to date")) << r.out;
}

TEST_F(CliDraw, FiguresCheckFindsAChangedMissingOrExtraFigure) {
  // A source tree with one small chapter and the gallery (the programs `t2 figures` runs are the
  // chapters present in root/chapters, and the gallery): spoiled three ways, in both folders.
  // FiguresCheckPassesOnThisRepository checks every figure; this one checks what --check finds.
  const fs::path root = dir_ / "root", source = T2_SOURCE_DIR;
  const std::string chapter = "02-primitives";
  fs::create_directories(root / "chapters");
  fs::create_directories(root / "figures");
  fs::copy(source / "chapters" / chapter, root / "chapters" / chapter, fs::copy_options::recursive);
  for (const std::string& folder : {chapter, std::string("gallery")})
    fs::copy(source / "figures" / folder, root / "figures" / folder, fs::copy_options::recursive);
  const Result clean = t2("figures --check --root root");
  ASSERT_EQ(clean.status, 0) << clean.out << clean.err;
  EXPECT_TRUE(has(clean.out, "2 programs")) << clean.out;
  const fs::path changed = root / "figures" / "gallery" / "fig-3-5-orientation.svg";
  const fs::path missing = root / "figures" / chapter / "triangle-sphere.svg";
  ASSERT_TRUE(fs::exists(changed));
  ASSERT_TRUE(fs::exists(missing));
  std::ofstream(changed, std::ios::app) << "\n";
  fs::remove(missing);
  std::ofstream(root / "figures" / "gallery" / "stale.svg") << "<svg/>";
  const Result r = t2("figures --check --root root");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_TRUE(has(r.out, "differs: figures/gallery/fig-3-5-orientation.svg")) << r.out;
  EXPECT_TRUE(has(r.out, "missing: figures/" + chapter + "/triangle-sphere.svg")) << r.out;
  EXPECT_TRUE(has(r.out, "figures/gallery/stale.svg")) << r.out;
  // --check changes nothing; without it the figures are redrawn, and the extra file stays.
  EXPECT_FALSE(fs::exists(missing));
  const Result w = t2("figures --root root --jobs 1");
  EXPECT_EQ(w.status, 0) << w.err;
  EXPECT_TRUE(fs::exists(missing));
  EXPECT_EQ(slurp(missing), slurp(source / "figures" / chapter / "triangle-sphere.svg"));
  EXPECT_EQ(slurp(changed), slurp(source / "figures" / "gallery" / "fig-3-5-orientation.svg"));
  const Result again = t2("figures --check --root root");
  EXPECT_EQ(again.status, 1);
  EXPECT_FALSE(has(again.out, "differs")) << again.out;
  EXPECT_FALSE(has(again.out, "missing")) << again.out;
  EXPECT_TRUE(has(again.out, "stale.svg")) << again.out;
}

TEST_F(CliDraw, FiguresBadUsageExitsTwo) {
  for (const char* args : {"figures --jobs 0", "figures --jobs x", "figures --frob", "figures --jobs"}) {
    const Result r = t2(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
  }
}

}  // namespace
}  // namespace t2
