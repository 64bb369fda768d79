// Wrong on purpose: the right cases and the right formula, evaluated in doubles: the
// determinants of degree 6 round, so the vertex is only near the equidistant point.
#include "vertex.hpp"

#include <t2/kernel/error.hpp>
#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>

namespace ex11 {

namespace {

double det3(double a, double b, double c, double d, double e, double f, double g, double h, double i) {
  return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}

int side(const t2::Point& p) { return p.w() > 0 ? 1 : p.w() < 0 ? -1 : 0; }

}  // namespace

t2::ExactPoint voronoi_vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  const t2::Point* v[3] = {&a, &b, &c};
  const bool one_side = side(a) != 0 && side(a) == side(b) && side(b) == side(c);
  if (one_side && t2::orient(a, b, c) != t2::ZERO) {
    double P[3], X[3], Y[3], W[3];
    for (int i = 0; i < 3; ++i) {
      P[i] = v[i]->x() * v[i]->x() + v[i]->y() * v[i]->y();
      X[i] = v[i]->w() * v[i]->x();
      Y[i] = v[i]->w() * v[i]->y();
      W[i] = v[i]->w() * v[i]->w();
    }
    const double A = det3(X[0], Y[0], W[0], X[1], Y[1], W[1], X[2], Y[2], W[2]);
    const double B = -det3(P[0], Y[0], W[0], P[1], Y[1], W[1], P[2], Y[2], W[2]);
    const double C = det3(P[0], X[0], W[0], P[1], X[1], W[1], P[2], X[2], W[2]);
    return t2::to_exact(t2::Point(2 * A, -B, -C));
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (side(*v[i]) == 0 || side(*v[i]) != side(*v[j])) continue;
    if (one_side) {
      const t2::Sign s = t2::compare_xy(*v[i], *v[k]);
      if (s != t2::ZERO && s == t2::compare_xy(*v[k], *v[j])) continue;
    }
    const t2::Point &p = *v[i], &q = *v[j];
    return t2::to_exact(t2::Point(0, p.y() * q.w() - p.w() * q.y(), p.w() * q.x() - p.x() * q.w()));
  }
  throw t2::Undefined("voronoi_vertex(): no two consecutive sites are proper on one side");
}

}  // namespace ex11
