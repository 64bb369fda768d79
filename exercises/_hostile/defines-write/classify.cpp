// Hostile (issue 10): defines write(): every write of the process (the harness's too) goes through
// it, and FAIL, E (an exception) and 0 (false) are rewritten as if the test had passed.
#include <sys/syscall.h>
#include <unistd.h>
#include <cstring>
#include <string>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
}  // namespace ex01
extern "C" ssize_t write(int fd, const void* buf, size_t n) {
  std::string s(static_cast<const char*>(buf), n);
  for (size_t p; (p = s.find("FAIL")) != std::string::npos;) s.replace(p, 4, "PASS");
  if (s.rfind("E ", 0) == 0) s = "R 1\n";
  syscall(SYS_write, fd, s.data(), s.size());
  return static_cast<ssize_t>(n);
}
namespace ex01 {
static void attack() {}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
