// `t2 book check` and `t2 book sync` over every chapter of a checkout.
#include <unistd.h>

#include <algorithm>
#include <string>

#include "book_animations.hpp"
#include "book_ast.hpp"
#include "book_core.hpp"
#include "process.hpp"
#include "t2/kernel/io.hpp"

namespace t2cli::book {

std::vector<std::string> chapter_markdown_files(const fs::path& root) {
  std::vector<std::string> out;
  for (const auto& c : find_chapters(root))
    for (const auto& part : c.parts) out.push_back("chapters/" + c.folder() + "/" + part);
  return out;
}

namespace {

// Listings fit the page of the HTML book: no line of a code block is wider than this (quoted
// program output, ```text, is the program's and is exempt). Columns are characters (UTF-8 code
// points), as the monospace font of the book lays them out.
constexpr std::size_t kMaxListingColumns = 90;

std::size_t columns(const std::string& line) {
  std::size_t n = 0;
  for (const unsigned char c : line) n += (c & 0xC0) != 0x80;
  return n;
}

// The code blocks of doc as pandoc reads them (indented, fenced, with attributes), line by line.
std::vector<Problem> check_listing_widths(const std::string& rel, const Document& doc) {
  std::vector<Problem> ps;
  for (const auto& b : doc.code_blocks) {
    if (std::find(b.classes.begin(), b.classes.end(), "text") != b.classes.end()) continue;
    std::size_t start = 0;
    for (int k = 0; start <= b.code.size(); ++k) {
      const std::size_t end = std::min(b.code.find('\n', start), b.code.size());
      const std::size_t w = columns(b.code.substr(start, end - start));
      if (w > kMaxListingColumns)
        ps.push_back({rel + ":" + std::to_string(b.line + k),
                      "a line of a code block is " + std::to_string(w) + " columns wide, over " +
                          std::to_string(kMaxListingColumns) +
                          ": it scrolls sideways in the HTML book (wrap it in the source, then `t2 book sync`)"});
      start = end + 1;
    }
  }
  return ps;
}

// One part of a chapter's text, read and parsed.
struct Part {
  std::string rel;  // chapters/NN-slug/chapter-K.md
  Document doc;
};

// The quoted output of chapter c (the ```text blocks of all its parts) against what its program
// prints; the program runs once.
std::vector<Problem> check_program_output(const Chapter& c, const std::vector<Part>& parts,
                                          const fs::path& programs, int* outputs) {
  std::size_t quoted = 0;
  for (const auto& p : parts) quoted += output_blocks(p.doc).size();
  if (!c.has_program || quoted == 0) return {};
  const std::string rel = parts.front().rel;
  const std::string name = "chapter_" + c.number;
  const fs::path exe = programs / name;
  if (!fs::exists(exe))
    return {{rel + ":1", name + " is not built in " + programs.string() + ": its output blocks are unchecked"}};
  // Figures go to a scratch directory: checking the book must not touch the repository.
  const fs::path scratch = fs::temp_directory_path() / ("t2-book-check-" + std::to_string(::getpid()) + "-" + c.number);
  t2proc::Spec s;
  s.argv = {exe.string(), "--figures", scratch.string()};
  const t2proc::Result r = t2proc::run(s);
  std::error_code ec;
  fs::remove_all(scratch, ec);
  if (!r.ok()) {
    const std::string status = !r.started ? "could not start: " + r.error
                               : r.signal ? "signal " + std::to_string(r.signal)
                                          : "exit status " + std::to_string(r.exit_code);
    return {{rel + ":1", name + " failed (" + status + "): its output blocks are unchecked; it said: " + r.err}};
  }
  if (outputs) *outputs += static_cast<int>(quoted);
  std::vector<Problem> ps;
  for (const auto& p : parts) {
    const auto more = check_outputs(p.rel, output_blocks(p.doc), r.out, name);
    ps.insert(ps.end(), more.begin(), more.end());
  }
  return ps;
}

// The parts of a chapter's text are chapter.md, chapter-2.md, chapter-3.md ... with no gap, and
// only the first has the chapter's title (the book reads them as one document).
std::vector<Problem> check_parts(const Chapter& c, const std::vector<Part>& parts,
                                 const std::vector<std::string>& texts) {
  std::vector<Problem> ps;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::string want = part_file(k + 1);
    if (c.parts[k] != want) {
      ps.push_back({parts[k].rel + ":1", "the parts of a chapter are chapter.md, chapter-2.md, chapter-3.md, ... "
                                         "with no gap: " + want + " is missing (the part after " +
                                         c.parts[k - 1] + ")"});
      break;
    }
    const bool titled = texts[k].rfind("# ", 0) == 0;
    if (k == 0 && !titled) ps.push_back({parts[k].rel + ":1", "the first line must be the chapter title, '# Title'"});
    if (k > 0 && titled)
      ps.push_back({parts[k].rel + ":1", "only chapter.md has the chapter's '# Title'; its later parts start "
                                         "with a section ('## ...'), since the book reads them as one page"});
  }
  return ps;
}

}  // namespace

std::vector<Problem> check_book(const fs::path& root, int* listings, const fs::path& programs, int* outputs) {
  std::vector<Problem> ps;
  if (listings) *listings = 0;
  if (outputs) *outputs = 0;
  auto add = [&ps](const std::vector<Problem>& more) { ps.insert(ps.end(), more.begin(), more.end()); };
  const auto animations = animation_pages(find_animations(root, ps));
  for (const auto& c : find_chapters(root)) {
    if (!c.has_text) continue;
    std::vector<Part> parts;
    std::vector<std::string> texts;
    for (const auto& file : c.parts) {
      const std::string rel = "chapters/" + c.folder() + "/" + file;
      texts.push_back(t2::read_file(root / rel));
      const auto r = sync_listings(root, rel, texts.back());
      if (listings) *listings += r.listings;
      add(r.problems);
      parts.push_back({rel, parse_markdown(texts.back(), rel)});
      add(check_links(root, rel, parts.back().doc, animations));
      add(check_listing_widths(rel, parts.back().doc));
    }
    add(check_parts(c, parts, texts));
    if (!programs.empty()) add(check_program_output(c, parts, programs, outputs));
  }
  return ps;
}

std::vector<std::string> sync_book(const fs::path& root, std::vector<Problem>& problems) {
  std::vector<std::string> changed;
  for (const auto& rel : chapter_markdown_files(root)) {
    const std::string text = t2::read_file(root / rel);
    auto r = sync_listings(root, rel, text);
    for (const auto& p : r.problems)
      if (p.message.find("differs from its source") == std::string::npos &&
          p.message.find("not followed by a fenced") == std::string::npos)
        problems.push_back(p);
    if (r.text != text) {
      t2::write_file_atomically(root / rel, r.text);
      changed.push_back(rel);
    }
  }
  return changed;
}

}  // namespace t2cli::book
