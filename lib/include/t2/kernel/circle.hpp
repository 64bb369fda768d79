#pragma once
/// @file circle.hpp
/// @brief Circles of T² (seed 000, §4.1.9): centre, a boundary point and an orientation, with
/// finite, infinite and "beyond infinity" radii.
///
/// A radius of T² need not be a real number: it is infinite when the centre is on Ω, or when
/// the boundary is Ω itself around a proper centre (figure 4.11: the two hemispheres), and
/// "beyond infinity" when centre and boundary point lie on different sides (figures 4.9–4.10:
/// around a front centre, the circle of the back side drawn at the same Cartesian distance).
/// So, as in the thesis, a circle is stored as its centre, one point of its boundary and an
/// orientation: that determines every case exactly. A centre on Ω with a boundary point on
/// Ω determines nothing (a circle centred at infinity is a line perpendicular to the centre's
/// direction, and no such line passes through a second point of Ω unless it is the one
/// perpendicular direction — then it is not unique): that pair is undefined.
///
/// Which side of the circle is "inside" is decided by t2::in_circle (incircle.hpp), not here.

#include <string>
#include <type_traits>
#include <utility>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/segment.hpp"

namespace t2 {

/// The three kinds of radius of a circle of T².
enum class RadiusKind {
  finite,           ///< centre and boundary proper, on the same side
  infinite,         ///< centre on Ω (a line), or boundary on Ω around a proper centre (Ω itself)
  beyond_infinity,  ///< centre and boundary proper, on different sides
};

/// "finite", "infinite" or "beyond_infinity".
inline const char* to_string(RadiusKind k) {
  return k == RadiusKind::finite ? "finite" : k == RadiusKind::infinite ? "infinite" : "beyond_infinity";
}

/// An oriented circle of T²: `center()`, a point `boundary_point()` on it, `orientation()`.
template <class T>
class BasicCircle {
 public:
  using Coordinate = T;  ///< the number type of the coordinates

  /// The circle around c through p. Throws `Undefined` when both c and p are on Ω,
  /// `BadInput` for orientation ZERO. c = p is the degenerate circle of radius zero (allowed,
  /// as in CGAL); c = ¬p its "beyond infinity" counterpart, the single point ¬c.
  BasicCircle(BasicPoint<T> c, BasicPoint<T> p, Sign orientation = POSITIVE)
      : c_(std::move(c)), p_(std::move(p)), o_(orientation) {
    if (c_.w() == 0 && p_.w() == 0)
      throw Undefined("circle(c, p) is undefined when both the centre and the boundary point are at infinity");
    if (o_ == ZERO) throw BadInput("a circle is oriented: POSITIVE or NEGATIVE, not ZERO");
  }
  const BasicPoint<T>& center() const { return c_; }          ///< the centre
  const BasicPoint<T>& boundary_point() const { return p_; }  ///< a point of the circle
  Sign orientation() const { return o_; }                     ///< POSITIVE: counter-clockwise

