#pragma once
// The book system behind `t2 book`, `t2 run` and `t2 list`: chapters, named source regions and
// the listings of chapter.md files that are cut from them (see chapters/README.md).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace t2cli::book {

namespace fs = std::filesystem;

/// One folder chapters/NN-slug/.
struct Chapter {
  std::string number;  ///< "01"
  std::string slug;    ///< "t2-plane"
  fs::path dir;        ///< <root>/chapters/01-t2-plane
  std::string title;   ///< text of the first "# " heading of chapter.md ("" if none)
  bool has_text = false;     ///< chapter.md exists
  bool has_program = false;  ///< main.cpp exists
  std::string folder() const { return number + "-" + slug; }  ///< "01-t2-plane"
};

/// The repository root compiled into the tool (T2_SOURCE_DIR).
fs::path default_root();
/// The build directory of the running t2 binary (<build>/bin/t2 -> <build>), else T2_BINARY_DIR.
fs::path own_build_dir();

/// Every chapters/NN-slug/ folder under root, sorted by number.
std::vector<Chapter> find_chapters(const fs::path& root);
/// The chapter named by "1", "01", "01-t2-plane" or "t2-plane"; nullopt if none.
std::optional<Chapter> find_chapter(const fs::path& root, const std::string& name);

/// Reads a whole file; throws std::runtime_error if it cannot.
std::string read_text(const fs::path& p);
/// Splits text into lines (without the newline characters).
std::vector<std::string> split_lines(const std::string& text);

/// The region `//> name` ... `//< name` of a C++ source text, common indentation removed.
/// Throws std::runtime_error naming the file when a marker is missing or doubled.
std::string cut_region(const std::string& source, const std::string& name, const std::string& file);

/// One problem found by `t2 book check`.
struct Problem {
  std::string where;    ///< "chapters/01-t2-plane/chapter.md:42"
  std::string message;  ///< what is wrong
};

/// A listing block found in a chapter.md.
struct Listing {
  std::size_t comment_line = 0;  ///< 0-based line of the <!-- listing: ... --> comment
  std::string path;              ///< source path relative to the root
  std::string name;              ///< region name
};

/// Result of checking (and optionally rewriting) the listings of one markdown file.
struct SyncResult {
  std::string text;               ///< the file with every listing rewritten from its source
  std::vector<Problem> problems;  ///< drift (only reported when not rewriting), missing markers
  int listings = 0;               ///< listings seen
  int changed = 0;                ///< listings whose text differs from the source
};

/// Checks every listing of the markdown `text` (file `md`, relative `rel`) against its source.
SyncResult sync_listings(const fs::path& root, const std::string& rel, const std::string& text);

/// Local link and image targets of a markdown text (outside code), with their 0-based lines.
struct LinkRef {
  std::size_t line = 0;  ///< 0-based line
  std::string target;    ///< as written, without a "#fragment"
  bool image = false;    ///< `![..](..)`
};
std::vector<LinkRef> local_links(const std::string& text);

/// All chapter.md files of the repository (relative paths, sorted).
std::vector<std::string> chapter_markdown_files(const fs::path& root);

/// A ```text block of a chapter: program output quoted by the text.
struct OutputBlock {
  int line = 0;                    ///< 0-based line of the opening fence
  std::vector<std::string> lines;  ///< its non-blank lines, trailing spaces removed
};
/// The ```text blocks of a markdown text.
std::vector<OutputBlock> output_blocks(const std::string& text);
/// Problems of the output blocks of chapter.md `rel` against `output`, the standard output of
/// its program `program`: the non-blank lines of each block must be printed by the program, in
/// that order (a block may quote an excerpt, not every line). One problem per block at most.
std::vector<Problem> check_outputs(const std::string& rel, const std::string& text, const std::string& output,
                                   const std::string& program);

/// `t2 book check`: every problem of every chapter (empty when clean). With `programs` (a
/// directory holding the built chapter_NN programs), each chapter's program is also run and
/// its quoted output blocks checked against what it prints; `outputs` counts those blocks.
std::vector<Problem> check_book(const fs::path& root, int* listings = nullptr, const fs::path& programs = {},
                                int* outputs = nullptr);
/// `t2 book sync`: rewrites listings; returns the files changed, and problems in `problems`.
std::vector<std::string> sync_book(const fs::path& root, std::vector<Problem>& problems);

/// Runs a program (no shell) and waits; returns its exit status (128+signal if killed), or
/// -1 if it could not be started. With `stdout_to_stderr` the child's output goes to stderr.
int run_program(const std::vector<std::string>& argv, bool stdout_to_stderr = false);
/// Runs a program as `run_program` does, with its standard output collected into `out` and
/// its standard error into `err`.
int run_program_capture(const std::vector<std::string>& argv, std::string& out, std::string& err);

}  // namespace t2cli::book
