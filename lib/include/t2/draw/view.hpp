#pragma once
/// @file view.hpp
/// @brief Viewports of the models of T² and the projection mathematics behind them.
///
/// - `PlaneView`: the two-sided planar model (seed 000, fig. 3.3). The point [w, x, y] with
///   w ≠ 0 is drawn at (x/w, y/w) — so p and ¬p land on the same spot, the front one filled and
///   solid, the back one hollow and dashed. The finite part is clipped to a disk of radius
///   `half_width` around (cx, cy); Ω is the horizon ring just outside it, on which the point
///   [0, x, y] sits at direction (x, y).
/// - `SphereView`: the spherical model (fig. 3.4). [w, x, y] is centrally projected to the unit
///   sphere, in space coordinates (x, y, w): the front side is the upper hemisphere w > 0 and Ω
///   the equator. The sphere is seen orthographically from the direction of latitude `lat` and
///   longitude `lon` (degrees); what lies on the far hemisphere is dashed and faded.
/// - `T1View`: the oriented projective line T¹ as a circle (fig. 3.1) or as two copies of the
///   real line (fig. 3.2).

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "t2/draw/vec.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/point.hpp"

namespace t2::draw {

/// The unit vector of space representing p on the sphere: (x, y, w) / |(x, y, w)|.
Vec3 on_sphere(const Point& p);

/// The viewport of the planar model (see the file comment).
struct PlaneView {
  double cx = 0;          ///< x of the centre of the viewport
  double cy = 0;          ///< y of the centre of the viewport
  double half_width = 4;  ///< radius of the disk of the finite plane that is shown
  int size = 360;         ///< width and height of the picture in pixels (points for PDF)
  bool omega = true;      ///< draw the Ω ring
  bool axes = false;      ///< draw the x and y axes through the origin

  /// Where the finite point (x, y) is drawn, relative to the centre, in units where the
  /// visible disk has radius 1.
  Vec2 to_unit(double x, double y) const;
  /// Radius of the Ω ring in the same units (slightly more than 1).
  static constexpr double ring = 1.08;
  /// Where a point of T² is drawn (unit coordinates, see `to_unit`): a proper point at
  /// (x/w, y/w); a point at infinity on the ring at direction (x, y). The position may lie
  /// outside the visible disk (it is then clipped when drawn).
  Vec2 place(const Point& p) const;
};

/// The orthographic view of the spherical model (see the file comment).
struct SphereView {
  double lat = 25;        ///< latitude of the viewing direction, degrees (90: from above)
  double lon = -65;       ///< longitude of the viewing direction, degrees
  int size = 360;         ///< width and height of the picture in pixels (points for PDF)
  bool omega = true;      ///< draw Ω (the equator w = 0)
  bool graticule = false; ///< draw meridians and parallels every 30 degrees, faintly

  /// The unit vector towards the viewer: (cos lat cos lon, cos lat sin lon, sin lat).
  Vec3 eye() const;
  /// The screen axes: unit vectors of space drawn to the right and up.
  std::pair<Vec3, Vec3> screen_axes() const;
  /// Orthographic projection of a point of space onto the picture (the sphere outline is the
  /// unit circle).
  Vec2 project(const Vec3& s) const;
  /// Projection of a point of T² (central projection to the sphere, then `project`).
  Vec2 project(const Point& p) const { return project(on_sphere(p)); }
  /// Height of s towards the viewer (s · eye): positive on the visible hemisphere.
  double depth(const Vec3& s) const;
};

/// The view of the sphere that looks straight at the points `pts`: `base` with its latitude and
/// longitude turned to the mean of their unit vectors (`on_sphere`), so that the data sits in the
/// middle of the picture. A mean within 10° of a pole is rounded to the pole, seen with longitude
/// −90°: the picture is then turned as the planar model's, x to the right (and, from above, y
/// up). When the points balance out (a mean of length below 1e-9 per point), or `pts` is empty,
/// `base` is returned unchanged.
SphereView facing(const std::vector<Point>& pts, SphereView base = {});

/// The projected great circle of a line: an ellipse centred at the origin.
struct Ellipse {
  Vec2 major;        ///< unit vector along the major axis (the semi-major axis is 1)
  double minor = 0;  ///< semi-minor axis length, |n · eye| for the unit normal n of the line
};

/// The ellipse on which the great circle of line l projects in view `v`. It touches the
/// outline (the unit circle) at ±`major`, the projections of the two limb points of l.
Ellipse great_circle_ellipse(const Line& l, const SphereView& v);

/// The limb points of the great circle of l: the two points of the circle with depth 0, as
/// unit vectors (n × eye normalized, and its opposite). Empty when the circle *is* the limb.
std::optional<std::pair<Vec3, Vec3>> limb_points(const Line& l, const SphereView& v);

/// One piece of an arc: from `a` to `b` along the shorter great circle, entirely on one side
/// of the limb.
struct ArcPiece {
  Vec3 a;               ///< start (unit vector)
  Vec3 b;               ///< end (unit vector)
  bool visible = true;  ///< true on the near hemisphere
};

/// Splits the segment of T² from p to q (the shorter arc) at the limb: one piece when it does
/// not cross the limb, two when it does (an arc shorter than half a circle crosses a great
/// circle at most once). Throws `t2::Undefined` when q = ¬p.
std::vector<ArcPiece> split_at_limb(const Point& p, const Point& q, const SphereView& v);

/// How T¹ is drawn.
enum class T1Model {
  circle,  ///< the unit circle: [w, x] at the direction of the vector (w, x) (fig. 3.1)
  lines,   ///< two copies of the real line, front above, back below (fig. 3.2)
};

/// The viewport of the oriented projective line T¹.
struct T1View {
  T1Model model = T1Model::circle;  ///< which model
  double half_width = 4;            ///< for `T1Model::lines`: the shown part of each line
  int size = 360;                   ///< width of the picture in pixels
};

}  // namespace t2::draw
