#include "t2/kernel/t1.hpp"

#include <fmt/format.h>

#include "t2/kernel/point.hpp"

namespace t2 {

ExactT1 to_exact(const T1& a) {
  const ExactPoint p = to_exact(Point(a.w(), a.x(), 0));  // one common power of two
  return ExactT1(p.w(), p.x());
}

std::string to_string(const T1& a) { return fmt::format("[{}, {}]", to_string(a.w()), to_string(a.x())); }

std::string to_string(const ExactT1& a) {
  return fmt::format("[{}, {}]", a.w().get_str(), a.x().get_str());
}

}  // namespace t2
