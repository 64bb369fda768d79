// A chapter in several files and a chapter with several exercise sheets, as `t2 book check`,
// `t2 book sync` and `t2 book build` meet them: chapter.md continued in chapter-2.md ... is
// checked file by file (listings, links, widths, quoted output) and built as one page; every
// exercises/NN-slug/ and exercises/NNx-slug/ with a README.md gets a page, linked from the
// contents and from its chapter, with no list to edit when a sheet is added.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "cli_testing.hpp"

namespace {

namespace fs = std::filesystem;

class BookParts : public t2::testing::CliTest {
 protected:
  // Chapter 01 in three parts (a listing in part 2, a figure in part 3, a quoted output block
  // in part 3 printed by its program), chapter 02 in one; exercise sheets 01, 01b, 01c of
  // chapter 01, 02 of chapter 02, and folders that are no sheet of a chapter.
  void make_repo() {
    write("chapters/01-alpha/main.cpp", "int main() {\n  //> greet\n  int n = 3;\n  //< greet\n}\n");
    write("chapters/01-alpha/chapter.md",
        "# Alpha\n\n## One\n\nFirst part. See [two](chapter-2.md#two).\n\n"
        "*Continued in [chapter-2.md](chapter-2.md).*\n");
    write("chapters/01-alpha/chapter-2.md",
        "## Two\n\n<!-- listing: chapters/01-alpha/main.cpp#greet -->\n```cpp\nint n = 3;\n```\n\n"
        "Continued in [chapter-3.md](chapter-3.md).\n");
    write("chapters/01-alpha/chapter-3.md",
        "## Three\n\n![A dot.](../../figures/01-alpha/dot.svg)\n\nIt prints:\n\n```text\nthree\n```\n\n"
        "Back to [part one](chapter.md#one) and [beta](../02-beta/chapter.md).\n");
    write("chapters/02-beta/chapter.md", "# Beta\n\nSee [alpha, part three](../01-alpha/chapter-3.md#three).\n");
    write("figures/01-alpha/dot.svg",
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"8\" height=\"8\"><circle cx=\"4\" cy=\"4\" r=\"3\"/></svg>\n");
    // The chapter's "program": a script that prints the quoted line.
    write("bin/chapter_01", "#!/bin/sh\necho three\n");
    fs::permissions(dir_ / "bin/chapter_01", fs::perms::owner_all);
    for (const char* ex : {"01-alpha", "01b-more", "01c-last", "02-beta"})
      write(std::string("exercises/") + ex + "/README.md", std::string("# Sheet ") + ex + "\n\nDo it.\n");
    write("exercises/01d-no-readme/notes.txt", "not a sheet: no README.md\n");
    write("exercises/_template/README.md", "# Template\n");
    write("exercises/010-x/README.md", "# Not chapter 01\n");
    fs::create_directories(dir_ / "book");
    for (const char* f : {"template.html", "book.lua", "style.css", "parts.txt"})
      fs::copy_file(fs::path(T2_SOURCE_DIR) / "book" / f, dir_ / "book" / f, fs::copy_options::overwrite_existing);
  }

