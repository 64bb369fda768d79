// Exercise 07b, wrong solution: the plane's diameter. The largest distance between the drawn
// points (x/w, y/w), compared exactly, over all proper points; points of Ω are skipped (they
// have no drawing). Right on one side, wrong as soon as there are front and back points (their
// distance is beyond infinity) or points of Ω (+∞).
#include "diameter.hpp"

#include <t2/kernel/number.hpp>

namespace ex07b {

std::vector<long> diameter(const std::vector<t2::Point>& P) {
  std::vector<long> best = {0, 0};
  t2::Rational d = -1;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = i + 1; j < P.size(); ++j) {
      if (P[i].w() == 0 || P[j].w() == 0) continue;
      const t2::Rational dx = t2::to_rational(P[i].x()) / t2::to_rational(P[i].w()) -
                              t2::to_rational(P[j].x()) / t2::to_rational(P[j].w());
      const t2::Rational dy = t2::to_rational(P[i].y()) / t2::to_rational(P[i].w()) -
                              t2::to_rational(P[j].y()) / t2::to_rational(P[j].w());
      if (dx * dx + dy * dy > d) d = dx * dx + dy * dy, best = {long(i), long(j)};
    }
  return best;
}

}  // namespace ex07b
