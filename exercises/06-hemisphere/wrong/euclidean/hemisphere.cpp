// Exercise 06, wrong solution: the plane's answer. "Points have a hull unless they are on both
// sides": the front is the hemisphere w > 0, the back w < 0, and any mix has none. It misses
// every other hemisphere (a line through the plane, tilted) and Ω.
#include "hemisphere.hpp"

#include <t2/kernel/error.hpp>

namespace ex06 {

namespace {

bool all(const std::vector<t2::Point>& P, double sign) {
  for (const t2::Point& p : P)
    if (!(p.w() * sign > 0)) return false;
  return true;
}

}  // namespace

t2::ExactPoint hemisphere(const std::vector<t2::Point>& P) {
  if (all(P, 1)) return t2::ExactPoint(1, 0, 0);
  if (all(P, -1)) return t2::ExactPoint(-1, 0, 0);
  throw t2::Undefined("hemisphere: points on both sides");
}

std::vector<long> witness(const std::vector<t2::Point>& P) {
  if (all(P, 1) || all(P, -1)) return {};
  long front = -1, other = -1;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P[i].w() > 0) {
      if (front < 0) front = long(i);
    } else if (other < 0) {
      other = long(i);
    }
  return front < 0 ? std::vector<long>{other, other == 0 ? 1 : 0} : std::vector<long>{front, other};
}

}  // namespace ex06
