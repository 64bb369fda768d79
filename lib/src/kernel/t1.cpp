#include "t2/kernel/t1.hpp"

#include <fmt/format.h>

namespace t2 {

std::string to_string(const T1& a) { return fmt::format("[{}, {}]", to_string(a.w()), to_string(a.x())); }

std::string to_string(const ExactT1& a) {
  return fmt::format("[{}, {}]", a.w().get_str(), a.x().get_str());
}

}  // namespace t2
