// t2 animate from the command line: every algorithm writes one self-contained page whose last
// step is the algorithm's answer (compared with t2 hull and with t2::delaunay), and bad input,
// no hull and too many points leave the output untouched with the documented exit statuses.
#include <algorithm>
#include <regex>
#include <sstream>

#include "animate_testing.hpp"
#include "cli_testing.hpp"
#include "testing.hpp"
#include "t2/gen/generate.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/triangulate.hpp"
#include "t2/triangulation/triangulate_t2.hpp"

namespace t2::testing {
namespace {

class AnimateCli : public CliTest {
 protected:
  // The points of a generated scene file, and the file.
  // `back`: the share behind (both-sides).
  std::vector<Point> generate(const std::string& name, gen::Kind k, std::size_t n, std::uint64_t seed,
                              double back = gen::Options().back) {
    gen::Options o;
    o.n = n;
    o.seed = seed;
    o.back = back;
    write(name, gen::to_text(k, o));
    return gen::points(k, o);
  }
};

// The JSON array after `"key":[` in the object of the page's last step (nlohmann writes the
// keys of an object in sorted order, and the steps in order).
std::string last_step_field(const std::string& html, const std::string& key) {
  const auto answer = html.rfind("\"kind\":\"answer\"");
  if (answer == std::string::npos) return "<no answer step>";
  const auto open = html.rfind("{\"chain\":", answer);
  const auto at = html.find("\"" + key + "\":", open);
  if (open == std::string::npos || at == std::string::npos) return "<no " + key + ">";
  std::size_t depth = 0, k = at + key.size() + 3;
  const std::size_t begin = k;
  for (; k < html.size(); ++k) {
    depth += html[k] == '[';
    if (html[k] == ']' && --depth == 0) break;
  }
  return html.substr(begin, k + 1 - begin);
}

// The colour of the overlay (tools/t2/animate/frame.cpp: #9467bd), as the SVG writes it.
const char* const kOverlayStroke = "stroke:rgb(58.039216%,40.392157%,74.117647%)";

std::vector<std::size_t> numbers(const std::string& s) {
  std::vector<std::size_t> v;
  static const std::regex num(R"(\d+)");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), num); it != std::sregex_iterator(); ++it)
    v.push_back(std::stoul(it->str()));
  return v;
}

// True when a and b are the same cyclic sequence.
bool same_cycle(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  for (std::size_t r = 0; r < a.size(); ++r)
    if (std::equal(a.begin(), a.end(), b.begin() + 0, [&, k = std::size_t(0)](std::size_t x, std::size_t) mutable {
          return x == b[(r + k++) % b.size()];
        }))
      return true;
  return false;
}

void expect_self_contained(const std::string& html, const std::string& what) {
  EXPECT_TRUE(has(html, "<!DOCTYPE html>")) << what;
  EXPECT_FALSE(has(html, "<script src")) << what;
  EXPECT_FALSE(has(html, "<link")) << what;
  EXPECT_FALSE(has(html, "@import")) << what;
  EXPECT_FALSE(has(html, "https://")) << what;
  // The only http:// text is the SVG and XLink namespaces (names, never fetched).
  std::string rest = html;
  for (const char* ns : {"http://www.w3.org/2000/svg", "http://www.w3.org/1999/xlink"})
    for (auto at = rest.find(ns); at != std::string::npos; at = rest.find(ns)) rest.erase(at, std::string(ns).size());
  EXPECT_FALSE(has(rest, "http://")) << what;
  EXPECT_TRUE(has(page_data(html), "<svg")) << what;  // the frames, inside the packed data
}

// Every step of a page is drawn in both models, so the pages cost some CPU per point: 8 points
// here, 12 under the `long` label (tests/long.cmake).
std::size_t animated_points() { return testing::scale() == 1 ? 8 : 12; }

