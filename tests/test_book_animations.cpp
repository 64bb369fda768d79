// The animations of the book: `t2 book build` runs every `t2 animate ALGO FILE -o NAME.html`
// command of the chapters (a line of a code block or inline code) from the root and writes the
// page to <book>/animations/NAME.html, the same bytes as the command run by hand; a chapter's
// link ../../animations/NAME.html becomes animations/NAME.html and resolves in the book;
// `t2 book check` accepts such a link only when some command writes NAME.html, and reports
// commands that cannot run (unknown algorithm, missing file, one page from two commands).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "cli_testing.hpp"

namespace {

namespace fs = std::filesystem;
using t2::testing::has;
using t2::testing::slurp;

class BookAnimations : public t2::testing::CliTest {
 protected:
  // One chapter in two parts: a command in a code block (with a comment) linked from part 1, an
  // inline command in part 2 linked from part 1 too.
  void make_repo() {
    write("chapters/01-alpha/chapter.md",
        "# Alpha\n\n**Watch it.** [Graham's scan](../../animations/graham.html) and "
        "[Delaunay](../../animations/del.html).\n\n"
        "```sh\nt2 animate graham data/pts.t2 -o graham.html   # also: jarvis\n```\n");
    write("chapters/01-alpha/chapter-2.md", "## More\n\nAnd `t2 animate delaunay data/pts.t2 -o del.html` too.\n");
    write("data/pts.t2", "0 0\n4 0\n4 3\n0 3\n1 1\n2.5 2\n");
    fs::create_directories(dir_ / "book");
    for (const char* f : {"template.html", "book.lua", "style.css", "parts.txt"})
      fs::copy_file(fs::path(T2_SOURCE_DIR) / "book" / f, dir_ / "book" / f, fs::copy_options::overwrite_existing);
  }

  // Every local href and src of an HTML page of `out` that names no existing file.
  static std::vector<std::string> broken_links(const fs::path& out, const std::string& page) {
    static const std::regex ref(R"re((?:href|src)="([^"#:]+)(#[^"]*)?")re");
    const std::string html = slurp(out / page);
    std::vector<std::string> broken;
    for (std::sregex_iterator m(html.begin(), html.end(), ref), end; m != end; ++m)
      if (!fs::exists(out / (*m)[1].str())) broken.push_back((*m)[1]);
    return broken;
  }
};

TEST_F(BookAnimations, BuildWritesThePagesTheChaptersLinkTo) {
  T2_NEEDS_PANDOC();
  make_repo();
  const auto r = t2("book build --quiet --root . --out out --docs nodocs");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const std::string graham = slurp(dir_ / "out/animations/graham.html"), del = slurp(dir_ / "out/animations/del.html");
  EXPECT_TRUE(graham.starts_with("<!DOCTYPE html")) << graham.substr(0, 200);
  EXPECT_TRUE(has(graham, "Graham's scan of data/pts.t2 (6 points)"));
  EXPECT_TRUE(has(del, "randomized incremental Delaunay of data/pts.t2 (6 points)"));
  // The command in the text made the page: run by hand from the root, it writes the same bytes.
  const auto by_hand = t2("animate graham data/pts.t2 -o graham.html");
  ASSERT_EQ(by_hand.status, 0) << by_hand.err;
  EXPECT_EQ(slurp(dir_ / "graham.html"), graham);
  const std::string page = slurp(dir_ / "out/01-alpha.html");
  EXPECT_TRUE(has(page, "href=\"animations/graham.html\"")) << page;
  EXPECT_TRUE(has(page, "href=\"animations/del.html\"")) << page;
  EXPECT_EQ(broken_links(dir_ / "out", "01-alpha.html"), std::vector<std::string>{});
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "out/animations"), fs::directory_iterator()), 2);
  EXPECT_EQ(t2("book check --root .").status, 0);
}

TEST_F(BookAnimations, CheckRefusesLinksNoCommandWritesAndCommandsThatCannotRun) {
  T2_NEEDS_PANDOC();
  make_repo();
  write("chapters/01-alpha/chapter-2.md",
      "## More\n\nA [missing page](../../animations/nope.html).\n\n"
      "```sh\nt2 animate quicksort data/pts.t2 -o q.html\nt2 animate graham data/none.t2 -o n.html\n"
      "t2 animate jarvis data/pts.t2 -o graham.html\nt2 animate graham data/pts.t2\n```\n");
  const auto r = t2("book check --root .");
  EXPECT_EQ(r.status, 1) << r.out;
  for (const char* want :
       {"chapter-2.md:3: link target ../../animations/nope.html: no chapter's t2 animate command writes "
        "animations/nope.html",
        "chapter-2.md:6: t2 animate has no algorithm 'quicksort'",
        "chapter-2.md:7: the data file data/none.t2 of t2 animate does not exist",
        "chapter-2.md:8: graham.html is also written by the command at chapters/01-alpha/chapter.md:6, from other "
        "arguments",
        "chapter.md:3: link target ../../animations/del.html: no chapter's t2 animate command writes "
        "animations/del.html",  // its command was in the old chapter-2.md
        "chapter-2.md:9: a t2 animate command of the book is 't2 animate ALGO FILE -o NAME.html'"})
    EXPECT_TRUE(has(r.err, want)) << want << "\n" << r.err;
  EXPECT_FALSE(has(r.err, "graham.html: no chapter")) << r.err;  // written by chapter.md's command
  const auto b = t2("book build --quiet --root . --out out --docs nodocs");
  EXPECT_NE(b.status, 0);
  EXPECT_TRUE(has(b.err, "chapter-2.md:6: t2 animate has no algorithm 'quicksort'")) << b.err;
}

// This repository: every algorithm of t2 animate has a page in the book, each made by one
// command, and chapters 06-15 link pages that their commands write (the links resolve: `t2
// book check`, BookCheck.ThisRepositoryIsInSync).
TEST(BookAnimationsOfThisRepository, EveryAlgorithmIsAnimatedAndLinked) {
  const std::regex command(R"(t2 animate ([a-z0-9-]+) (\S+) -o ([a-z0-9-]+\.html))");
  const std::regex link(R"(\]\(\.\./\.\./animations/([a-z0-9-]+\.html)\))");
  std::set<std::string> algos, pages, linked;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(T2_SOURCE_DIR) / "chapters")) {
    const std::string name = e.path().filename().string();
    if (!std::regex_match(name, std::regex("chapter(-[0-9]+)?\\.md"))) continue;
    const std::string md = slurp(e.path());
    for (std::sregex_iterator m(md.begin(), md.end(), command), end; m != end; ++m)
      algos.insert((*m)[1]), pages.insert((*m)[3]);
    for (std::sregex_iterator m(md.begin(), md.end(), link), end; m != end; ++m) linked.insert((*m)[1]);
  }
  EXPECT_EQ(algos,
            (std::set<std::string>{"chan", "closest-pair-divide", "delaunay", "emst", "fortune", "graham", "intersect",
                                   "intersect-circular", "jarvis", "kdtree", "lec", "merge", "sec", "trapezoid",
                                   "triangulate", "triangulate-t2", "voronoi", "walk"}));
  EXPECT_EQ(linked, pages);
}

}  // namespace
