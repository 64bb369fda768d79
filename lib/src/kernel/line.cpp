#include "t2/kernel/line.hpp"

#include <fmt/format.h>

#include <cmath>

namespace t2::detail {

namespace {
template <class N>
std::array<N, 3> cross_of(const std::array<N, 3>& a, const std::array<N, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
}  // namespace

std::array<Integer, 3> cross(const std::array<Integer, 3>& a, const std::array<Integer, 3>& b,
                             const char* rule) {
  auto c = cross_of(a, b);
  if (c[0] == 0 && c[1] == 0 && c[2] == 0) throw Undefined(rule);
  return c;
}

std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const char* rule) {
  auto c = cross_of(a, b);
  const bool finite = std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]);
  if (finite && (c[0] != 0 || c[1] != 0 || c[2] != 0)) return c;
  // Rounding lost the answer (overflow, or a tiny cross product rounded to zero): compute it
  // exactly and scale it back into range. Scaling by a positive factor keeps the same line.
  const ExactPoint ea = to_exact(Point(a[0], a[1], a[2]));
  const ExactPoint eb = to_exact(Point(b[0], b[1], b[2]));
  auto e = cross({ea.w(), ea.x(), ea.y()}, {eb.w(), eb.x(), eb.y()}, rule);
  const Point d = to_double(ExactPoint(e[0], e[1], e[2]));
  return {d.w(), d.x(), d.y()};
}

}  // namespace t2::detail

namespace t2 {

std::string to_string(const Line& l) {
  return fmt::format("<{}, {}, {}>", to_string(l.W()), to_string(l.X()), to_string(l.Y()));
}

std::string to_string(const ExactLine& l) {
  return fmt::format("<{}, {}, {}>", l.W().get_str(), l.X().get_str(), l.Y().get_str());
}

}  // namespace t2
