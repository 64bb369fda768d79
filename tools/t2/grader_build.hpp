#pragma once
// Building for the grader. Trusted code (the tests, the checker and driver mains, the probe) is
// compiled outside the sandbox from the source tree (GoogleTest's header precompiled once),
// cached by content, and verified by its SHA-256 on every use (a cached file that changed is
// rebuilt); the cache is never visible in the sandbox. The submission is compiled AND linked inside the sandbox, without LTO, and its
// object is read (as untrusted data) between the two steps.

#include <filesystem>
#include <string>
#include <vector>

#include "grader_core.hpp"

namespace t2grader {

/// The trusted parts of one exercise, built (or taken from the cache) for a run.
struct TrustedParts {
  fs::path probe;                  ///< the sandbox probe program
  fs::path checker_public;         ///< public tests + remote.cpp (checker side) + checker main
  fs::path checker_hidden;         ///< hidden tests likewise (empty when not grading)
  std::vector<fs::path> driver_objects;  ///< driver main + remote.cpp (driver side)
  /// The shared libraries the driver runs with, host path → path inside: the loader, the C and
  /// C++ runtimes and fmt, nothing else (GMP is linked in statically), so a driver's dlopen has
  /// nothing else to open; the same under the sanitizers (their runtimes are linked in).
  std::vector<std::pair<fs::path, fs::path>> runtime;
};

/// Builds what `ex` needs outside the sandbox; throws GraderError when trusted code does not build.
TrustedParts build_trusted(const Exercise& ex, bool hidden, const fs::path& work);

/// The sandboxed build of a submission.
struct StudentBuild {
  bool ok = false;          ///< the driver program exists
  bool timed_out = false;   ///< the compile or link hit its wall-clock limit
  bool refused = false;     ///< compiled, but refused (LTO sections, a forbidden name)
  std::string messages;     ///< compiler or linker messages, or why it was refused
  fs::path driver;          ///< the linked driver (host path)
};

/// Compiles `src_dir`/<ex.source> in the sandbox (src_dir holds only the intake's copies),
/// checks the object, and links the driver in the sandbox, within `wall_seconds`.
StudentBuild build_student(const Exercise& ex, const TrustedParts& t, const fs::path& src_dir,
                           const fs::path& out_dir, double wall_seconds);

/// The library archive the driver links against; throws GraderError when it is not built.
fs::path library_archive();

}  // namespace t2grader
