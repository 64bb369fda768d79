#pragma once
// Reading the student's compiled object, which is untrusted data: a bounds-checked parser of
// ELF64 relocatable objects that lists section names and symbol names, and the checks built on
// it (no LTO sections; no reference to a forbidden library name).

#include <string>
#include <vector>

namespace t2grader {

/// What an object holds.
struct ObjectInfo {
  bool ok = false;                   ///< parsed
  std::string error;                 ///< why not
  std::vector<std::string> sections; ///< section names
  std::vector<std::string> symbols;  ///< demangled names of every symbol, defined or not
};

/// Parses an ELF64 little-endian object from its bytes (never reads outside them).
ObjectInfo read_object(const std::string& bytes);

/// The qualified name of a demangled symbol without return type, template arguments and
/// parameters: "bool t2::operator==<double>(t2::BasicPoint<double> const&, ...)" → "t2::operator==".
std::string bare_name(const std::string& demangled);

/// Why the object must be refused (empty when it is acceptable): LTO sections (whose code the
/// linker plugin would compile), or a symbol whose bare name is, or is a member of, one of
/// `forbidden`.
std::string refuse_object(const ObjectInfo& o, const std::vector<std::string>& forbidden);

}  // namespace t2grader
