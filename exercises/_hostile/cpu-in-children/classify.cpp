// Hostile (issue 29, minor): CPU time in children. Three forked workers each use 0.8 s of CPU,
// under the per-process limit (RLIMIT_CPU counts one process), 2.4 s together against a limit
// of 1 s. The limit is the whole tree's (the cgroup's CPU time): the tree is killed, 0 points.
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
namespace {
double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
// True when three workers could use 0.8 s of CPU each: then where() answers correctly, so that a
// CPU limit per process only shows up as points scored.
bool attack() {
  static const bool done = [] {
    pid_t kids[3];
    for (pid_t& k : kids) {
      k = fork();
      if (k == 0) {
        volatile double x = 0;
        while (cpu_now() < 0.8) x = x + 1;
        _exit(0);
      }
      if (k < 0) return false;
    }
    bool all = true;
    for (pid_t k : kids) {
      int status = 0;
      all = waitpid(k, &status, 0) == k && WIFEXITED(status) && WEXITSTATUS(status) == 0 && all;
    }
    return all;
  }();
  return done;
}
}  // namespace
Where where(const t2::Point& p) {
  if (attack()) return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity;  // the tree was not limited
  throw std::logic_error("where() is not implemented yet");
}
bool same_point(const t2::Point&, const t2::Point&) { throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
