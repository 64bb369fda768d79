// Exercise 03, reference solution: m = |w_q| p + |w_p| q (seed 000 §4.3.2, after [dRS94]),
// plus the two cases where that formula collapses to [0,0,0] although the answer exists or
// must be refused explicitly: equal points on Ω (the seed's formula misses them) and antipodes.
#include "mid.hpp"

namespace ex03 {

t2::ExactPoint midpoint(const t2::ExactPoint& p, const t2::ExactPoint& q) {
  if (p == q) return p;
  if (p == t2::antipode(q)) throw t2::Undefined("midpoint(p, q) is undefined when q = antipode(p)");
  if (p.w() == 0 && q.w() == 0)
    throw t2::Undefined("midpoint(p, q) is undefined for two distinct points of the line at infinity");
  const t2::Integer a = abs(q.w()), b = abs(p.w());
  return t2::ExactPoint(a * p.w() + b * q.w(), a * p.x() + b * q.x(), a * p.y() + b * q.y());
}

}  // namespace ex03
