// Must NOT compile: a predicate's coordinates all have one number type. Mixing a double with an
// int used to convert 0.5 to an integer silently and answer 0 (issue 9). Built by
// check_compile_fail.cmake twice: as is (must fail, with the library's message) and with
// -DT2_CONTROL (same types, must compile), so the failure is known to come from the mixing.
#include "t2/kernel/filter.hpp"

int main() {
  auto minus = [](const auto& a, const auto& b) { return a - b; };
#ifdef T2_CONTROL
  return static_cast<int>(t2::sign_of_poly(minus, 0.5, 0.0));
#else
  return static_cast<int>(t2::sign_of_poly(minus, 0.5, 0));
#endif
}
