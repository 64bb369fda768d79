#pragma once
// The animations of the book. A chapter's "Watch it" paragraph prints the command that makes
// one, a line of a code block or inline code: `t2 animate ALGO FILE -o OUT.html`, FILE relative
// to the repository root. `t2 book build` runs each such command as printed, from the root, and writes the page to
// <book>/animations/OUT.html; the chapter links to it as ../../animations/OUT.html (the folder
// animations/ of the book, as ../../figures/ is its figures/), and `t2 book check` accepts such
// a link only when some chapter's command writes OUT.html. The command in the text is the
// command that made the page.

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "book_core.hpp"

namespace t2cli::book {

/// One `t2 animate` command of a chapter's code block.
struct Animation {
  std::string where;  ///< "chapters/06-convex-hull/chapter.md:605"
  std::string algo;   ///< "graham"
  std::string file;   ///< "data/examples/uniform-16.t2", relative to the root
  std::string out;    ///< "graham.html": the page's name in <book>/animations/
};

/// The `t2 animate` commands of every chapter under `root`, in reading order; a command that
/// is not of the form above, names an unknown ALGO or a FILE that does not exist, or writes a
/// page that another command writes from other arguments, is a problem instead.
std::vector<Animation> find_animations(const fs::path& root, std::vector<Problem>& problems);

/// The names of the pages the commands write ("graham.html", ...).
std::set<std::string> animation_pages(const std::vector<Animation>& animations);

/// Writes the page of every command into `out`/animations/; returns how many. Throws
/// std::runtime_error naming the command when one fails.
int build_animations(const fs::path& root, const std::vector<Animation>& animations, const fs::path& out, bool quiet);

}  // namespace t2cli::book
