// `t2 book check` and `t2 book sync`: the listings of a chapter.md, each a comment
// <!-- listing: PATH#NAME --> and the fenced code block after it, compared with (or rewritten
// from) the source region it is cut from. Line-based on purpose: sync rewrites the markdown
// text and must keep every other byte of it.
#include <algorithm>
#include <regex>
#include <stdexcept>

#include "book_core.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli::book {

std::size_t fence_of(const std::string& line, char& ch) {
  std::size_t i = 0;
  while (i < line.size() && i < 3 && line[i] == ' ') ++i;
  if (i >= line.size() || (line[i] != '`' && line[i] != '~')) return 0;
  ch = line[i];
  std::size_t n = 0;
  while (i + n < line.size() && line[i + n] == ch) ++n;
  return n >= 3 ? n : 0;
}

namespace {

const std::regex& listing_re() {
  static const std::regex re(R"(^\s*<!--\s*listing:\s*([^#\s]+)#(\S+)\s*-->\s*$)");
  return re;
}

std::string language_of(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".cpp" || ext == ".hpp" || ext == ".h" || ext == ".cc") return "cpp";
  if (ext == ".cmake" || fs::path(path).filename() == "CMakeLists.txt") return "cmake";
  if (ext == ".sh") return "sh";
  return "";
}

std::string shorten(const std::string& s) { return s.size() > 100 ? s.substr(0, 97) + "..." : s; }

}  // namespace

SyncResult sync_listings(const fs::path& root, const std::string& rel, const std::string& text) {
  SyncResult r;
  const auto lines = split_lines(text);
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < lines.size()) {
    std::smatch m;
    if (!std::regex_match(lines[i], m, listing_re())) {
      // Skip over fenced code blocks so that a listing comment shown *inside* a code block (as in
      // chapters/README.md) is not taken for a real one.
      char ch;
      const std::size_t n = fence_of(lines[i], ch);
      out.push_back(lines[i++]);
      if (n) {
        while (i < lines.size()) {
          char c2;
          const std::size_t n2 = fence_of(lines[i], c2);
          out.push_back(lines[i++]);
          if (n2 >= n && c2 == ch && t2::trim(out.back()).find_first_not_of(ch) == std::string::npos) break;
        }
      }
      continue;
    }
    ++r.listings;
    const std::string where = rel + ":" + std::to_string(i + 1);
    const std::string src = m[1], name = m[2];
    out.push_back(lines[i++]);
    // The fenced block that follows, if any.
    char ch = '`';
    std::size_t n = i < lines.size() ? fence_of(lines[i], ch) : 0;
    std::string open = "```" + language_of(src);
    std::vector<std::string> old;
    bool had_block = false;
    if (n) {
      had_block = true;
      open = lines[i++];
      while (i < lines.size()) {
        char c2;
        const std::size_t n2 = fence_of(lines[i], c2);
        if (n2 >= n && c2 == ch && t2::trim(lines[i]).find_first_not_of(ch) == std::string::npos) break;
        old.push_back(lines[i++]);
      }
      if (i >= lines.size()) {
        r.problems.push_back({where, "the code block of listing " + src + "#" + name + " is never closed"});
        r.text = text;
        return r;
      }
      ++i;  // closing fence
    }
    std::string region;
    try {
      const fs::path sp = root / src;
      if (!fs::exists(sp)) throw std::runtime_error("listing source " + src + " does not exist");
      region = cut_region(t2::read_file(sp), name, src);
    } catch (const std::exception& e) {
      r.problems.push_back({where, std::string("listing ") + src + "#" + name + ": " + e.what()});
      out.push_back(open);
      for (const auto& l : old) out.push_back(l);
      out.push_back(std::string(std::max<std::size_t>(n, 3), ch));
      if (!had_block) out.pop_back(), out.pop_back();
      continue;
    }
    const auto want = split_lines(region);
    if (!had_block) {
      ++r.changed;
      r.problems.push_back({where, "listing " + src + "#" + name + " is not followed by a fenced code block"});
    } else if (want != old) {
      ++r.changed;
      std::size_t k = 0;
      while (k < want.size() && k < old.size() && want[k] == old[k]) ++k;
      std::string msg = "listing " + src + "#" + name + " differs from its source at line " + std::to_string(k + 1) +
                        " of the listing (file line " + std::to_string(i - old.size() + k) + ")\n";
      msg += "    book:   " + (k < old.size() ? shorten(old[k]) : std::string("(listing ends here)")) + "\n";
      msg += "    source: " + (k < want.size() ? shorten(want[k]) : std::string("(region ends here)"));
      r.problems.push_back({where, msg});
    }
    out.push_back(open);
    for (const auto& l : want) out.push_back(l);
    out.push_back(std::string(std::max<std::size_t>(n, 3), ch));
  }
  r.text = join_lines(out);
  return r;
}

}  // namespace t2cli::book
