#pragma once
// What a submission's compile sees (issue 29): the allow-list. A deny-list of names cannot say
// "solve it yourself" while the code that solves it is in the sandbox (a macro renames a
// header-only algorithm before its #include; Boost and CGAL answer as well as t2 does), so the
// sandboxed compile is shown only
//   - the exercise's API header (copied next to the submission),
//   - the library headers the manifest's `allowed:` line names, and the library headers those
//     include (closed under #include; nothing else of lib/include),
//   - of the host's /usr/include, only what the C++ standard library and those headers include
//     (GMP's headers when an allowed header includes them; never Boost, CGAL or qhull).
// What a folder does not hold, no macro, template or #include can reach.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "grader_core.hpp"

namespace t2grader {

/// The header, at the top of the view, that includes the allowed headers in the manifest's order
/// (absent when the manifest allows none): the compile's first -include, precompiled beside it.
inline constexpr const char* kAllowedHeader = "t2-allowed.hpp";

/// The headers a submission's compile sees.
struct IncludeView {
  fs::path tree;                      ///< host folder bound at /t2/include: the allowed library headers
  std::vector<std::string> headers;   ///< the library headers in it ("t2/kernel/point.hpp"), sorted
  std::vector<fs::path> masked;       ///< folders hidden in the sandbox (an empty, read-only tmpfs over each)
  std::vector<fs::path> system;       ///< host files and folders bound back, read-only, at the same path
};

/// The library's headers in the source tree (lib/include).
fs::path library_include_dir();

/// The library headers `allowed` and every library header they include, transitively, as paths
/// relative to `include_root` (sorted); throws GraderError naming a header that does not exist.
std::vector<std::string> header_closure(const fs::path& include_root, const std::vector<std::string>& allowed);

/// Builds the view of `ex` under `work` (the library headers copied, kAllowedHeader written, the
/// system headers found by the compiler on the standard library and the allowed headers, cached
/// per allow-list and `toolchain` key); throws GraderError.
IncludeView include_view(const Exercise& ex, const fs::path& work, std::uint64_t toolchain);

}  // namespace t2grader
