#pragma once
/// @file error.hpp
/// @brief How the library says that a construction is undefined in T².

#include <stdexcept>
#include <string>

namespace t2 {

/// Thrown when an object or construction is undefined in T²: the segment of two antipodes,
/// the join of equal points, the triple [0,0,0], a triangle violating its preconditions...
/// `what()` names the rule of T² that was broken, so that the command line tool can print it
/// and exit with status 3.
class Undefined : public std::domain_error {
 public:
  /// @param rule the rule of T² that the construction broke
  explicit Undefined(const std::string& rule) : std::domain_error(rule) {}
};

/// Thrown when a value cannot even be read as data: a NaN or infinite coordinate.
class BadInput : public std::invalid_argument {
 public:
  /// @param what what is wrong with the data
  explicit BadInput(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace t2
