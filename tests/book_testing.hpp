#pragma once
// What the tests of the book system share (test_book.cpp: check, sync, list, run;
// test_book_html.cpp: the HTML book and the browser): running the tool, temporary folders and
// a tiny repository of two chapters.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_testing.hpp"

namespace t2::book_testing {

namespace fs = std::filesystem;

using t2::testing::have_program;
using t2::testing::slurp;

struct Result {
  int status = -1;
  std::string output;  // stdout and stderr
};

inline Result run(const std::string& cmd) {
  const auto r = t2::testing::shell(cmd);
  return {r.status, r.out};
}

inline std::string tool() { return T2_TOOL; }

inline void spit(const fs::path& p, const std::string& s) {
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
inline void make_repo(const fs::path& root) {
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

}  // namespace t2::book_testing
