#pragma once
// What pandoc sees in a chapter: its links, images and code blocks, read from pandoc's JSON AST
// (`pandoc -t json`, the reader of `t2 book build`), so that `t2 book check` judges the same
// document the book renders: reference links, autolinks, links over several lines, fences with
// attributes ({.text}, ~~~) count; inline code, comments and code blocks hold no links.

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "book_core.hpp"

namespace t2cli::book {

/// The pandoc reader of the book: `t2 book build` renders with it, `t2 book check` parses with it.
inline constexpr const char* kPandocReader = "markdown+tex_math_dollars-implicit_header_references";

/// A link or image of a chapter.
struct LinkRef {
  int line = 0;         ///< 1-based line of the source where it is written (best effort: 1 if not found)
  std::string target;   ///< the file it names: without a "#fragment", %XX decoded
  std::string url;      ///< as pandoc read it
  bool image = false;   ///< an image (`![..](..)`), not a link
  bool local = false;   ///< a file of the repository: no scheme (http:, mailto:), not a bare #fragment
};

/// A fenced code block of a chapter.
struct CodeBlock {
  int line = 0;                       ///< 1-based line of its first content line (best effort)
  std::vector<std::string> classes;   ///< {"text"} for ```text and ```{.text}
  std::string code;                   ///< its content, as pandoc read it
};

/// The parts of one markdown document that the checks look at, in document order.
struct Document {
  std::vector<LinkRef> links;
  std::vector<CodeBlock> code_blocks;
};

/// Parses `text` (the markdown file `where`, for messages) with pandoc and collects its links,
/// images and code blocks; lines are found in `text`. Throws std::runtime_error when pandoc
/// cannot be run or fails.
Document parse_markdown(const std::string& text, const std::string& where);

/// A ```text block of a chapter: program output quoted by the text.
struct OutputBlock {
  std::vector<std::string> lines;  ///< its non-blank lines, trailing spaces removed
  std::vector<int> line_of;        ///< the 1-based source line of each of them
};
/// The code blocks of class `text`.
std::vector<OutputBlock> output_blocks(const Document& doc);

/// Problems of the output blocks of chapter.md `rel` against `output`, the standard output of
/// its program `program`: the non-blank lines of each block must be printed by the program, in
/// that order (a block may quote an excerpt, not every line). One problem per block at most.
std::vector<Problem> check_outputs(const std::string& rel, const std::vector<OutputBlock>& blocks,
                                   const std::string& output, const std::string& program);

/// Problems of the links and images of chapter.md `rel` (under `root`): every local target must
/// exist, and a link to animations/NAME.html (the book's animations, book_animations.hpp) must
/// name one of `animations`, the pages the chapters' t2 animate commands write.
std::vector<Problem> check_links(const fs::path& root, const std::string& rel, const Document& doc,
                                 const std::set<std::string>& animations);

}  // namespace t2cli::book
