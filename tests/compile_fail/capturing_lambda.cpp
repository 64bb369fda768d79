// Must NOT compile: a predicate's polynomial is a lambda without captures. sign_of_poly keeps one
// error bound per lambda type (filter.hpp, bound_of). Below, a captured flag chooses between
// a² − b² and a² − c²: were it allowed, the bound of the first choice (M_a²·M_b²) would serve the
// other too, so a tiny b and a huge c would certify wrong signs (issue 23). Built by
// check_compile_fail.cmake twice: as is (must fail, with the library's message) and with
// -DT2_CONTROL (the same body, the flag a constant and the lambda without captures, must
// compile), so the failure is known to come from the capture.
#include "t2/kernel/filter.hpp"

int main(int argc, char**) {
#ifdef T2_CONTROL
  constexpr bool first = true;
  auto poly = [](const auto& a, const auto& b, const auto& c) {
#else
  const bool first = argc > 1;
  auto poly = [&](const auto& a, const auto& b, const auto& c) {
#endif
    const auto& s = first ? b : c;
    return a * a - s * s;
  };
  return static_cast<int>(t2::sign_of_poly(poly, 1.0, 0x1p-40, 0x1p40)) + argc;
}
