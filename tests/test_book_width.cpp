// `t2 book check` keeps listings on the page: no line of a code block of a chapter (quoted
// program output, ```text, excepted) may be over 90 columns, counted in characters.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_testing.hpp"

namespace {

namespace fs = std::filesystem;

class BookCheckWidth : public t2::testing::CliTest {
 protected:
  // A chapter whose listing has one line `width` characters wide (a comment of 'é's: two bytes,
  // one column each), and a ```text block of 120 columns; then `t2 book check` on it.
  t2::testing::Result check_with(std::size_t width) {
    std::string line = "int n = 3;  // ";  // 15 columns
    for (std::size_t c = 15; c < width; ++c) line += "\u00e9";
    fs::create_directories(dir_ / "chapters/01-alpha");
    fs::create_directories(dir_ / "book");
    write("chapters/01-alpha/main.cpp", "int main() {\n  //> wide\n" + line + "\n  //< wide\n}\n");
    write("chapters/01-alpha/chapter.md",
          "# Alpha\n\nText.\n\n<!-- listing: chapters/01-alpha/main.cpp#wide -->\n```cpp\n" + line +
              "\n```\n\nOutput:\n\n```{.text}\n" + std::string(120, 'x') + "\n```\n");
    for (const char* f : {"template.html", "book.lua", "style.css", "parts.txt"})
      fs::copy_file(fs::path(T2_SOURCE_DIR) / "book" / f, dir_ / "book" / f,
                    fs::copy_options::overwrite_existing);
    return t2("book check --root .");
  }
};

TEST_F(BookCheckWidth, NinetyColumnsFitNinetyOneDoNot) {
  if (!t2::testing::have_program("pandoc")) GTEST_SKIP() << "pandoc is not installed: skipped";
  // The oracle of the width: the line built above, its characters counted by hand.
  const auto fits = check_with(90);
  EXPECT_EQ(fits.status, 0) << fits.out << fits.err;
  const auto over = check_with(91);
  const std::string said = over.out + over.err;
  EXPECT_EQ(over.status, 1) << said;
  EXPECT_NE(said.find("chapters/01-alpha/chapter.md:7"), std::string::npos) << said;
  EXPECT_NE(said.find("91 columns wide, over 90"), std::string::npos) << said;
  EXPECT_EQ(said.find("120 columns"), std::string::npos) << "quoted output is exempt: " << said;
}

}  // namespace
