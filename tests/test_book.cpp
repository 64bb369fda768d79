// The book system as authors and readers meet it: `t2 book check|sync` on a small repository
// made here (drift, missing markers, missing figures and links), `t2 list`, `t2 run`, the HTML
// book of this repository (every page, every local link and image), and headless Chromium
// loading the pages (images decoded, MathML laid out, a screenshot).
// Tests that need pandoc (every check and build) or Chromium skip, saying so, without them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_testing.hpp"

namespace fs = std::filesystem;

namespace {

using t2::testing::have_program;
using t2::testing::slurp;

struct Result {
  int status = -1;
  std::string output;  // stdout and stderr
};

Result run(const std::string& cmd) {
  const auto r = t2::testing::shell(cmd);
  return {r.status, r.out};
}

#define T2_NEEDS_PANDOC() \
  if (!have_program("pandoc")) GTEST_SKIP() << "pandoc is not installed (the Debian package pandoc): skipped"

std::string tool() { return T2_TOOL; }

void spit(const fs::path& p, const std::string& s) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << s;
}

// A fresh temporary directory, removed at the end of the test.
struct TempDir {
  fs::path path;
  TempDir() {
    std::string t = (fs::temp_directory_path() / "t2-book-XXXXXX").string();
    path = ::mkdtemp(t.data());
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// A tiny repository: two chapters, a source file with a region, a figure.
void make_repo(const fs::path& root) {
  spit(root / "chapters/01-alpha/main.cpp",
       "#include <cstdio>\n"
       "int main() {\n"
       "  //> greet\n"
       "  int n = 3;\n"
       "  if (n > 2) {\n"
       "    std::puts(\"hello\");\n"
       "  }\n"
       "  //< greet\n"
       "}\n");
  spit(root / "chapters/01-alpha/chapter.md",
       "# Alpha and $T^2$\n\n"
       "Text with `t2::orient` and a [link](../02-beta/chapter.md#more).\n\n"
       "<!-- listing: chapters/01-alpha/main.cpp#greet -->\n"
       "```cpp\n"
       "int n = 3;\n"
       "if (n > 2) {\n"
       "  std::puts(\"hello\");\n"
       "}\n"
       "```\n\n"
       "![A circle.](../../figures/01-alpha/circle.svg)\n\n"
       "$$ \\det(p, q, r) > 0 $$\n");
  spit(root / "chapters/02-beta/chapter.md", "# Beta\n\n## More\n\nBack to [alpha](../01-alpha/chapter.md).\n");
  spit(root / "figures/01-alpha/circle.svg",
       "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"80\" height=\"40\"><circle cx=\"20\" cy=\"20\" r=\"15\" "
       "fill=\"#1f77b4\"/></svg>\n");
  fs::create_directories(root / "book");
  for (const char* f : {"template.html", "book.lua", "style.css", "parts.txt"})
    fs::copy_file(fs::path(T2_SOURCE_DIR) / "book" / f, root / "book" / f);
}

// The lines of the listing block that follows the listing comment in a chapter.md.
std::vector<std::string> listing_lines(const std::string& md) {
  std::vector<std::string> out;
  const auto at = md.find("<!-- listing:");
  if (at == std::string::npos) return out;
  auto open = md.find("```cpp\n", at);
  if (open == std::string::npos) return out;
  open += 7;
  const auto close = md.find("\n```", open - 1);
  std::string body = md.substr(open, close - open + 1);
  std::size_t s = 0, e;
  while ((e = body.find('\n', s)) != std::string::npos) {
    out.push_back(body.substr(s, e - s));
    s = e + 1;
  }
  return out;
}

TEST(BookCheck, ThisRepositoryIsInSync) {
  T2_NEEDS_PANDOC();
  const Result r = run(tool() + " book check");
  EXPECT_EQ(r.status, 0) << r.output;
  // The chapters' quoted output was checked against their programs (built with the tool).
  EXPECT_NE(r.output.find("quoted output block(s), each printed by its chapter program"), std::string::npos)
      << r.output;
}

// Chapter 01 of make_repo() quoting `block` as program output; the program is a shell script
// in <root>/bin that runs `script`. Returns what `t2 book check --programs` says.
Result check_quoted_output(const TempDir& t, const std::string& block, const std::string& script) {
  make_repo(t.path);
  const fs::path md = t.path / "chapters/01-alpha/chapter.md";
  spit(md, slurp(md) + "\nThe program prints:\n\n```text\n" + block + "```\n");
  const fs::path exe = t.path / "bin/chapter_01";
  spit(exe, "#!/bin/sh\n" + script);
  fs::permissions(exe, fs::perms::owner_all);
  return run(tool() + " book check --root " + t.path.string() + " --programs " + (t.path / "bin").string());
}

TEST(BookCheck, QuotedOutputMustBePrintedByTheChapterProgramInOrder) {
  T2_NEEDS_PANDOC();
  const std::string prints = "echo alpha; echo '  beta  '; echo gamma; echo figures >&2\n";
  {
    TempDir t;  // the whole output, with its indentation; trailing spaces do not matter
    const Result r = check_quoted_output(t, "alpha\n  beta\ngamma\n", prints);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("1 quoted output block(s)"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("figures"), std::string::npos) << r.output;  // the program's stderr is kept quiet
  }
  {
    TempDir t;  // an excerpt, with a blank line
    EXPECT_EQ(check_quoted_output(t, "alpha\n\ngamma\n", prints).status, 0);
  }
  {
    TempDir t;  // a line the program does not print: reported at its own line of chapter.md
    const Result r = check_quoted_output(t, "delta\nalpha\n", prints);
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string md = slurp(t.path / "chapters/01-alpha/chapter.md");
    const auto lines_before = std::count(md.begin(), md.begin() + md.find("delta"), '\n');
    EXPECT_NE(r.output.find("chapters/01-alpha/chapter.md:" + std::to_string(lines_before + 1) +
                            ": the output block quotes a line that chapter_01 does not print: 'delta'"),
              std::string::npos)
        << r.output;
  }
  {
    TempDir t;  // the right lines in the wrong order
    const Result r = check_quoted_output(t, "gamma\nalpha\n", prints);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("(after the block's previous lines): 'alpha'"), std::string::npos) << r.output;
  }
  {
    TempDir t;  // indentation is part of the line
    EXPECT_EQ(check_quoted_output(t, "beta\n", prints).status, 1);
  }
  {
    TempDir t;  // a program that fails
    const Result r = check_quoted_output(t, "alpha\n", "echo alpha; echo boom >&2; exit 3\n");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("chapter_01 failed (exit status 3): its output blocks are unchecked; it said: boom"),
              std::string::npos)
        << r.output;
  }
  {
    TempDir t;  // no program built: said so; without --programs another root is not checked
    make_repo(t.path);
    const fs::path md = t.path / "chapters/01-alpha/chapter.md";
    spit(md, slurp(md) + "\n```text\nalpha\n```\n");
    const Result missing = run(tool() + " book check --root " + t.path.string() + " --programs " + t.path.string());
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.output.find("chapter_01 is not built in"), std::string::npos) << missing.output;
    const Result unchecked = run(tool() + " book check --root " + t.path.string());
    EXPECT_EQ(unchecked.status, 0) << unchecked.output;
    EXPECT_NE(unchecked.output.find("quoted program output not checked"), std::string::npos) << unchecked.output;
  }
}

