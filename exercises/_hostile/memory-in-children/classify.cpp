// Hostile (issue 10): six children of 400 MB each (the per-process limit is 512 MB).
#include <sys/wait.h>
#include <unistd.h>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
// True when all six children held their 400 MB at once: then (only then) it answers where()
// correctly, so that a tree memory limit that does not hold shows up as points scored.
static bool attack() {
  static const bool all = [] {
    pid_t kids[6];
    for (auto& k : kids)
      if ((k = fork()) == 0) {
        char* p = static_cast<char*>(std::malloc(400u << 20));
        if (!p) _exit(1);
        std::memset(p, 1, 400u << 20);
        sleep(1);
        _exit(0);
      }
    int ok = 0;
    for (auto k : kids) {
      int st = 0;
      if (k > 0 && waitpid(k, &st, 0) == k && WIFEXITED(st) && WEXITSTATUS(st) == 0) ++ok;
    }
    return ok == 6;
  }();
  return all;
}
Where where(const t2::Point& p) {
  if (attack()) return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity;  // the limit did not hold
  throw std::logic_error("where() is not implemented yet");
}
bool same_point(const t2::Point&, const t2::Point&) { throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
