#pragma once
/// @file trapezoid_map.hpp
/// @brief The trapezoidal map of non-crossing segments of one affine chart, built by randomized
/// incremental construction with its history DAG (de Berg, van Kreveld, Overmars and
/// Schwarzkopf, *Computational Geometry*, chapter 6), exact.
///
/// **The chart.** Every point given has w > 0 (a front point; the caller maps the back side to
/// the front by the antipode, trapezoid_locate.hpp). The segments are segments of T² between such
/// points, so each is the ordinary segment of the plane z = (x/w, y/w), and no point at infinity
/// is involved. They may share endpoints, but two of them meet nowhere else and no endpoint lies
/// inside another segment (a violation met during the construction throws `SegmentError`; not every crossing is met).
///
/// **Degeneracies.** The x-order is the lexicographic order (x, then y) of `compare_xy`: it is the
/// order of the x-coordinates after the symbolic shear (x, y) ↦ (x + εy, y), so no two distinct
/// endpoints share an x and no segment is vertical (de Berg et al., §6.3). "p above segment ab"
/// (a before b) is orient(a, b, p) > 0, which the shear does not change. The map has no bounding
/// box: a trapezoid may be unbounded to the left or right (no `leftp`/`rightp`) and above or below
/// (no `top`/`bottom`), which the algorithm never needs to compare.
///
/// **Answers.** A query point p (w > 0) is equal to an endpoint (`Hit::point`), inside a segment
/// (`Hit::segment`), or strictly inside a trapezoid whose bottom segment is `below` (`none` if
/// nothing is below p). All decisions are signs of `compare_xy` and `orient` on input points.
///
/// **Tracing** (trace/hook.hpp). The construction and the query have overloads that tell a hook
/// each insertion (`trapezoid_split`) and each DAG node a query meets (`dag_x`, `dag_y`,
/// `dag_leaf`), with the map lent; the overloads without a hook contain no trace code.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

/// Segments that are not a valid input of a trapezoidal map: `segment()` is one at fault.
class SegmentError : public BadInput {
 public:
  /// @param segment the index of a segment at fault
  /// @param what what is wrong
  SegmentError(std::size_t segment, const std::string& what) : BadInput(what), segment_(segment) {}
  /// The index of a segment at fault.
  std::size_t segment() const { return segment_; }

 private:
  std::size_t segment_;
};

/// The trapezoidal map of segments of one chart and its history DAG (see the file comment).
class TrapezoidMap {
 public:
  using Index = std::uint32_t;                ///< point, segment, trapezoid and node indices
  static constexpr Index none = 0xFFFFFFFFu;  ///< no segment, point, neighbour or node

  /// Where a query point lies.
  struct Hit {
    /// What the point hits.
    enum class Kind {
      trapezoid,  ///< strictly inside a trapezoid: `id` is it, `below` the segment under it
      segment,    ///< inside segment `id`
      point       ///< equal to point `id`
    } kind = Kind::trapezoid;  ///< what the point hits
    Index id = none;           ///< the trapezoid, segment or point
    Index below = none;        ///< for a trapezoid: its bottom segment, or `none`
    std::size_t steps = 0;     ///< the DAG nodes visited (the query's path length)
  };

  /// One trapezoid: bounded by the segments `top` and `bottom` and the vertical lines through the
  /// points `leftp` and `rightp` (`none`: unbounded that way); its neighbours across the parts of
  /// its left side above and below `leftp` (`ul`, `ll`) and of its right side (`ur`, `lr`).
  struct Trapezoid {
    Index top = none;     ///< the segment above
    Index bottom = none;  ///< the segment below
    Index leftp = none;   ///< the point of the left side
    Index rightp = none;  ///< the point of the right side
    Index ul = none;      ///< upper-left neighbour
    Index ll = none;      ///< lower-left neighbour
    Index ur = none;      ///< upper-right neighbour
    Index lr = none;      ///< lower-right neighbour
    Index node = none;    ///< its leaf in the DAG (`none` once it is destroyed)
  };

  /// Builds the map of `segments` (pairs of indices into `points`, in either direction) by
  /// inserting them in the order of a random permutation drawn from `seed`. Throws `SegmentError`
  /// for segments that cross, overlap or touch another's inside (see the file comment).
  /// @param points the endpoints, each with w > 0, no two equal
  /// @param segments the segments, as index pairs into `points`
  /// @param seed the seed of the insertion order
  TrapezoidMap(std::vector<Point> points, std::vector<std::pair<Index, Index>> segments, std::uint64_t seed);
  /// The same construction, telling `hook` each insertion (`Event::trapezoid_split`; the points
  /// named are indices into `points`).
  /// @param points the endpoints, each with w > 0, no two equal
  /// @param segments the segments, as index pairs into `points`
  /// @param seed the seed of the insertion order
  /// @param hook hears the reports
  TrapezoidMap(std::vector<Point> points, std::vector<std::pair<Index, Index>> segments, std::uint64_t seed,
               const trace::AnyHook& hook);

  /// Locates p (w > 0) by descending the DAG. Expected O(log n) steps for random insertion
  /// orders (chapter 14, part 3).
  /// @param p the query point
  Hit locate(const Point& p) const;
  /// The same query, telling `hook` each DAG node it meets (`dag_x`, `dag_y`, `dag_leaf`).
  /// @param p the query point
  /// @param hook hears the reports
  Hit locate(const Point& p, const trace::AnyHook& hook) const;

  /// The number of segments.
  std::size_t segments() const { return seg_.size(); }
  /// The number of DAG nodes (inner nodes and leaves).
  std::size_t nodes() const { return node_.size(); }
  /// Every trapezoid made, by index (as in `Hit::id` and the neighbour fields); those of the
  /// final map have a `node`, the destroyed ones `none`.
  const std::vector<Trapezoid>& trapezoids() const { return trap_; }
  /// The greatest number of nodes on a path from the root to a leaf.
  std::size_t depth() const;
  /// Segment i as (left, right) point indices, left before right in the x-order.
  std::pair<Index, Index> segment(Index i) const { return {seg_[i].a, seg_[i].b}; }
  /// Point i (as given, w > 0).
  const Point& point(Index i) const { return P_[i]; }

 private:
  struct Seg {
    Index a, b;  // a before b in the x-order
  };
  struct Node {
    enum Kind : std::uint8_t { x, y, leaf } kind;
    Index id;           // the point (x), the segment (y), the trapezoid (leaf)
    Index left, right;  // x: left, right; y: above, below
  };
  template <class H>
  void build(std::vector<std::pair<Index, Index>> segments, std::uint64_t seed, H& hook);
  template <class H>
  void insert(Index s, H& hook);
  template <class H>
  Hit descend(const Point& p, H& hook) const;
  trace::Report told(trace::Event e, std::initializer_list<std::size_t> at, Sign sign,
                     Index trapezoid) const;
  Index locate_left(Index s) const;
  Index make(const Trapezoid& t);
  void link_upper(Index left, Index right);
  void link_lower(Index left, Index right);
  Index push(const Node& n);
  std::vector<Point> P_;
  std::vector<Seg> seg_;
  std::vector<Trapezoid> trap_;
  std::vector<Node> node_;
};

}  // namespace t2