TEST_F(AnimateCli, HullAlgorithmsEndWithTheHullOfTHull) {
  generate("u.t2", gen::Kind::uniform, animated_points(), 5);
  generate("both.t2", gen::Kind::both_sides, animated_points(), 3);
  generate("back.t2", gen::Kind::both_sides, animated_points(), 4, 1.0);  // every point behind
  for (const char* file : {"u.t2", "both.t2", "back.t2"})
    for (const std::string algo : {"jarvis", "graham", "merge", "chan"}) {
      const std::string what = algo + " " + file;
      const Result r = t2("animate " + algo + " " + file + " -o out.html");
      ASSERT_EQ(r.status, 0) << what << r.err;
      EXPECT_TRUE(has(r.out, "out.html: ")) << r.out;
      const std::string page = slurp(dir_ / "out.html");
      expect_self_contained(page, what);
      const std::string html = page_data(page);  // the steps as JSON text
      const Result h = t2(std::string("hull ") + file + " --algorithm " + algo);  // one name, one algorithm
      ASSERT_EQ(h.status, 0);
      EXPECT_TRUE(same_cycle(numbers(last_step_field(html, "chain")), numbers(h.out)))
          << what << ": " << last_step_field(html, "chain") << " vs " << h.out;
      // The merge of the points of one half (front or back) merges nothing: that half's chain is
      // the whole algorithm, shown at the lecture level (hull_recorder.hpp), and there is no
      // deeper step; on both sides the lecture level shows the two halves' hulls.
      const bool merge = algo == "merge", one_half = merge && std::string(file) != "both.t2";
      EXPECT_EQ(has(html, "\"depth\":1"), !one_half) << what << ": debugging steps";
      EXPECT_EQ(has(html, "The hull of the positive half"), merge && !one_half) << what;
      EXPECT_EQ(has(html, "The hull of the negative half"), merge && !one_half) << what;
      if (merge && one_half) {
        EXPECT_TRUE(has(html, "\"kind\":\"pop\"")) << what << ": the chain's pops";
      }
    }
}

// The last step of each triangulation's page, decoded (animate_testing.hpp), is the library's
// answer: `t2 animate triangulate` is what `t2 triangulate` runs (the sweep on front points),
// `t2 animate triangulate-t2` what `t2::triangulate_t2` runs.
TEST_F(AnimateCli, TriangulationsEndWithTheTriangulation) {
  const auto P = generate("d.t2", gen::Kind::disk, animated_points(), 2);
  for (const std::string algo : {"delaunay", "triangulate", "triangulate-t2"}) {
    const Result r = t2("animate " + algo + " d.t2 -o " + algo + ".html");
    ASSERT_EQ(r.status, 0) << algo << r.err;
    const std::string page = slurp(dir_ / (algo + ".html"));
    expect_self_contained(page, algo);
    const auto steps = page_steps(page);
    const std::string html = page_data(page);  // the steps as JSON text
    ASSERT_FALSE(steps.empty());
    const Triangulation answer = algo == "delaunay"      ? delaunay(P)
                                 : algo == "triangulate" ? triangulate(P)
                                                         : triangulate_t2(P).tr;
    EXPECT_EQ(steps.back().triangles, sorted_triangles(answer)) << algo;
    EXPECT_TRUE(has(html, "\"kind\":\"flip\"")) << algo;  // these 8 disk points need flips in all three
    EXPECT_EQ(has(html, "\"kind\":\"in-circle\""), algo == "delaunay");
  }
}

// What a frame shows is what its step says: a step that speaks of a circle draws one (the
// overlay's stroke appears in its frame and in no other).
TEST_F(AnimateCli, FramesDrawTheCircleTheyName) {
  generate("d.t2", gen::Kind::uniform, 12, 4);
  ASSERT_EQ(t2("animate delaunay d.t2 -o d.html").status, 0);
  std::size_t circles = 0;
  for (const auto& s : page_steps(slurp(dir_ / "d.html"))) {
    const std::string text = s.step.at("text");
    const bool speaks = text.find("circle") != std::string::npos;
    circles += speaks;
    EXPECT_EQ(has(s.svg, kOverlayStroke), speaks) << text;
  }
  EXPECT_GT(circles, 5u);
}

TEST_F(AnimateCli, BadInputNoHullAndTooManyPointsLeaveTheOutputAlone) {
  write("out.html", "old");
  write("bad.t2", "0 0\n1 x\n");
  Result r = t2("animate graham bad.t2 -o out.html");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "bad.t2:2")) << r.err;
  write("anti.t2", "1 1\n0 1\n-1 -1 -1\n");
  for (const char* algo : {"jarvis", "graham", "merge"}) {
    r = t2(std::string("animate ") + algo + " anti.t2 -o out.html");
    EXPECT_EQ(r.status, 3) << algo;
    EXPECT_TRUE(has(r.err, "p0 and p2 are antipodal")) << r.err;
  }
  r = t2("animate delaunay anti.t2 -o out.html");  // a back point: not animated
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "front points only")) << r.err;
  generate("many.t2", gen::Kind::uniform, 201, 1);
  r = t2("animate graham many.t2 -o out.html");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(has(r.err, "at most 200 points")) << r.err;
  r = t2("animate quickhull bad.t2 -o out.html");
  EXPECT_EQ(r.status, 2);
  r = t2("animate graham bad.t2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(slurp(dir_ / "out.html"), "old");
  EXPECT_EQ(files(), (std::vector<std::string>{"anti.t2", "bad.t2", "many.t2", "out.html"}));  // no temporary left
}

