#pragma once
// Taking a submission in: the one file the exercise needs is copied as a regular file; a
// submission folder holding symlinks, FIFOs, devices or sockets, or too many or too large files,
// is refused with a message that names what is wrong. Nothing is followed, nothing blocks.

#include <filesystem>
#include <string>

#include "grader_core.hpp"

namespace t2grader {

/// Limits of a submission folder.
struct IntakeLimits {
  std::size_t max_entries = 200;             ///< files and folders, at any depth
  std::uintmax_t max_source_bytes = 1 << 20; ///< the exercise's source file
  int max_depth = 4;                         ///< folder nesting
};

/// Copies `submission`/<ex.source> and the exercise's header into `dest` (created, readable by
/// the sandbox); returns why the submission is refused, or "" when it was taken in.
std::string take_in(const Exercise& ex, const fs::path& submission, const fs::path& dest,
                    const IntakeLimits& lim = {});

}  // namespace t2grader
