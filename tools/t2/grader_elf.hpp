#pragma once
// Reading the student's compiled object, which is untrusted data: a bounds-checked parser of
// ELF64 relocatable objects that lists section names and the names symbols stand for, and the
// checks built on it (no LTO sections; no reference to a forbidden library name). Symbols are
// read in their mangled form, never demangled: a demangler's output can be exponentially longer
// than its input, and a hostile symbol of a few hundred bytes would hang the grader.

#include <string>
#include <vector>

namespace t2grader {

/// What an object holds.
struct ObjectInfo {
  bool ok = false;                   ///< parsed
  std::string error;                 ///< why not
  std::vector<std::string> sections; ///< section names
  std::vector<std::string> symbols;  ///< the qualified name of every symbol, defined or not:
                                     ///< "t2::operator==" for any t2::operator==<...>(...),
                                     ///< without template arguments, parameters or ABI tags;
                                     ///< a C symbol's own name
};

/// Parses an ELF64 little-endian object from its bytes (never reads outside them). Names are
/// read whole, never cut; an object whose names add up to more than 64 MB is not read.
ObjectInfo read_object(const std::string& bytes);

/// Why the object must be refused (empty when it is acceptable): LTO sections (whose code the
/// linker plugin would compile), or a symbol whose bare name is, or is a member of, one of
/// `forbidden`.
std::string refuse_object(const ObjectInfo& o, const std::vector<std::string>& forbidden);

}  // namespace t2grader
