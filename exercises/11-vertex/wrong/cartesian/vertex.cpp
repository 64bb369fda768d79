// Wrong on purpose: Euclidean only. The vertex is "the circumcentre": the drawn positions'
// circumcentre, exactly, always as a front point, whatever the orientation and the side of the
// sites; with a site on Ω or sites on two sides there is no circumcentre, so it throws.
#include "vertex.hpp"

#include <t2/kernel/error.hpp>

namespace ex11 {

t2::ExactPoint voronoi_vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  using t2::Rational;
  if (a.w() == 0 || b.w() == 0 || c.w() == 0 || (a.w() > 0) != (b.w() > 0) || (a.w() > 0) != (c.w() > 0))
    throw t2::Undefined("voronoi_vertex(): no circumcentre");
  auto X = [](const t2::Point& p) -> t2::Rational { return t2::to_rational(p.x()) / t2::to_rational(p.w()); };
  auto Y = [](const t2::Point& p) -> t2::Rational { return t2::to_rational(p.y()) / t2::to_rational(p.w()); };
  const Rational a1 = 2 * (X(b) - X(a)), b1 = 2 * (Y(b) - Y(a)), c1 = X(b) * X(b) + Y(b) * Y(b) - X(a) * X(a) - Y(a) * Y(a);
  const Rational a2 = 2 * (X(c) - X(a)), b2 = 2 * (Y(c) - Y(a)), c2 = X(c) * X(c) + Y(c) * Y(c) - X(a) * X(a) - Y(a) * Y(a);
  const Rational det = a1 * b2 - a2 * b1;
  if (det == 0) throw t2::Undefined("voronoi_vertex(): collinear sites have no circumcentre");
  const Rational ux = (c1 * b2 - c2 * b1) / det, uy = (a1 * c2 - a2 * c1) / det;
  const t2::Integer d = ux.get_den() * uy.get_den();
  return t2::ExactPoint(d, t2::Integer(ux * d), t2::Integer(uy * d));
}

}  // namespace ex11