// The house issue's weight: a page of 200 uniform points at most 1 MB, for the algorithms whose
// debugging steps each draw a new circle (an in-circle test, a candidate circle, a circle event).
// The unit run takes 40 points and 320 KB (their pages unpacked weigh 0.44-0.85 MB); the long run
// the 200 points and the 1 MB.
TEST_F(AnimateCli, PagesOfTwoHundredPointsWeighAtMostOneMegabyte) {
  const std::size_t n = testing::scale() == 1 ? 40 : 200;
  ASSERT_EQ(t2("gen uniform --n " + std::to_string(n) + " --seed 3 -o u.t2").status, 0);
  for (const char* algo : {"delaunay", "sec", "fortune"}) {
    const Result r = t2(std::string("animate ") + algo + " u.t2 -o w.html");
    ASSERT_EQ(r.status, 0) << algo << ": " << r.err;
    EXPECT_LE(std::filesystem::file_size(dir_ / "w.html"), std::min<std::size_t>(n * 8000, 1000000))
        << algo << " at " << n << " points";
    EXPECT_GE(page_steps(slurp(dir_ / "w.html")).size(), n) << algo;  // every step is in it
  }
}

TEST_F(AnimateCli, DegenerateInputsStillAnimate) {
  write("one.t2", "0 0\n0 0\n");
  write("line.t2", "0 0\n1 1\n2 2\n");
  write("none.t2", "# nothing\n");
  for (const char* file : {"one.t2", "line.t2", "none.t2"})
    for (const char* algo : {"jarvis", "graham", "merge", "triangulate", "triangulate-t2", "delaunay", "sec"}) {
      const Result r = t2(std::string("animate ") + algo + " " + file + " -o x.html");
      EXPECT_EQ(r.status, 0) << algo << " " << file << r.err;
      EXPECT_TRUE(has(page_data(slurp(dir_ / "x.html")), "\"kind\":\"answer\"")) << algo << " " << file;
    }
  const Result r = t2("animate graham line.t2 -o x.html");
  EXPECT_EQ(numbers(last_step_field(page_data(slurp(dir_ / "x.html")), "chain")), (std::vector<std::size_t>{0, 2}));
}

// The "Watch it" commands of chapters 06-10 and 12 name an algorithm of t2 animate and a valid data
// file; under the long label they run as printed, from the top of the repository (here a folder
// whose data/ is the repository's), and write their pages (some seconds of CPU in all).
TEST_F(AnimateCli, TheChaptersWatchItCommandsRun) {
  fs::create_directory_symlink(fs::path(T2_SOURCE_DIR) / "data", dir_ / "data");
  const std::regex command("t2 animate ([a-z0-9-]+) (data/examples/[a-z0-9-]+\\.t2) -o ([a-z]+\\.html)");
  int commands = 0;
  for (const char* ch : {"06-convex-hull", "07-calipers", "09-triangulation", "10-delaunay", "12-proximity"}) {
    std::string md;  // the chapter's text: chapter.md, then its later parts chapter-2.md ...
    for (int k = 1;; ++k) {
      const fs::path part = fs::path(T2_SOURCE_DIR) / "chapters" / ch /
                            (k == 1 ? std::string("chapter.md") : "chapter-" + std::to_string(k) + ".md");
      if (!fs::exists(part)) break;
      md += t2::read_file(part);
    }
    int in_chapter = 0;
    for (std::sregex_iterator m(md.begin(), md.end(), command), end; m != end; ++m, ++in_chapter, ++commands) {
      const std::string algo = (*m)[1], file = (*m)[2], out = (*m)[3];
      EXPECT_TRUE(algo == "jarvis" || algo == "graham" || algo == "merge" || algo == "triangulate" ||
                  algo == "triangulate-t2" || algo == "delaunay" || algo == "sec" || algo == "emst" || algo == "lec" ||
                  algo == "closest-pair-divide" || algo == "chan")
          << ch << ": " << m->str();
      EXPECT_NO_THROW((void)read_scene(dir_ / file)) << ch << ": " << m->str();
      if (testing::scale() == 1) continue;
      const Result r = t2(m->str().substr(3));
      EXPECT_EQ(r.status, 0) << ch << ": " << m->str() << ": " << r.err;
      EXPECT_TRUE(slurp(dir_ / out).starts_with("<!DOCTYPE html")) << m->str();
    }
    EXPECT_GE(in_chapter, 1) << ch << " links no animation on a data file";
  }
  EXPECT_GE(commands, 5);
}

}  // namespace
}  // namespace t2::testing