 private:
  BasicPoint<T> c_, p_;
  Sign o_;
};

/// Circles with `double` coordinates.
using Circle = BasicCircle<double>;
/// Circles with big-integer coordinates.
using ExactCircle = BasicCircle<Integer>;

/// The kind of radius of c (see `RadiusKind`).
template <class T>
RadiusKind radius_kind(const BasicCircle<T>& c) {
  const Side a = side_of(c.center()), b = side_of(c.boundary_point());
  if (a == Side::infinity || b == Side::infinity) return RadiusKind::infinite;
  return a == b ? RadiusKind::finite : RadiusKind::beyond_infinity;
}

/// The same circle with the opposite orientation.
template <class T>
BasicCircle<T> opposite(const BasicCircle<T>& c) {
  return BasicCircle<T>(c.center(), c.boundary_point(), -c.orientation());
}

/// The circle with diameter pq (§4.1.9), through p. For p, q on the same side the centre is
/// their midpoint |w_q|p + |w_p|q (seed §4.3.2). Undefined when p or q is on Ω (no point is
/// equidistant from them), when q = ¬p, and — the seed's rule — for p and q on different
/// sides unless they are equally far from c = pq ∩ Ω (then c would be the centre).
///
/// That last rule is tested exactly, with the seed's notion of relative distance to a point
/// at infinity (§4.3.1: a and b are equally far from c when b is on the perpendicular to c
/// through a): the sign of (P − Q)·c with P, Q the Cartesian positions. But c is itself the
/// direction of P − Q (c_x = |w_p w_q|(x_p/w_p − x_q/w_q), likewise c_y), so the test reads
/// |P − Q|² = 0: it holds only for P = Q, i.e. q = ¬p, where the segment is undefined. The
/// seed's exception is empty: a diameter with ends on different sides never defines a circle.
template <class T>
BasicCircle<T> circle_from_diameter(const BasicPoint<T>& p, const BasicPoint<T>& q, Sign orientation = POSITIVE) {
  if (p.w() == 0 || q.w() == 0)
    throw Undefined("circle_from_diameter(p, q) is undefined when p or q is at infinity");
  if (p == antipode(q)) throw Undefined("circle_from_diameter(p, q) is undefined when q = antipode(p)");
  const T awp = p.w() < 0 ? T(-p.w()) : p.w(), awq = q.w() < 0 ? T(-q.w()) : q.w();
  if ((p.w() > 0) != (q.w() > 0)) {
    auto relative = [](const auto& p, const auto& q, const auto& ap, const auto& aq) {
      const auto cx = aq * p.x + ap * q.x, cy = aq * p.y + ap * q.y;  // c = |w_q| p + |w_p| q
      return (p.x * q.w - q.x * p.w) * cx + (p.y * q.w - q.y * p.w) * cy;  // ∝ (P − Q)·c
    };
    if (sign_of_poly(relative, p, q, awp, awq) != ZERO)
      throw Undefined(
          "circle_from_diameter(p, q) is undefined for p and q on different sides of T2 that are not equally far "
          "from the point where pq crosses the line at infinity");
  }
  const BasicPoint<T> c = detail::exactly<T>(
      [](const ExactPoint& a, const ExactPoint& b) {
        const Integer wa = abs(a.w()), wb = abs(b.w());
        return mix(wb, a, wa, b);
      },
      p, q);
  return BasicCircle<T>(c, p, orientation);
}

/// The circle through p, q and r (§4.1.9), with boundary point p.
///
/// * Three proper points on one side, not collinear: the circumcircle, oriented by Δ(p, q, r).
///   Its centre is computed without division from the lifted rows (w², wx, wy, x² + y²): with
///   M_j the 3×3 minors of that 3×4 matrix, the centre is [−2M₃, M₁, −M₂], negated if needed
///   to lie on the points' side.
/// * Three proper collinear points (on one side or not): the bisectors are parallel and meet
///   at a point of Ω, from which all three are equally far (§4.3.1): the circle of infinite
///   radius that is their line. Its centre is the point of Ω on the positive side of p ∨ q,
///   and the orientation POSITIVE (the line traversed from p to q has that centre on its left).
/// * Points on both sides, not collinear: undefined. The seed's rule ("the distances to c,
///   the meeting point of the bisectors of pq and qr, differ") comes to this: with p, q on one
///   side and r on the other, no point is at a finite distance from q and r alike, so the
///   bisector of q and r is Ω, c is the point of Ω perpendicular to pq, and r is as far from c
///   as p only if r is on the line pq.
/// * A point on Ω (seed: one or two improper points; with three the centre would be either
///   hemisphere), two equal or two antipodal points: undefined.
template <class T>
BasicCircle<T> circle_through(const BasicPoint<T>& p, const BasicPoint<T>& q, const BasicPoint<T>& r) {
  if (p.w() == 0 || q.w() == 0 || r.w() == 0)
    throw Undefined("circle(p, q, r) is undefined when a point is at infinity");
  if (p == q || q == r || r == p) throw Undefined("circle(p, q, r) is undefined when two points are equal");
  if (p == antipode(q) || q == antipode(r) || r == antipode(p))
    throw Undefined("circle(p, q, r) is undefined when two points are antipodal");
  const Sign o = orient(p, q, r);
  if (o == ZERO) {
    const BasicLine<T> l = join(p, q);
    return BasicCircle<T>(BasicPoint<T>(T(0), l.X(), l.Y()), p, POSITIVE);
  }
  const bool same = (p.w() > 0) == (q.w() > 0) && (q.w() > 0) == (r.w() > 0);
  if (!same)
    throw Undefined("circle(p, q, r) is undefined for points on both sides of T2 that are not collinear");
  const BasicPoint<T> c = detail::exactly<T>(
      [](const ExactPoint& a, const ExactPoint& b, const ExactPoint& e) {
        // Lifted rows (w², wx, wy, x² + y²).
        const ExactPoint* v[3] = {&a, &b, &e};
        Integer m[3][4];
        for (int i = 0; i < 3; ++i) {
          const auto& s = *v[i];
          m[i][0] = s.w() * s.w();
          m[i][1] = s.w() * s.x();
          m[i][2] = s.w() * s.y();
          m[i][3] = s.x() * s.x() + s.y() * s.y();
        }
        auto minor = [&](int skip) {
          int c[3], k = 0;
          for (int j = 0; j < 4; ++j)
            if (j != skip) c[k++] = j;
          return Integer(det3(m[0][c[0]], m[0][c[1]], m[0][c[2]], m[1][c[0]], m[1][c[1]], m[1][c[2]], m[2][c[0]],
                              m[2][c[1]], m[2][c[2]]));
        };
        const Integer M1 = minor(1), M2 = minor(2), M3 = minor(3);
        Integer w = -2 * M3, x = M1, y = -M2;
        if (sgn(w) != sgn(a.w())) {
          w = -w;
          x = -x;
          y = -y;
        }
        return ExactPoint(w, x, y);
      },
      p, q, r);
  return BasicCircle<T>(c, p, o);
}

/// "circle(center [..], through [..], +)".
template <class T>
std::string to_string(const BasicCircle<T>& c) {
  return "circle(center " + to_string(c.center()) + ", through " + to_string(c.boundary_point()) + ", " +
         to_symbol(c.orientation()) + ")";
}

}  // namespace t2
