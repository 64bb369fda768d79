// The book system as readers meet it: the HTML book of a small repository and of this one
// (every page, every local link, anchor and image), and headless Chromium loading the pages
// (images decoded, MathML laid out, a screenshot). Check, sync, list, run: test_book.cpp.
// Tests that need pandoc (every build) or Chromium skip, saying so, without them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "book_testing.hpp"

namespace fs = std::filesystem;

namespace {

using namespace t2::book_testing;

// ---- the HTML book ------------------------------------------------------------------------

// Every local href/src of an HTML page, with the fragment split off.
struct Ref {
  std::string attr, path, fragment;
};
std::vector<Ref> local_refs(const std::string& html) {
  std::vector<Ref> out;
  static const std::regex re(R"re(\b(href|src)="([^"]*)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), re); it != std::sregex_iterator(); ++it) {
    const std::string v = (*it)[2];
    if (std::regex_search(v, std::regex("^[a-zA-Z][a-zA-Z0-9+.-]*:"))) continue;  // http:, data:, mailto:
    const auto h = v.find('#');
    out.push_back({(*it)[1], v.substr(0, h), h == std::string::npos ? "" : v.substr(h + 1)});
  }
  return out;
}

std::set<std::string> ids(const std::string& html) {
  std::set<std::string> out;
  static const std::regex re(R"re(\bid="([^"]*)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), re); it != std::sregex_iterator(); ++it)
    out.insert((*it)[1]);
  return out;
}

// Checks every page of a built book: local targets exist, anchors exist in local pages.
void expect_no_broken_links(const fs::path& out) {
  int pages = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    if (e.path().extension() != ".html") continue;
    ++pages;
    const std::string html = slurp(e.path());
    const auto own = ids(html);
    for (const auto& r : local_refs(html)) {
      if (r.path.empty()) {
        EXPECT_TRUE(own.count(r.fragment)) << e.path().filename() << ": no anchor #" << r.fragment;
        continue;
      }
      const fs::path target = out / r.path;
      EXPECT_TRUE(fs::exists(target)) << e.path().filename() << ": " << r.attr << "=" << r.path << " does not exist";
      if (!r.fragment.empty() && target.extension() == ".html" && fs::exists(target) &&
          fs::weakly_canonical(target).string().find(fs::weakly_canonical(out).string()) == 0) {
        EXPECT_TRUE(ids(slurp(target)).count(r.fragment)) << e.path().filename() << ": no anchor " << r.path << "#" << r.fragment;
      }
    }
  }
  EXPECT_GT(pages, 0);
}

TEST(BookBuild, SmallRepositoryMakesLinkedPages) {
  T2_NEEDS_PANDOC();
  TempDir t;
  make_repo(t.path / "repo");
  const fs::path out = t.path / "out";
  const Result r = run(tool() + " book build --quiet --root " + (t.path / "repo").string() + " --out " + out.string() +
                       " --docs " + (fs::path(T2_BINARY_DIR) / "docs").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string index = slurp(out / "index.html"), a = slurp(out / "01-alpha.html"), b = slurp(out / "02-beta.html");
  EXPECT_NE(index.find("Part I — The oriented projective plane"), std::string::npos) << index;
  EXPECT_EQ(index.find("Part II"), std::string::npos);  // no chapter of part II exists
  EXPECT_NE(index.find("href=\"01-alpha.html\""), std::string::npos);
  EXPECT_NE(index.find("href=\"02-beta.html\""), std::string::npos);
  // Previous/next links, .md links rewritten to pages, the figure as <img>, math as MathML.
  EXPECT_NE(a.find("rel=\"next\" href=\"02-beta.html\""), std::string::npos);
  EXPECT_EQ(a.find("rel=\"prev\""), std::string::npos);
  EXPECT_NE(b.find("rel=\"prev\" href=\"01-alpha.html\""), std::string::npos);
  EXPECT_NE(a.find("href=\"02-beta.html#more\""), std::string::npos) << a;
  EXPECT_NE(b.find("href=\"01-alpha.html\""), std::string::npos);
  EXPECT_NE(a.find("<img src=\"figures/01-alpha/circle.svg\""), std::string::npos) << a;
  EXPECT_NE(a.find("<math display=\"block\""), std::string::npos);
  EXPECT_EQ(a.find("$$"), std::string::npos);
  EXPECT_NE(a.find("class=\"sourceCode cpp\""), std::string::npos);  // highlighted listing
  if (fs::exists(fs::path(T2_BINARY_DIR) / "docs" / "t2.tag")) {
    EXPECT_TRUE(std::regex_search(a, std::regex(R"re(<a\s+href="[^"]*docs/html/[^"]+"\s+class="api"><code>t2::orient</code>)re"))) << a;
  }
  expect_no_broken_links(out);
}

// The book of this repository, built once for the tests below.
const fs::path& real_book() {
  static TempDir dir;
  static bool built = false;
  if (!built) {
    built = true;
    const Result r = run(tool() + " book build --quiet --out " + (dir.path / "book").string() + " --docs " +
                         (fs::path(T2_BINARY_DIR) / "docs").string());
    EXPECT_EQ(r.status, 0) << r.output;
  }
  static const fs::path p = dir.path / "book";
  return p;
}

std::vector<std::string> chapter_folders() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(fs::path(T2_SOURCE_DIR) / "chapters"))
    if (e.is_directory() && fs::exists(e.path() / "chapter.md") &&
        std::regex_match(e.path().filename().string(), std::regex("[0-9][0-9]-[a-z0-9-]+")))
      out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(BookBuild, EveryChapterOfThisRepositoryHasAPageAndNoBrokenLink) {
  // The optimized tree builds this repository's book (build.sh's build, 32 s); under the
  // sanitizers the same book code runs on SmallRepositoryMakesLinkedPages, and pandoc, which
  // takes most of this test's 47 s there, is not ours to sanitize.
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the whole book is built in the optimized tree";
  T2_NEEDS_PANDOC();
  const fs::path& out = real_book();
  ASSERT_TRUE(fs::exists(out / "index.html"));
  const std::string index = slurp(out / "index.html");
  const auto folders = chapter_folders();
  for (std::size_t i = 0; i < folders.size(); ++i) {
    const std::string page = folders[i] + ".html";
    ASSERT_TRUE(fs::exists(out / page)) << page;
    EXPECT_NE(index.find("href=\"" + page + "\""), std::string::npos) << page;
    const std::string html = slurp(out / page);
    if (i + 1 < folders.size()) {
      EXPECT_NE(html.find("rel=\"next\" href=\"" + folders[i + 1] + ".html\""), std::string::npos) << page;
    }
    if (i > 0) {
      EXPECT_NE(html.find("rel=\"prev\" href=\"" + folders[i - 1] + ".html\""), std::string::npos) << page;
    }
    if (fs::exists(fs::path(T2_SOURCE_DIR) / "exercises" / folders[i] / "README.md")) {
      EXPECT_NE(html.find("href=\"exercises-" + folders[i] + ".html\""), std::string::npos) << page;
    }
    EXPECT_EQ(html.find("$$"), std::string::npos) << page << ": display math left unrendered";
  }
  expect_no_broken_links(out);
}

// ---- headless Chromium ---------------------------------------------------------------------

// Loads a copy of `page` with a probe script in Chromium and returns the dumped DOM.
std::string probe(const fs::path& dir, const std::string& page, const fs::path& profile) {
  std::string html = slurp(dir / page);
  const std::string script =
      "<script>window.addEventListener('load', () => {"
      " const imgs = [...document.images];"
      " const bad = imgs.filter(i => !i.complete || i.naturalWidth === 0).map(i => i.getAttribute('src'));"
      " const flat = [...document.querySelectorAll('math')].filter(m => m.getBoundingClientRect().height === 0).length;"
      " const r = document.createElement('pre'); r.id = 't2-probe';"
      " r.textContent = 'images=' + imgs.length + ' broken=[' + bad.join(' ') + '] flatmath=' + flat;"
      " document.body.appendChild(r); });</script>";
  html.insert(html.rfind("</body>"), script);
  const std::string copy = "probe-" + page;
  spit(dir / copy, html);
  const Result r = run(
      "chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking "
      "--disable-component-update --disable-sync --user-data-dir=" +
      profile.string() + " --virtual-time-budget=10000 --dump-dom file://" + (dir / copy).string());
  fs::remove(dir / copy);
  return r.output;
}

#define T2_NEEDS_CHROMIUM() \
  if (!have_program("chromium")) GTEST_SKIP() << "chromium is not installed (scripts/deps.sh): skipped"

TEST(BookBrowser, ImagesLoadAndMathIsLaidOutInChromium) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the browser tests do not run under sanitizers";
  T2_NEEDS_PANDOC();
  T2_NEEDS_CHROMIUM();
  const fs::path& out = real_book();
  TempDir profile;
  std::vector<std::string> pages = {"index.html"};
  for (const auto& f : chapter_folders()) pages.push_back(f + ".html");
  static const std::regex re(R"(images=(\d+) broken=\[([^\]]*)\] flatmath=(\d+))");
  for (const auto& page : pages) {
    const std::string dom = probe(out, page, profile.path);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(dom, m, re)) << page << ": the probe did not run\n" << dom.substr(0, 2000);
    EXPECT_EQ(m[2].str(), "") << page << ": images that did not load";
    EXPECT_EQ(m[3].str(), "0") << page << ": MathML elements with no height";
    const std::string html = slurp(out / page);
    std::size_t imgs = 0;
    for (auto p = html.find("<img "); p != std::string::npos; p = html.find("<img ", p + 1)) ++imgs;
    EXPECT_EQ(std::stoul(m[1].str()), imgs) << page;  // Chromium saw every image of the page
  }
}

TEST(BookBrowser, ScreenshotsOfContentsAndAChapter) {
  if (std::getenv("T2_SANITIZED")) GTEST_SKIP() << "the browser tests do not run under sanitizers";
  T2_NEEDS_PANDOC();
  T2_NEEDS_CHROMIUM();
  const fs::path& out = real_book();
  const auto folders = chapter_folders();
  std::vector<std::string> pages = {"index.html"};
  if (!folders.empty()) pages.push_back(folders.front() + ".html");
  // Kept in the build directory, for a human to look at: build/<dir>/book-screenshots/.
  const fs::path shots = fs::path(T2_BINARY_DIR) / "book-screenshots";
  fs::create_directories(shots);
  for (const auto& page : pages) {
    TempDir profile;
    const fs::path png = shots / (fs::path(page).stem().string() + ".png");
    fs::remove(png);
    const Result r = run(
        "chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking "
        "--disable-component-update --disable-sync --hide-scrollbars --window-size=1200,1600 --user-data-dir=" +
        profile.path.string() + " --virtual-time-budget=10000 --screenshot=" + png.string() + " file://" +
        (out / page).string());
    ASSERT_TRUE(fs::exists(png)) << r.output;
    const std::string data = slurp(png);
    EXPECT_EQ(data.substr(1, 3), "PNG");
    EXPECT_GT(data.size(), 10000u) << page << ": a nearly empty screenshot";
  }
}

}  // namespace
