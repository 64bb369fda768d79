// The animations of the book (book_animations.hpp).
#include "book_animations.hpp"

#include <fmt/format.h>

#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "algorithms/registry.hpp"
#include "animate/run.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/scene.hpp"

namespace t2cli::book {

namespace {

// An algorithm of t2 animate: registered with a recorder (algorithms/registry.hpp).
bool known_algorithm(const std::string& algo) {
  const algorithms::Algorithm* a = algorithms::find(algo);
  return a != nullptr && a->animates();
}

// One command found at `where`: an animation, or a problem.
void add(const fs::path& root, const std::string& where, const std::string& text, std::vector<Animation>& found,
         std::vector<Problem>& ps) {
  static const std::regex command(R"(^t2 animate (\S+) (\S+) -o ([a-z0-9][a-z0-9-]*\.html)\s*(#.*)?$)");
  std::smatch m;
  if (!std::regex_match(text, m, command)) {
    ps.push_back({where, "a t2 animate command of the book is 't2 animate ALGO FILE -o NAME.html' (FILE relative "
                         "to the repository root, NAME of a-z, 0-9 and -)"});
    return;
  }
  Animation a{where, m[1], m[2], m[3]};
  std::error_code ec;
  if (!known_algorithm(a.algo))
    ps.push_back({where, "t2 animate has no algorithm '" + a.algo + "'"});
  else if (!fs::is_regular_file(root / a.file, ec))
    ps.push_back({where, "the data file " + a.file + " of t2 animate does not exist"});
  else
    found.push_back(std::move(a));
}

// The commands of one markdown file `rel`: the lines of its code blocks that start with
// "t2 animate", and its inline code `t2 animate ...` in prose.
void scan(const fs::path& root, const std::string& rel, std::vector<Animation>& found, std::vector<Problem>& ps) {
  const auto lines = split_lines(t2::read_file(root / rel));
  std::size_t open = 0;  // the length of the open fence, 0 outside a code block
  char open_ch = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    char ch = 0;
    const std::size_t n = fence_of(lines[i], ch);
    if (open == 0 && n > 0) {
      open = n, open_ch = ch;
      continue;
    }
    if (open > 0 && n >= open && ch == open_ch && lines[i].find_first_not_of(" `~") == std::string::npos) {
      open = 0;
      continue;
    }
    std::vector<std::string> commands;  // a line of a code block, or the inline code of prose
    if (open > 0 && lines[i].rfind("t2 animate", 0) == 0) commands.push_back(lines[i]);
    for (std::size_t at = 0; open == 0 && (at = lines[i].find("`t2 animate ", at)) != std::string::npos;) {
      const std::size_t end = lines[i].find('`', at + 1);
      commands.push_back(lines[i].substr(at + 1, end == std::string::npos ? end : end - at - 1));
      at = end == std::string::npos ? lines[i].size() : end + 1;
    }
    for (const auto& c : commands) add(root, rel + ":" + std::to_string(i + 1), c, found, ps);
  }
}

}  // namespace

std::vector<Animation> find_animations(const fs::path& root, std::vector<Problem>& problems) {
  std::vector<Animation> found;
  for (const auto& rel : chapter_markdown_files(root)) scan(root, rel, found, problems);
  std::map<std::string, const Animation*> first;  // page -> its first command
  std::vector<Animation> out;
  for (const auto& a : found) {
    const auto [it, fresh] = first.emplace(a.out, &a);
    if (fresh) {
      out.push_back(a);
    } else if (it->second->algo != a.algo || it->second->file != a.file) {
      problems.push_back({a.where, fmt::format("{} is also written by the command at {}, from other arguments", a.out,
                                               it->second->where)});
    }
  }
  return out;
}

std::set<std::string> animation_pages(const std::vector<Animation>& animations) {
  std::set<std::string> pages;
  for (const auto& a : animations) pages.insert(a.out);
  return pages;
}

int build_animations(const fs::path& root, const std::vector<Animation>& animations, const fs::path& out, bool quiet) {
  fs::create_directories(out / "animations");
  for (const auto& a : animations) {
    try {
      // The scene is named as the command names it, so the page's title is the same.
      const t2::Scene scene = t2::parse_scene(t2::read_file(root / a.file), a.file);
      const std::string done = animate::write_animation(a.algo, scene, out / "animations" / a.out);
      if (!quiet) fmt::print("  {}\n", done);
    } catch (const std::exception& e) {
      throw std::runtime_error(fmt::format("{}: t2 animate {} {} -o {}: {}", a.where, a.algo, a.file, a.out, e.what()));
    }
  }
  return static_cast<int>(animations.size());
}

}  // namespace t2cli::book
