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
///
/// Its text is chapter.md, continued (so that no file outgrows 500 lines) in chapter-2.md,
/// chapter-3.md, ...: the parts are read in that order as one document, and the book makes one
/// page of them. Its exercise sheets are every folder exercises/NN-* and exercises/NNx-* (one
/// letter after the number: 01b, 01c, ...) that holds a README.md.
struct Chapter {
  std::string number;  ///< "01"
  std::string slug;    ///< "t2-plane"
  fs::path dir;        ///< <root>/chapters/01-t2-plane
  std::string title;   ///< text of the first "# " heading of chapter.md ("" if none)
  bool has_text = false;     ///< chapter.md exists
  bool has_program = false;  ///< main.cpp exists
  /// The files of its text in reading order ("chapter.md", "chapter-2.md", ...): chapter.md
  /// first, then every chapter-K.md by K (gaps in K are reported by `t2 book check`); empty
  /// when there is no chapter.md.
  std::vector<std::string> parts;
  /// Its exercise folders under exercises/ ("01-t2-plane", "01b-t1-order", ...), sorted.
  std::vector<std::string> exercises;
  std::string folder() const { return number + "-" + slug; }  ///< "01-t2-plane"
};

/// The file name of part `k` (1-based) of a chapter's text: "chapter.md", "chapter-2.md", ...
std::string part_file(std::size_t k);

/// The repository root compiled into the tool (T2_SOURCE_DIR).
fs::path default_root();
/// The build directory of the running t2 binary (<build>/bin/t2 -> <build>), else T2_BINARY_DIR.
fs::path own_build_dir();

/// Every chapters/NN-slug/ folder under root, sorted by number.
std::vector<Chapter> find_chapters(const fs::path& root);
/// The chapter named by "1", "01", "01-t2-plane" or "t2-plane"; nullopt if none.
std::optional<Chapter> find_chapter(const fs::path& root, const std::string& name);

/// Splits text into lines (without the newline characters).
std::vector<std::string> split_lines(const std::string& text);
/// The lines, each followed by a newline.
std::string join_lines(const std::vector<std::string>& lines);

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

/// The length of the code fence that opens or closes at `line` (```` ``` ```` or `~~~`, at most
/// three spaces in), its character in `ch`; 0 when the line is no fence.
std::size_t fence_of(const std::string& line, char& ch);

/// Every part of the text of every chapter (relative paths: chapters/NN-slug/chapter.md,
/// .../chapter-2.md, ...), chapter by chapter, each chapter's parts in reading order.
std::vector<std::string> chapter_markdown_files(const fs::path& root);

/// `t2 book check`: every problem of every chapter (empty when clean). With `programs` (a
/// directory holding the built chapter_NN programs), each chapter's program is also run and
/// its quoted output blocks checked against what it prints; `outputs` counts those blocks.
std::vector<Problem> check_book(const fs::path& root, int* listings = nullptr, const fs::path& programs = {},
                                int* outputs = nullptr);
/// `t2 book sync`: rewrites listings; returns the files changed, and problems in `problems`.
std::vector<std::string> sync_book(const fs::path& root, std::vector<Problem>& problems);

/// Runs a program (no shell, through t2proc) with this process's standard output and error and
/// waits; returns its exit status (128+signal if killed), or -1 if it could not be started.
/// Without `stdout_to_stderr` it also reads this process's standard input (`t2 run 05 < in`);
/// with it, its standard output is collected and then written to stderr, and its input is empty.
int run_program(const std::vector<std::string>& argv, bool stdout_to_stderr = false);

}  // namespace t2cli::book