TEST(BookCheck, CleanRepositoryPasses) {
  T2_NEEDS_PANDOC();
  TempDir t;
  make_repo(t.path);
  const Result r = run(tool() + " book check --root " + t.path.string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1 listing"), std::string::npos) << r.output;
}

TEST(BookCheck, DriftIsReportedWithChapterListingAndLineThenSyncFixesIt) {
  T2_NEEDS_PANDOC();
  TempDir t;
  make_repo(t.path);
  // The author changes the code: the listing in the chapter is now stale at its 3rd line.
  const fs::path src = t.path / "chapters/01-alpha/main.cpp";
  std::string code = slurp(src);
  code.replace(code.find("hello"), 5, "world");
  spit(src, code);
  const Result r = run(tool() + " book check --root " + t.path.string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("chapters/01-alpha/chapter.md:5"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("chapters/01-alpha/main.cpp#greet"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("line 3 of the listing"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("std::puts(\"world\");"), std::string::npos) << r.output;

  const Result s = run(tool() + " book sync --root " + t.path.string());
  EXPECT_EQ(s.status, 0) << s.output;
  // The oracle: the region as written above, dedented by hand.
  const std::vector<std::string> want = {"int n = 3;", "if (n > 2) {", "  std::puts(\"world\");", "}"};
  const std::string md = slurp(t.path / "chapters/01-alpha/chapter.md");
  EXPECT_EQ(listing_lines(md), want) << md;
  EXPECT_EQ(md.rfind("# Alpha", 0), 0u);
  EXPECT_NE(md.find("![A circle.]"), std::string::npos);  // the rest of the chapter is kept
  EXPECT_EQ(run(tool() + " book check --root " + t.path.string()).status, 0);
  // Syncing again changes nothing.
  EXPECT_EQ(run(tool() + " book sync --root " + t.path.string()).status, 0);
  EXPECT_EQ(slurp(t.path / "chapters/01-alpha/chapter.md"), md);
}

TEST(BookCheck, SyncCreatesTheBlockAfterABareComment) {
  T2_NEEDS_PANDOC();
  TempDir t;
  make_repo(t.path);
  spit(t.path / "chapters/02-beta/chapter.md",
       "# Beta\n\n## More\n\n<!-- listing: chapters/01-alpha/main.cpp#greet -->\n\nAfter.\n");
  EXPECT_EQ(run(tool() + " book check --root " + t.path.string()).status, 1);
  EXPECT_EQ(run(tool() + " book sync --root " + t.path.string()).status, 0);
  const std::string md = slurp(t.path / "chapters/02-beta/chapter.md");
  const std::vector<std::string> want = {"int n = 3;", "if (n > 2) {", "  std::puts(\"hello\");", "}"};
  EXPECT_EQ(listing_lines(md), want) << md;
  EXPECT_NE(md.find("After."), std::string::npos);
  EXPECT_EQ(run(tool() + " book check --root " + t.path.string()).status, 0);
}

TEST(BookCheck, MissingMarkerFigureAndLinkFail) {
  T2_NEEDS_PANDOC();
  {
    TempDir t;
    make_repo(t.path);
    std::string code = slurp(t.path / "chapters/01-alpha/main.cpp");
    code.erase(code.find("  //< greet\n"), 12);
    spit(t.path / "chapters/01-alpha/main.cpp", code);
    const Result r = run(tool() + " book check --root " + t.path.string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("//< greet"), std::string::npos) << r.output;
    EXPECT_EQ(run(tool() + " book sync --root " + t.path.string()).status, 1);  // sync cannot fix it
  }
  {
    TempDir t;
    make_repo(t.path);
    fs::remove(t.path / "figures/01-alpha/circle.svg");
    const Result r = run(tool() + " book check --root " + t.path.string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("circle.svg"), std::string::npos) << r.output;
  }
  {
    TempDir t;
    make_repo(t.path);
    spit(t.path / "chapters/02-beta/chapter.md", "# Beta\n\nSee [gone](../03-gamma/chapter.md) and `[not](a-link.md)`.\n");
    const Result r = run(tool() + " book check --root " + t.path.string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("chapters/02-beta/chapter.md:3: link target ../03-gamma/chapter.md"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("a-link.md"), std::string::npos) << r.output;  // inline code is not a link
  }
}

TEST(BookCheck, LinksAndOutputBlocksAreThoseOfPandocsReading) {
  T2_NEEDS_PANDOC();
  TempDir t;
  make_repo(t.path);
  // A link written over two lines, a reference link, an autolink to a web page, a link in an
  // HTML comment and one in inline code: the first two are checked, the others are not links.
  spit(t.path / "chapters/02-beta/chapter.md",
       "# Beta\n\nSee [the\ngone one](../03-gamma/chapter.md), [a ref][r], <https://example.org/x.md>,\n"
       "<!-- [hidden](nowhere.md) --> and `[not](a-link.md)`.\n\n[r]: missing%20ref.md\n");
  // Output quoted in a ~~~ fence with attributes, not only in ```text.
  const fs::path md = t.path / "chapters/01-alpha/chapter.md";
  spit(md, slurp(md) + "\n~~~ {.text}\nalpha\ndelta\n~~~\n");
  const fs::path exe = t.path / "bin/chapter_01";
  spit(exe, "#!/bin/sh\necho alpha\n");
  fs::permissions(exe, fs::perms::owner_all);
  const Result r = run(tool() + " book check --root " + t.path.string() + " --programs " + (t.path / "bin").string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("chapters/02-beta/chapter.md:4: link target ../03-gamma/chapter.md does not exist"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("chapters/02-beta/chapter.md:7: link target missing ref.md does not exist"), std::string::npos)
      << r.output;
  for (const char* not_a_link : {"example.org", "nowhere.md", "a-link.md"})
    EXPECT_EQ(r.output.find(not_a_link), std::string::npos) << not_a_link << "\n" << r.output;
  const std::string text = slurp(md);
  const auto line = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(text.find("delta")), '\n') + 1;
  EXPECT_NE(r.output.find("chapters/01-alpha/chapter.md:" + std::to_string(line) +
                          ": the output block quotes a line that chapter_01 does not print (after the block's previous "
                          "lines): 'delta'"),
            std::string::npos)
      << r.output;
}

TEST(BookList, ListsEveryChapterWithTitleAndProgram) {
  TempDir t;
  make_repo(t.path);
  const Result r = run(tool() + " list --root " + t.path.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(01\s+alpha\s+yes\s+Alpha and \$T\^2\$)"))) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(02\s+beta\s+no\s+Beta)"))) << r.output;
}

TEST(BookRun, BadChapterIsBadUsage) {
  EXPECT_EQ(run(tool() + " run").status, 2);
  EXPECT_EQ(run(tool() + " run 99").status, 2);
  EXPECT_EQ(run(tool() + " book frobnicate").status, 2);
}

TEST(BookRun, RunsTheChapterProgramWithItsArguments) {
  const fs::path exe = fs::path(T2_BINARY_DIR) / "bin" / "chapter_01";
  if (!fs::exists(exe)) GTEST_SKIP() << "chapter_01 is not built in this build directory";
  TempDir t;
  // The oracle is the program itself, run directly with the same arguments.
  const Result direct = run(exe.string() + " --figures " + (t.path / "a").string());
  const Result via = run(tool() + " run --no-build 01 --figures " + (t.path / "b").string());
  EXPECT_EQ(via.status, direct.status);
  EXPECT_EQ(via.output, direct.output);
  EXPECT_FALSE(fs::is_empty(t.path / "b"));
}

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
