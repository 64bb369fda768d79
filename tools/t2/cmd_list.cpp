// t2 list: the chapters of the course.
#include <fmt/format.h>

#include "book_core.hpp"
#include "command.hpp"

namespace t2cli {
namespace {

int run(Args args) {
  std::filesystem::path root = book::default_root();
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--root" && i + 1 < args.size()) {
      root = args[++i];
    } else {
      throw UsageError("unexpected argument '" + args[i] + "'");
    }
  }
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

}  // namespace

T2_COMMAND({"list", "list the chapters of the course",
            "Usage: t2 list [--root DIR]\n"
            "\n"
            "Prints one line per chapter folder chapters/NN-slug/: the number, the slug, whether\n"
            "the chapter has a program (main.cpp, run it with `t2 run NN`) and the title (the first\n"
            "'# ' heading of chapter.md).\n",
            run});

}  // namespace t2cli
