// The book system as authors meet it: `t2 book check|sync` on a small repository made here
// (drift, missing markers, missing figures and links, quoted program output), `t2 list` and
// `t2 run`. The HTML book and the browser: test_book_html.cpp.
// Tests that need pandoc (every check) skip, saying so, without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "book_testing.hpp"

namespace fs = std::filesystem;

namespace {

using namespace t2::book_testing;

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

}  // namespace
