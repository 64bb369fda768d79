// Hostile (issue 29, break 3): run-time lookup. No header and no symbol names GMP: dlopen and
// dlsym (declared by hand, <dlfcn.h> is not in the compile's view) find it by name at run time,
// which no check of the object sees. The driver runs with its own shared libraries only (GMP is
// linked into it statically), so there is nothing to open: 0 points, like the stub.
#include <stdexcept>
#include "classify.hpp"
extern "C" void* dlopen(const char* file, int mode);
extern "C" void* dlsym(void* handle, const char* name);
namespace ex01 {
// True when a GMP library could be opened and its integer functions found: then where() answers
// correctly, so that a reachable GMP shows up as points scored.
static bool attack() {
  static const bool found = [] {
    for (const char* lib : {"libgmp.so.10", "/usr/lib/x86_64-linux-gnu/libgmp.so.10", "libgmpxx.so.4"})
      if (void* h = dlopen(lib, 2 /* RTLD_NOW */))
        if (dlsym(h, "__gmpz_init") != nullptr) return true;
    return false;
  }();
  return found;
}
Where where(const t2::Point& p) {
  if (attack()) return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity;  // GMP was reachable
  throw std::logic_error("where() is not implemented yet");
}
bool same_point(const t2::Point&, const t2::Point&) { throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