  t2::testing::Result check() { return t2("book check --root . --programs bin"); }
};

TEST_F(BookParts, EveryPartIsCheckedAndSynced) {
  T2_NEEDS_PANDOC();
  make_repo();
  const auto clean = check();
  EXPECT_EQ(clean.status, 0) << clean.out << clean.err;
  EXPECT_NE(clean.out.find("2 chapter(s), 1 listing(s)"), std::string::npos) << clean.out;
  EXPECT_NE(clean.out.find("1 quoted output block(s)"), std::string::npos) << clean.out;

  // Drift in part 2, a missing figure in part 3, an unprinted line quoted in part 3: each
  // reported at its own file and line.
  write("chapters/01-alpha/main.cpp", "int main() {\n  //> greet\n  int n = 4;\n  //< greet\n}\n");
  fs::remove(dir_ / "figures/01-alpha/dot.svg");
  write("bin/chapter_01", "#!/bin/sh\necho four\n");
  const auto bad = check();
  const std::string said = bad.out + bad.err;
  EXPECT_EQ(bad.status, 1) << said;
  EXPECT_NE(said.find("chapters/01-alpha/chapter-2.md:3: listing chapters/01-alpha/main.cpp#greet differs"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("chapters/01-alpha/chapter-3.md:3: figure ../../figures/01-alpha/dot.svg does not exist"), std::string::npos)
      << said;
  EXPECT_NE(said.find("chapters/01-alpha/chapter-3.md:8: the output block quotes a line that chapter_01 does not "
                      "print"),
            std::string::npos)
      << said;

  // sync rewrites the listing of part 2 and leaves the other files alone.
  const std::string one = t2::testing::slurp(dir_ / "chapters/01-alpha/chapter.md");
  const auto sync = t2("book sync --root .");
  EXPECT_EQ(sync.status, 0) << sync.out << sync.err;
  EXPECT_NE(sync.out.find("rewrote listings of chapters/01-alpha/chapter-2.md"), std::string::npos) << sync.out;
  EXPECT_NE(t2::testing::slurp(dir_ / "chapters/01-alpha/chapter-2.md").find("int n = 4;"), std::string::npos);
  EXPECT_EQ(t2::testing::slurp(dir_ / "chapters/01-alpha/chapter.md"), one);
}

TEST_F(BookParts, PartsAreNumberedWithoutGapsAndOnlyTheFirstHasTheTitle) {
  T2_NEEDS_PANDOC();
  make_repo();
  fs::rename(dir_ / "chapters/01-alpha/chapter-3.md", dir_ / "chapters/01-alpha/chapter-4.md");
  auto r = check();
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("chapters/01-alpha/chapter-4.md:1: the parts of a chapter are chapter.md, chapter-2.md, "
                       "chapter-3.md, ... with no gap: chapter-3.md is missing (the part after chapter-2.md)"),
            std::string::npos)
      << r.err;
  fs::rename(dir_ / "chapters/01-alpha/chapter-4.md", dir_ / "chapters/01-alpha/chapter-3.md");
  write("chapters/01-alpha/chapter-2.md", "# Two\n\nA second title.\n");
  r = check();
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("chapters/01-alpha/chapter-2.md:1: only chapter.md has the chapter's '# Title'"),
            std::string::npos)
      << r.err;
}

TEST_F(BookParts, OnePagePerChapterAndEveryExerciseSheetLinked) {
  T2_NEEDS_PANDOC();
  make_repo();
  const auto r = t2("book build --quiet --root . --out out --docs nodocs");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const fs::path out = dir_ / "out";
  // One page for the three parts of chapter 01, in their order; the "Continued in" lines,
  // navigation between the source files, are not on it.
  EXPECT_FALSE(fs::exists(out / "01-alpha-2.html"));
  const std::string a = t2::testing::slurp(out / "01-alpha.html");
  const auto one = a.find("First part."), two = a.find("id=\"two\""), three = a.find("dot.svg");
  ASSERT_NE(one, std::string::npos) << a;
  ASSERT_NE(two, std::string::npos) << a;
  ASSERT_NE(three, std::string::npos) << a;
  EXPECT_LT(one, two);
  EXPECT_LT(two, three);
  EXPECT_EQ(a.find("Continued in"), std::string::npos) << a;
  // Links to a part, from the chapter or from another, land on the chapter's page.
  EXPECT_NE(a.find("href=\"01-alpha.html#two\""), std::string::npos) << a;
  EXPECT_NE(a.find("href=\"01-alpha.html#one\""), std::string::npos) << a;
  EXPECT_NE(a.find("id=\"three\""), std::string::npos) << a;
  const std::string b = t2::testing::slurp(out / "02-beta.html");
  EXPECT_NE(b.find("href=\"01-alpha.html#three\""), std::string::npos) << b;

  // Every sheet of the chapter, found by its folder's name alone, has a page linked from the
  // contents and from the chapter's bar; the others are no sheet of chapter 01.
  const std::string index = t2::testing::slurp(out / "index.html");
  for (const std::string ex : {"01-alpha", "01b-more", "01c-last"}) {
    const std::string page = "exercises-" + ex + ".html";
    EXPECT_TRUE(fs::exists(out / page)) << page;
    EXPECT_NE(index.find("href=\"" + page + "\""), std::string::npos) << page << "\n" << index;
    EXPECT_NE(a.find("href=\"" + page + "\""), std::string::npos) << page;
    EXPECT_EQ(b.find("href=\"" + page + "\""), std::string::npos) << page;
  }
  EXPECT_NE(b.find("href=\"exercises-02-beta.html\""), std::string::npos) << b;
  EXPECT_NE(index.find(">01b</a>"), std::string::npos) << index;
  for (const char* not_sheet : {"exercises-01d-no-readme.html", "exercises-_template.html", "exercises-010-x.html"})
    EXPECT_FALSE(fs::exists(out / not_sheet)) << not_sheet;
  // The sheet's page leads up to its chapter.
  EXPECT_NE(t2::testing::slurp(out / "exercises-01c-last.html").find("href=\"01-alpha.html\""), std::string::npos);
}

}  // namespace
