#pragma once
/// @file segment.hpp
/// @brief Segments of T² (seed 000, §3.4 and §4.1.3): the shorter arc between two
/// non-antipodal points, point-on-segment, the planar-model cases, intersection.
///
/// In the spherical model the segment from p to q is the shorter great-circle arc from p to
/// q; algebraically it is the set of points αp + βq with α, β ≥ 0 (not both zero). That cone
/// is what every function here tests, with exact signs of polynomials — never with
/// coordinates divided by w.
///
/// **Degenerate segments.** `segment(p, p)` is allowed and is the single point p, as in CGAL
/// (where `Segment_2(p, p)` is a valid degenerate segment): the cone αp + βp is just p, so
/// every formula below stays meaningful, and algorithms (hulls, triangulations) meet such
/// segments naturally. Only `segment(p, ¬p)` is undefined: the cone of p and ¬p is a whole
/// line through p, and infinitely many great semicircles join p to ¬p (§3.4).

#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/filter.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"

namespace t2 {

namespace detail {

/// Runs an exact construction `f` on `Integer` points: for `double` points, converts them
/// exactly (`to_exact`), constructs with big integers and rounds once at the end
/// (`to_double`); for `Integer` points calls `f` directly. Either way no division happens and
/// a `double` result is the correctly scaled rounding of the exact point.
template <class T, class F, class... P>
BasicPoint<T> exactly(F&& f, const P&... points) {
  if constexpr (std::is_same_v<T, double>) {
    return to_double(f(to_exact(points)...));
  } else {
    return f(points...);
  }
}

/// The rule every segment obeys, as the text of `Undefined`.
inline constexpr const char* kAntipodalSegment = "segment(p, q) is undefined when q = antipode(p)";

}  // namespace detail

/// The oriented segment from `source()` to `target()`: the shorter arc of T² between two
/// points that are not antipodal. Equal endpoints give the degenerate one-point segment.
template <class T>
class BasicSegment {
 public:
  using Coordinate = T;  ///< the number type of the coordinates

  /// The segment from p to q. Throws `Undefined` when q = ¬p.
  BasicSegment(BasicPoint<T> p, BasicPoint<T> q) : p_(std::move(p)), q_(std::move(q)) {
    if (p_ == antipode(q_)) throw Undefined(detail::kAntipodalSegment);
  }
  const BasicPoint<T>& source() const { return p_; }  ///< the first endpoint
  const BasicPoint<T>& target() const { return q_; }  ///< the second endpoint
  /// Endpoint i: 0 is the source, 1 the target (i taken modulo 2, as in CGAL).
  const BasicPoint<T>& vertex(int i) const { return (i % 2 == 0) ? p_ : q_; }
  /// True for the one-point segment (source = target).
  bool is_degenerate() const { return p_ == q_; }

