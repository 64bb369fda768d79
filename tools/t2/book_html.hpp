#pragma once
// `t2 book build`: the HTML book, made with pandoc from the chapters (see book/README.md).

#include <filesystem>
#include <map>
#include <string>

namespace t2cli::book {

/// Where and from what to build the book.
struct BuildOptions {
  std::filesystem::path root;  ///< repository root (chapters/, figures/, book/ ...)
  std::filesystem::path out;   ///< output directory (index.html goes there)
  std::filesystem::path docs;  ///< Doxygen output directory holding t2.tag and html/
  bool quiet = false;          ///< no progress lines
};

/// The API names of a Doxygen tag file ("t2::orient", "t2::BasicPoint::w" ...) mapped to their
/// page and anchor ("filter_8hpp.html#a93cc...") relative to the html/ folder. Empty when the
/// tag file does not exist.
std::map<std::string, std::string> read_tag_file(const std::filesystem::path& tag);

/// Builds the book; throws std::runtime_error when pandoc fails. Returns the number of pages.
int build_book(const BuildOptions& o);

}  // namespace t2cli::book
