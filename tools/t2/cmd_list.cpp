// t2 list: the chapters of the course.
#include <fmt/format.h>

#include <memory>

#include "book_core.hpp"
#include "command.hpp"

namespace t2cli {
namespace cmd_list {

int list(const std::filesystem::path& root) {
  const auto chapters = book::find_chapters(root);
  if (chapters.empty()) {
    fmt::print("no chapters in {}\n", (root / "chapters").string());
    return kOk;
  }
  std::size_t w = 4;
  for (const auto& c : chapters) w = std::max(w, c.slug.size());
  fmt::print("{:<3} {:<{}} {:<8} {}\n", "NN", "slug", w, "program", "title");
  for (const auto& c : chapters)
    fmt::print("{:<3} {:<{}} {:<8} {}\n", c.number, c.slug, w, c.has_program ? "yes" : "no",
               c.has_text ? c.title : "(no chapter.md yet)");
  return kOk;
}

Action setup(Arguments& app) {
  auto root = std::make_shared<std::filesystem::path>(book::default_root());
  app.description(
      "Prints one line per chapter folder chapters/NN-slug/: the number, the slug, whether\n"
      "the chapter has a program (main.cpp, run it with `t2 run NN`) and the title (the first\n"
      "'# ' heading of chapter.md).");
  app.add_option("--root", *root, "the checkout whose chapters are listed (default: the one t2 was\nbuilt from)")
      ->type_name("DIR");
  return [root] { return list(*root); };
}

}  // namespace cmd_list

T2_COMMAND({"list", "list the chapters of the course", cmd_list::setup});

}  // namespace t2cli