 private:
  BasicPoint<T> p_, q_;
};

/// Segments with `double` coordinates.
using Segment = BasicSegment<double>;
/// Segments with big-integer coordinates.
using ExactSegment = BasicSegment<Integer>;

/// The same segment traversed the other way.
template <class T>
BasicSegment<T> opposite(const BasicSegment<T>& s) {
  return BasicSegment<T>(s.target(), s.source());
}

/// The antipodal segment ¬s, from ¬source to ¬target (the antipodal image of s on the sphere).
template <class T>
BasicSegment<T> antipode(const BasicSegment<T>& s) {
  return BasicSegment<T>(antipode(s.source()), antipode(s.target()));
}

/// Equality of oriented segments: same source and same target.
template <class T>
bool operator==(const BasicSegment<T>& s, const BasicSegment<T>& t) {
  return s.source() == t.source() && s.target() == t.target();
}

namespace detail {
/// The exact test behind `on_segment` (see there).
//> on-segment
template <class T>
bool on_segment_impl(const BasicPoint<T>& p, const BasicPoint<T>& q,
                     const BasicPoint<T>& r) {
  if (p == antipode(q)) throw Undefined(detail::kAntipodalSegment);
  if (orient(p, q, r) != ZERO) return false;
  if (p == q) return r == p;  // the one-point segment
  // (u × v)·(s × t) = (u·s)(v·t) − (u·t)(v·s) (Lagrange's identity) on the coordinates.
  auto coefficient = [](const auto& u, const auto& v, const auto& s, const auto& t) {
    auto dot = [](const auto& a, const auto& b) {
      return a.w * b.w + a.x * b.x + a.y * b.y;
    };
    return dot(u, s) * dot(v, t) - dot(u, t) * dot(v, s);
  };
  // α: (r × q)·(p × q);  β: (p × r)·(p × q).
  const Sign alpha = sign_of_poly(coefficient, r, q, p, q);
  const Sign beta = sign_of_poly(coefficient, p, r, p, q);
  return alpha != NEGATIVE && beta != NEGATIVE;
}
//< on-segment

}  // namespace detail

/// Is r on the segment pq? (seed 000, §4.3.5) Exact; throws `Undefined` when q = ¬p.
///
/// The seed maps the question to R³: with a = p, b = q, c = r and d = −a as vectors, "if b and
/// c are on the same side of the line ad, r ∈ pq iff Δ(c, o, a) ≠ Δ(c, o, b) or r = p". That
/// is sound read in the plane through o, a and b (which holds c): there the line ad passes
/// through o, Δ is the orientation within that plane (any fixed normal orients it), and the
/// unsaid case, b and c on different sides, means r ∉ pq. The same test written with signs of
/// T² is used here: r ∈ pq iff r is a non-negative combination αp + βq. With p ≠ ±q the cross
/// product n = p × q is not zero, and for r in the plane of p and q (Δ(p, q, r) = 0)
/// r × q = α n and p × r = β n, so sign α = sign((r×q)·n), sign β = sign((p×r)·n): two exact
/// degree-4 signs. For p = q the segment is the point p, and r is on it iff r = p.
///
/// (Written as two plain overloads rather than a template, so that it coexists with the
/// identical template of polygon.hpp; non-templates win overload resolution.)
inline bool on_segment(const Point& p, const Point& q, const Point& r) { return detail::on_segment_impl(p, q, r); }
/// Is r on the segment pq? Exact; the `Integer` version of `on_segment` above.
inline bool on_segment(const ExactPoint& p, const ExactPoint& q, const ExactPoint& r) {
  return detail::on_segment_impl(p, q, r);
}

/// Is r on the segment s (endpoints included)? Exact.
template <class T>
bool contains(const BasicSegment<T>& s, const BasicPoint<T>& r) {
  return on_segment(s.source(), s.target(), r);
}

/// How a segment looks in the planar (two-sided) model (seed 000, §3.4, figures 3.8–3.10).
enum class SegmentKind {
  front,             ///< both ends on the front side: an ordinary segment of the front plane
  back,              ///< both ends on the back side: an ordinary segment of the back plane
  crossing,          ///< one end front, one back: two half-rays meeting at a point of Ω
  front_ray,         ///< one end front, the other on Ω: a half-ray of the front plane
  back_ray,          ///< one end back, the other on Ω: a half-ray of the back plane
  on_infinity,       ///< both ends on Ω: an arc of the line at infinity
};

/// "front", "back", "crossing", "front_ray", "back_ray" or "on_infinity".
inline const char* to_string(SegmentKind k) {
  switch (k) {
    case SegmentKind::front: return "front";
    case SegmentKind::back: return "back";
    case SegmentKind::crossing: return "crossing";
    case SegmentKind::front_ray: return "front_ray";
    case SegmentKind::back_ray: return "back_ray";
    default: return "on_infinity";
  }
}

/// The planar-model case of s (see `SegmentKind`). A front–front segment never leaves the
/// front side, since αp + βq has w = αw_p + βw_q > 0; likewise back–back.
template <class T>
SegmentKind kind(const BasicSegment<T>& s) {
  const int a = static_cast<int>(side_of(s.source())), b = static_cast<int>(side_of(s.target()));
  if (a == 1 && b == 1) return SegmentKind::front;
  if (a == -1 && b == -1) return SegmentKind::back;
  if (a * b == -1) return SegmentKind::crossing;
  if (a + b == 1) return SegmentKind::front_ray;
  if (a + b == -1) return SegmentKind::back_ray;
  return SegmentKind::on_infinity;
}

/// True when s has one end on the front side and one on the back (figure 3.10): in the planar
/// model it is drawn as two half-rays, from the front end to `point_at_infinity(s)` and from
/// there on to the back end.
template <class T>
bool crosses_infinity(const BasicSegment<T>& s) {
  return kind(s) == SegmentKind::crossing;
}

/// The point where s meets Ω: |w_q|p + |w_p|q for a crossing segment (the seed's half-rays
/// both run towards it: from p "in the direction opposite to ¬q"), the end on Ω for a ray.
/// Throws `Undefined` for segments that do not meet Ω in exactly one point (front, back, or
/// lying on Ω). No division: exact with `Integer` coordinates.
template <class T>
BasicPoint<T> point_at_infinity(const BasicSegment<T>& s) {
  switch (kind(s)) {
    case SegmentKind::front_ray:
    case SegmentKind::back_ray:
      return is_at_infinity(s.source()) ? s.source() : s.target();
    case SegmentKind::crossing: {
      const auto& p = s.source();
      const auto& q = s.target();
      return detail::exactly<T>(
          [](const ExactPoint& a, const ExactPoint& b) {
            const Integer wa = abs(a.w()), wb = abs(b.w());
            return mix(wb, a, wa, b);
          },
          p, q);
    }
    default:
      throw Undefined("point_at_infinity(s) is undefined unless s meets the line at infinity in one point");
  }
}

/// The pieces of s as drawn in the planar model: for a crossing segment the half-ray from the
/// source to `point_at_infinity(s)` and the one from there to the target (each on one side,
/// kinds `front_ray`/`back_ray`); for every other segment s itself.
template <class T>
std::vector<BasicSegment<T>> planar_pieces(const BasicSegment<T>& s) {
  if (!crosses_infinity(s)) return {s};
  const BasicPoint<T> c = point_at_infinity(s);
  return {BasicSegment<T>(s.source(), c), BasicSegment<T>(c, s.target())};
}

/// Do the closed segments s and t share a point? Exact.
///
/// With n = a×b and m = c×d the normals of the two great circles (s = ab, t = cd) and
/// L = n × m one of their two common points, L lies on arc ab iff Δ(c,d,a) ≥ 0 ≥ Δ(c,d,b) and
/// on arc cd iff Δ(a,b,c) ≤ 0 ≤ Δ(a,b,d); −L iff the reverse inequalities hold. So, unlike in
/// R², four orientations that "straddle" are not enough: the two arcs may cross the other's
/// circle at antipodal points (s and ¬t), which needs the extra sign condition below.
/// Segments on a common line meet iff one holds an endpoint of the other.
template <class T>
bool intersects(const BasicSegment<T>& s, const BasicSegment<T>& t) {
  const auto &a = s.source(), &b = s.target(), &c = t.source(), &d = t.target();
  if (s.is_degenerate()) return contains(t, a);
  if (t.is_degenerate()) return contains(s, c);
  const int s1 = orient(a, b, c), s2 = orient(a, b, d), s3 = orient(c, d, a), s4 = orient(c, d, b);
  if (s1 == 0 && s2 == 0) {  // c and d on the line of s: the same great circle
    return contains(s, c) || contains(s, d) || contains(t, a) || contains(t, b);
  }
  const bool plus = s3 >= 0 && s4 <= 0 && s1 <= 0 && s2 >= 0;
  const bool minus = s3 <= 0 && s4 >= 0 && s1 >= 0 && s2 <= 0;
  return plus || minus;
}

/// What two segments share: nothing (`std::monostate`), one point, or a segment (overlapping
/// segments on a common line).
template <class T>
using SegmentIntersection = std::variant<std::monostate, BasicPoint<T>, BasicSegment<T>>;

/// The intersection of two closed segments. A crossing point is |Δ(a,b,d)|·c + |Δ(a,b,c)|·d
/// (the identity (a×b)×(c×d) = Δ(a,b,d)c − Δ(a,b,c)d, with the sign that keeps it on both
/// arcs): four orientations, no division. With `double` points it is computed exactly and
/// rounded once. A common piece of collinear segments is oriented like s.
template <class T>
SegmentIntersection<T> intersection(const BasicSegment<T>& s, const BasicSegment<T>& t) {
  if (!intersects(s, t)) return std::monostate{};
  const auto &a = s.source(), &b = s.target(), &c = t.source(), &d = t.target();
  if (s.is_degenerate()) return a;
  if (t.is_degenerate()) return c;
  if (orient(a, b, c) != ZERO || orient(a, b, d) != ZERO) {
    return detail::exactly<T>(
        [](const ExactPoint& ea, const ExactPoint& eb, const ExactPoint& ec, const ExactPoint& ed) {
          auto det = [](const ExactPoint& p, const ExactPoint& q, const ExactPoint& r) {
            return Integer(det3(p.w(), p.x(), p.y(), q.w(), q.x(), q.y(), r.w(), r.x(), r.y()));
          };
          const Integer u = abs(det(ea, eb, ed)), v = abs(det(ea, eb, ec));
          return mix(u, ec, v, ed);
        },
        a, b, c, d);
  }
  // Collinear overlap: an arc whose ends are endpoints of s or t (at most two distinct ones,
  // since two arcs shorter than half a circle cannot meet in two pieces).
  std::vector<BasicPoint<T>> ends;
  auto add = [&](const BasicPoint<T>& p) {
    for (const auto& e : ends)
      if (e == p) return;
    ends.push_back(p);
  };
  if (contains(t, a)) add(a);
  if (contains(s, c)) add(c);
  if (contains(s, d)) add(d);
  if (contains(t, b)) add(b);
  if (ends.size() == 1) return ends[0];
  // Orient the piece like s: the end nearer to a (between a and the other) comes first.
  if (on_segment(a, ends[1], ends[0])) return BasicSegment<T>(ends[0], ends[1]);
  return BasicSegment<T>(ends[1], ends[0]);
}

/// "segment([w, x, y] -> [w, x, y])".
template <class T>
std::string to_string(const BasicSegment<T>& s) {
  return "segment(" + to_string(s.source()) + " -> " + to_string(s.target()) + ")";
}

}  // namespace t2
