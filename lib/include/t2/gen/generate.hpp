#pragma once
/// @file generate.hpp
/// @brief Seeded, reproducible inputs for tests, benchmarks and lectures (`t2 gen KIND`).
///
/// Every generator is a pure function of its `Options`: the same options give the same points,
/// bit for bit, on any machine (see random.hpp for why no `std::*_distribution` is used). Where
/// the point of an input is a degeneracy, the degeneracy is *exact*: collinear points have
/// dyadic coordinates on one line, cocircular points are Pythagorean triples [c, a, b] with
/// a² + b² = c² (exactly on the unit circle in homogeneous coordinates).

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/kernel/polygon.hpp"
#include "t2/kernel/segment.hpp"

namespace t2::gen {

/// What a generator makes. The names (`name`, `kind_from_name`) are those of `t2 gen`.
enum class Kind {
  uniform,           ///< uniform in the square [-1, 1)²
  disk,              ///< uniform in the open unit disk
  polygon_interior,  ///< uniform in the L-shaped polygon (-1,-1) (1,-1) (1,0) (0,0) (0,1) (-1,1)
  normal,            ///< `clusters` normal clusters (σ = 0.1, Irwin–Hall) around uniform centres
  kuzmin,            ///< Kuzmin's distribution (as in PBBS): heavy-tailed around the origin
  circle,            ///< exactly on the unit circle: [c, a, b] with a² + b² = c² (or rounded, `cartesian`)
  segment,           ///< exactly on the line y = x/2 + 1/4, x in [-1, 1] (dyadic coordinates)
  boundary,          ///< exactly on the boundary of the square [-1, 1]² (dyadic coordinates)
  grid,              ///< integer points of the m×m grid, m = ⌈√n⌉ (collinear triples and duplicates)
  duplicates,        ///< n/8 distinct points, each repeated, written with random scales 1, 2, 4
  both_sides,        ///< front and back points, a share `back` behind, with a hull crossing Ω
  antipodal,         ///< front points and the antipodes of a tenth of them: no hull
  infinity,          ///< half front points, half points at infinity in directions (dx > 0, dy)
  circle_both_sides, ///< exactly on the circle of the sphere around the Ω point [0, 1, 0]: [a, c, b]
                     ///< with a² + b² = c², so on both sides (the unit circle turned about the y axis)
  cube,              ///< 3-D: uniform in the cube [-1, 1)³ (lines `x y z`)
  sphere,            ///< 3-D: on the unit sphere, rounded (lines `x y z`)
  simple_polygon,    ///< a random simple polygon (space partitioning, or 2-opt untangling: `untangle`)
  star_polygon,      ///< a polygon star-shaped around the origin
  convex_polygon,    ///< a convex polygon with vertices exactly on the unit circle
  monotone_polygon,  ///< an x-monotone polygon
  segments,          ///< segments with exactly `crossings` proper crossings
  polygon_edges,     ///< the edges of random 16-gons: connected (shared endpoints), polygons crossing
  segment_grid,      ///< n unit edges of an m×m integer grid: up to four segments end at a point
  segments_through_point,  ///< n segments through the origin (exactly): one point on all of them
};

/// The parameters of a generator.
struct Options {
  std::size_t n = 1000;        ///< how many points (vertices, segments)
  std::uint64_t seed = 1;      ///< the random stream
  double back = 0.3;           ///< both-sides: the share of points behind, in [0, 1]
  std::size_t crossings = 0;   ///< segments: the number of crossings
  std::size_t clusters = 4;    ///< normal: the number of clusters
  bool cartesian = false;      ///< circle: rounded (a/c, b/c) instead of exact [c, a, b]
  bool untangle = false;       ///< simple-polygon: 2-opt untangling of a random polygon, not space partitioning
};

/// Every kind, in the order of the enumeration.
const std::vector<Kind>& all_kinds();
/// The `t2 gen` name of a kind ("both-sides").
std::string_view name(Kind k);
/// The kind of a name; throws `BadInput` naming the valid kinds.
Kind kind_from_name(std::string_view name);
/// What the kind makes, in one line (for `t2 gen --help`).
std::string_view description(Kind k);

/// The points of a point kind (uniform ... infinity). Throws `BadInput` for another kind or
/// impossible options.
std::vector<Point> points(Kind k, const Options& o);
/// The points of a 3-D kind (cube, sphere).
std::vector<std::array<double, 3>> points3(Kind k, const Options& o);
/// The vertices of a polygon kind (simple-, star-, convex-, monotone-polygon), counter-clockwise.
Polygon polygon(Kind k, const Options& o);
/// Segments (kind segments): n segments with exactly o.crossings proper crossings, no other
/// contact.
std::vector<Segment> segments(const Options& o);
/// The n segments of a segment kind (segments, polygon-edges, segment-grid,
/// segments-through-point); throws `BadInput` for another kind.
std::vector<Segment> segments(Kind k, const Options& o);
/// Is k a kind of segments?
bool is_segment_kind(Kind k);

/// The file `t2 gen` writes: a comment naming the command, then the scene (or `x y z` lines).
std::string to_text(Kind k, const Options& o);

}  // namespace t2::gen
