// `t2 book check` and `t2 book sync` over every chapter of a checkout.
#include <unistd.h>

#include <algorithm>
#include <string>

#include "book_ast.hpp"
#include "book_core.hpp"
#include "process.hpp"
#include "t2/io.hpp"

namespace t2cli::book {

std::vector<std::string> chapter_markdown_files(const fs::path& root) {
  std::vector<std::string> out;
  for (const auto& c : find_chapters(root))
    if (c.has_text) out.push_back("chapters/" + c.folder() + "/chapter.md");
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

// The quoted output of chapter c (its ```text blocks) against what its program prints.
std::vector<Problem> check_program_output(const Chapter& c, const std::string& rel, const Document& doc,
                                          const fs::path& programs, int* outputs) {
  const auto blocks = output_blocks(doc);
  if (!c.has_program || blocks.empty()) return {};
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
  if (outputs) *outputs += static_cast<int>(blocks.size());
  return check_outputs(rel, blocks, r.out, name);
}

}  // namespace

std::vector<Problem> check_book(const fs::path& root, int* listings, const fs::path& programs, int* outputs) {
  std::vector<Problem> ps;
  if (listings) *listings = 0;
  if (outputs) *outputs = 0;
  auto add = [&ps](const std::vector<Problem>& more) { ps.insert(ps.end(), more.begin(), more.end()); };
  for (const auto& c : find_chapters(root)) {
    if (!c.has_text) continue;
    const std::string rel = "chapters/" + c.folder() + "/chapter.md";
    const std::string text = t2::read_file(root / rel);
    const auto r = sync_listings(root, rel, text);
    if (listings) *listings += r.listings;
    add(r.problems);
    if (text.rfind("# ", 0) != 0) ps.push_back({rel + ":1", "the first line must be the chapter title, '# Title'"});
    const Document doc = parse_markdown(text, rel);
    add(check_links(root, rel, doc));
    add(check_listing_widths(rel, doc));
    if (!programs.empty()) add(check_program_output(c, rel, doc, programs, outputs));
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
