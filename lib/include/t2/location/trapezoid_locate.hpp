#pragma once
/// @file trapezoid_locate.hpp
/// @brief Point location in a subdivision of T² (subdivision.hpp) by two trapezoidal maps
/// (trapezoid_map.hpp), one per side, with the walk (walk.hpp) where a map cannot answer.
///
/// **Charts.** The front side w > 0 is the plane of its points (x/w, y/w); the back side w < 0
/// is that plane again through the antipode, ¬p having w > 0. A *chart* is *closed* when no edge
/// of the map joins a point of its open side to a point outside it (on Ω or on the other side):
/// then the part of the map on that side is a set of ordinary bounded segments, each an edge with
/// both endpoints on the side, and the trapezoidal map of those segments answers every query of
/// the side. The face of a trapezoid is the face on the upper side of its bottom segment (the
/// face of the half-edge running left to right, seen in the chart; on the back the antipode
/// reverses orientations, so it is the face of the half-edge running right to left); a trapezoid
/// with nothing below it lies in the chart's unbounded region, whose face is found once, by
/// `locate_brute` of a point of the side to the right of every vertex.
///
/// **What the walk does.** A query on Ω, or on a side whose chart is not closed (an edge crosses
/// Ω or ends on it while its other end is on the side), is answered by `walk` from the first vertex of face 0. The
/// answers are exactly those of `walk` and `locate_brute` (the least face for edges and vertices).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "t2/location/subdivision.hpp"
#include "t2/location/trapezoid_map.hpp"
#include "t2/location/walk.hpp"

namespace t2 {

/// Point location by one trapezoidal map per closed side (see the file comment).
class TrapezoidLocator {
 public:
  /// The side of a chart.
  enum Side { front = 0, back = 1 };

  /// Builds the maps of the closed sides of S, each in the random order drawn from `seed`.
  /// Throws `MapError` when two edges of a side cross or a vertex lies inside an edge.
  /// @param S the subdivision (must outlive the locator)
  /// @param seed the seed of the insertion orders
  explicit TrapezoidLocator(const Subdivision& S, std::uint64_t seed = 0x7A9E201D);
  /// The same, telling `hook` each insertion into each map (`Event::trapezoid_split`, front
  /// map first): the points it names are vertices of S, and `input_of` maps the map's own
  /// points to them (on the back its points are their antipodes).
  /// @param S the subdivision (must outlive the locator)
  /// @param seed the seed of the insertion orders
  /// @param hook hears the reports
  TrapezoidLocator(const Subdivision& S, std::uint64_t seed, const trace::AnyHook& hook);

  /// Where p lies: the answer of `walk` (walk.hpp), exact.
  /// @param p the query point
  Location locate(const Point& p) const;
  /// The same, telling `hook` each DAG node the query meets (`dag_x`, `dag_y`, `dag_leaf`, with
  /// the points as vertices of S), or the walk's reports where the walk answers.
  /// @param p the query point
  /// @param hook hears the reports
  Location locate(const Point& p, const trace::AnyHook& hook) const;

  /// The trapezoidal map of side `s`, or nullptr when its chart is not closed.
  /// @param s the side
  const TrapezoidMap* chart(Side s) const { return charts_[s].map ? &*charts_[s].map : nullptr; }

 private:
  struct Chart {
    std::optional<TrapezoidMap> map;
    std::vector<Subdivision::Index> vertex;     // chart point -> vertex of S
    std::vector<Subdivision::Index> half_edge;  // segment -> half-edge of S
    std::vector<Location> above;                // segment -> the region on its upper side
    Location unbounded;                         // the region of the unbounded part
  };
  void build(Side s, std::uint64_t seed, const trace::AnyHook& hook);
  Location answer(const Point& p, const trace::AnyHook* hook) const;
  const Subdivision& S_;
  Chart charts_[2];
};

}  // namespace t2
