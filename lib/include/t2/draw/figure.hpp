#pragma once
/// @file figure.hpp
/// @brief A figure: an ordered list of styled items that refer to geometry of T².
///
/// Items are stored with `double` coordinates (exact inputs are rounded to the nearest double
/// point: a drawing has no need of more). Every geometric item is reduced to points of T²
/// joined by *segments of T²* (shorter great-circle arcs), so that both models draw the same
/// set: the planar model splits each arc where it crosses Ω, the spherical model where it
/// crosses the limb.

#include <string>
#include <type_traits>
#include <vector>

#include "t2/kernel/bbox.hpp"
#include "t2/kernel/circle.hpp"
#include "t2/draw/style.hpp"
#include "t2/kernel/isorect.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/ray.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/kernel/t1.hpp"
#include "t2/kernel/triangle.hpp"

namespace t2::draw {

/// What an item of a figure is.
enum class ItemKind {
  point,     ///< one point of T² (`points[0]`)
  line,      ///< a whole oriented line (`line`)
  segment,   ///< the segment of T² from `points[0]` to `points[1]`
  polygon,   ///< closed chain of segments through `points` (filled with `Style::fill`)
  polyline,  ///< open chain of segments through `points`
  label,     ///< `text` placed next to `points[0]`
  t1,        ///< a point of T¹ (`t1w`, `t1x`), drawn only by `T1View`
  circle,    ///< a circle of finite or beyond-infinity radius: the closed loop `points`, all on
             ///< one side, sampled in the circle's orientation (starting at its boundary point)
};

/// One styled item of a figure (see `Figure` for how to make them).
struct Item {
  ItemKind kind = ItemKind::point;  ///< what the item is
  std::vector<Point> points;        ///< its points (meaning depends on `kind`)
  Line line = Line(1, 0, 0);        ///< the line of an `ItemKind::line` item
  double t1w = 1;                   ///< weight of a T¹ item
  double t1x = 0;                   ///< coordinate of a T¹ item
  std::string text;                 ///< text of a label item
  Style style;                      ///< how it looks
};

namespace detail {
/// A point with `double` coordinates from a point of any coordinate type.
template <class T>
Point as_double(const BasicPoint<T>& p) {
  if constexpr (std::is_same_v<T, double>) {
    return p;
  } else {
    return to_double(p);
  }
}
/// A line with `double` coefficients from a line of any coefficient type.
template <class T>
Line as_double(const BasicLine<T>& l) {
  if constexpr (std::is_same_v<T, double>) {
    return l;
  } else {
    const Point p = to_double(ExactPoint(l.W(), l.X(), l.Y()));
    return Line(p.w(), p.x(), p.y());
  }
}
/// The vertices of a closed chain without consecutive repeats (cyclically).
template <class T>
std::vector<BasicPoint<T>> distinct_cycle(std::vector<BasicPoint<T>> v) {
  std::vector<BasicPoint<T>> out;
  for (auto& p : v)
    if (out.empty() || !(out.back() == p)) out.push_back(std::move(p));
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}
}  // namespace detail

/// An ordered list of styled items. Items are drawn by layer, then in the order added.
class Figure {
 public:
  /// Adds a point (front: filled marker; back: hollow marker; on Ω: on the horizon).
  template <class T>
  Figure& add(const BasicPoint<T>& p, Style s = {}) {
    return push(ItemKind::point, {detail::as_double(p)}, std::move(s));
  }
  /// Adds a whole oriented line (both sides in the planar model, a great circle on the sphere).
  /// With `Style::shade()` its positive side is shaded (a half-plane pair / hemisphere).
  template <class T>
  Figure& add(const BasicLine<T>& l, Style s = {}) {
    Item it;
    it.kind = ItemKind::line;
    it.line = detail::as_double(l);
    it.style = std::move(s);
    items_.push_back(std::move(it));
    return *this;
  }
  /// Adds a polygon: the closed chain of T² segments through the vertices, in order.
  template <class T>
  Figure& add(const std::vector<BasicPoint<T>>& vertices, Style s = {}) {
    std::vector<Point> v;
    for (const auto& p : vertices) v.push_back(detail::as_double(p));
    return push(ItemKind::polygon, std::move(v), std::move(s));
  }
  /// Adds the segment of T² s (as `segment(s.source(), s.target())`).
  template <class T>
  Figure& add(const BasicSegment<T>& s, Style st = {}) {
    return segment(s.source(), s.target(), std::move(st));
  }
  /// Adds a ray: the segment from its source to its point at infinity.
  template <class T>
  Figure& add(const BasicRay<T>& r, Style st = {}) {
    return segment(r.source(), r.target(), std::move(st));
  }
  /// Adds a triangle as the polygon of its three vertices (`Style::fill` shades its interior,
  /// on both sides of T² when it crosses Ω).
  template <class T>
  Figure& add(const BasicTriangle<T>& t, Style s = {}) {
    return add(std::vector<BasicPoint<T>>{t.vertex(0), t.vertex(1), t.vertex(2)}, std::move(s));
  }
  /// Adds an iso-rectangle as the polygon of its vertices in its orientation (repeated
  /// vertices of a degenerate or unbounded rectangle are drawn once).
  template <class T>
  Figure& add(const BasicIsoRect<T>& r, Style s = {}) {
    return add(detail::distinct_cycle<T>({r.vertex(0), r.vertex(1), r.vertex(2), r.vertex(3)}), std::move(s));
  }
  /// Adds a bounding box as the polygon a, b, c, d (an unbounded box closes along Ω).
  template <class T>
  Figure& add(const BasicBBox<T>& b, Style s = {}) {
    return add(detail::distinct_cycle<T>({b.vertex(0), b.vertex(1), b.vertex(2), b.vertex(3)}), std::move(s));
  }
  /// Adds a circle of T² of any radius kind (circle.hpp, seed 000 §4.1.9):
  /// - finite radius: the Euclidean circle on the side of its centre;
  /// - beyond infinity: the points of the *other* side at the same Cartesian distance (drawn
  ///   dashed around the spot of the centre in the planar model, around ¬c on the sphere);
  /// - infinite, centre on Ω: the line through the boundary point perpendicular to the
  ///   centre's direction; infinite around a proper centre: Ω itself.
  ///
  /// It is traversed in its orientation (POSITIVE: counter-clockwise in T², which on the back
  /// side is clockwise as drawn), shown by `Style::arrow`. `Style::fill` shades the region the
  /// circle bounds on its own side: the disk of a finite circle; for a beyond-infinity circle
  /// the back disk around ¬c, i.e. the points *farther* from c than the circle; for an infinite
  /// one the half-plane or hemisphere holding the centre.
  template <class T>
  Figure& add(const BasicCircle<T>& c, Style s = {}) {
    return add_circle(detail::as_double(c.center()), detail::as_double(c.boundary_point()), c.orientation(),
                      std::move(s));
  }
  /// Adds a point of T¹ (drawn only by `T1View`: on the circle model or on the two lines).
  template <class T>
  Figure& add(const BasicT1<T>& a, Style s = {}) {
    Item it;
    it.kind = ItemKind::t1;
    if constexpr (std::is_same_v<T, double>) {
      it.t1w = a.w();
      it.t1x = a.x();
    } else {
      const Point p = to_double(ExactPoint(a.w(), a.x(), 0));
      it.t1w = p.w();
      it.t1x = p.x();
    }
    it.style = std::move(s);
    items_.push_back(std::move(it));
    return *this;
  }
  /// Adds the segment of T² from p to q: the shorter great-circle arc. Throws `t2::Undefined`
  /// when q = ¬p (the segment of two antipodes is undefined) or when p = q.
  template <class T>
  Figure& segment(const BasicPoint<T>& p, const BasicPoint<T>& q, Style s = {}) {
    return push(ItemKind::segment, {detail::as_double(p), detail::as_double(q)}, std::move(s));
  }
  /// Adds the arrow p → q: the segment with an arrowhead at q.
  template <class T>
  Figure& arrow(const BasicPoint<T>& p, const BasicPoint<T>& q, Style s = {}) {
    return segment(p, q, std::move(s.arrow(true)));
  }
  /// Adds an open chain of T² segments (a sampled curve, a path). Consecutive points must not
  /// be antipodes.
  template <class T>
  Figure& polyline(const std::vector<BasicPoint<T>>& pts, Style s = {}) {
    std::vector<Point> v;
    for (const auto& p : pts) v.push_back(detail::as_double(p));
    return push(ItemKind::polyline, std::move(v), std::move(s));
  }
  /// Adds `text` next to point p (offset in the direction `Style::label_angle()`).
  template <class T>
  Figure& label(const BasicPoint<T>& p, std::string text, Style s = {}) {
    Item it;
    it.kind = ItemKind::label;
    it.points = {detail::as_double(p)};
    it.text = std::move(text);
    it.style = std::move(s);
    items_.push_back(std::move(it));
    return *this;
  }

  /// A title drawn above the picture (empty: none).
  Figure& title(std::string t) { title_ = std::move(t); return *this; }
  /// The title.
  const std::string& title() const { return title_; }

  /// The items, in the order added.
  const std::vector<Item>& items() const { return items_; }

 private:
  Figure& push(ItemKind k, std::vector<Point> pts, Style s);
  Figure& add_circle(const Point& c, const Point& p, Sign orientation, Style s);
  std::vector<Item> items_;
  std::string title_;
};

}  // namespace t2::draw
