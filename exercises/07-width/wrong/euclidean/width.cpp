// Exercise 07, wrong solution: the plane's width. Every line through two drawn points (x/w, y/w)
// with all the drawn points on one side is a candidate, compared exactly; points of Ω are
// skipped (they have no drawing), and front and back points are drawn together. Right on one
// side with no point of Ω.
#include "width.hpp"

#include <t2/kernel/number.hpp>

namespace ex07 {

std::vector<long> width(const std::vector<t2::Point>& P) {
  std::vector<long> idx;
  std::vector<t2::Rational> X, Y;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P[i].w() != 0) {
      idx.push_back(long(i));
      X.push_back(t2::to_rational(P[i].x()) / t2::to_rational(P[i].w()));
      Y.push_back(t2::to_rational(P[i].y()) / t2::to_rational(P[i].w()));
    }
  std::vector<long> best;
  t2::Rational w = -1;
  for (std::size_t i = 0; i < idx.size(); ++i)
    for (std::size_t j = 0; j < idx.size(); ++j) {
      const t2::Rational ux = X[j] - X[i], uy = Y[j] - Y[i], n2 = ux * ux + uy * uy;
      if (n2 == 0) continue;
      int side = 0;
      bool holds = true;
      t2::Rational far = 0;
      long k = idx[i];
      for (std::size_t p = 0; p < idx.size() && holds; ++p) {
        const t2::Rational c = ux * (Y[p] - Y[i]) - uy * (X[p] - X[i]);
        const int s = sgn(c);
        holds = !(s != 0 && side != 0 && s != side);
        if (s != 0) side = s;
        if (c * c / n2 > far) far = c * c / n2, k = idx[p];
      }
      if (holds && (w < 0 || far < w)) w = far, best = {idx[i], idx[j], k};
    }
  return best;
}

}  // namespace ex07
