#pragma once
// What the tests of scene files share: the ParseError a text gives, checked for its
// `name:line: ` prefix, and the expectation of an error on a given line.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "t2/kernel/scene.hpp"

namespace t2 {

/// The ParseError thrown by parsing `text`, checked to carry `name:line: ` in front.
inline ParseError error_of(std::string_view text, const std::string& name = "f.t2") {
  try {
    (void)parse_scene(text, name);
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), name);
    EXPECT_EQ(std::string(e.what()), name + ":" + std::to_string(e.line()) + ": " + e.message());
    return e;
  }
  ADD_FAILURE() << "no ParseError for: " << text;
  return ParseError(name, 0, "none");
}

/// Expects a ParseError on line `line` whose message contains `part`.
inline void expect_error(std::string_view text, int line, const std::string& part) {
  const ParseError e = error_of(text);
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_NE(e.message().find(part), std::string::npos) << "message: " << e.what() << "\nwanted: " << part;
}

}  // namespace t2
