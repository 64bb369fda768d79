#pragma once
/// @file step.hpp
/// @brief One recorded step of an animated algorithm: what happened, in a sentence, the state of
/// the algorithm's data structure, and what a picture of the step should highlight.
///
/// Steps carry a *depth* (seed 003, GeoLab's `animation_depth`): the lecture level shows the
/// steps that change the data structure (a push, a pop, a new hull vertex, a bridge, an
/// insertion, a flip); the debugging level adds every test the algorithm makes (each point
/// Graham or Jarvis considers, each in-circle test of Delaunay). A player shows the steps of
/// depth at most the chosen level.
///
/// A step names input points by index. What the algorithm *constructs* — a circle of an
/// in-circle test, a sweep line, a Voronoi vertex, an intersection point, a kd-tree split — is
/// not an input point: it goes into the step's `overlay`, a `t2::Scene` (kernel/scene.hpp) of
/// exact kernel objects (points, segments, polygons, lines, circles by centre and boundary
/// point, each with its style and label), drawn over the step's picture. A curve the kernel has
/// no object for (a parabola) goes into `curves`, sampled: drawing only.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "t2/kernel/scene.hpp"

namespace t2::trace {

/// How deep a step lies: the levels of detail of seed 003.
enum class Depth : int {
  lecture = 0,    ///< the steps a lecture shows: the data structure changes
  debugging = 1,  ///< every test the algorithm makes as well
};

/// The name of a depth ("lecture", "debugging").
inline const char* to_string(Depth d) { return d == Depth::lecture ? "lecture" : "debugging"; }

/// A triangle as three point indices (counter-clockwise).
using Tri = std::array<std::size_t, 3>;
/// An edge as two point indices.
using Edge = std::array<std::size_t, 2>;

/// One step of an algorithm, complete enough to be drawn and explained on its own (a player can
/// jump to it without replaying the steps before it).
struct Step {
  std::string kind;             ///< what happened: "push", "pop", "consider", "vertex", "flip", ...
  Depth depth = Depth::lecture; ///< the level of detail it belongs to
  std::string text;             ///< the explanation, one or two sentences
  // The data structure after the step.
  std::string structure;              ///< its name: "stack", "hull so far", "triangles touched"
  std::vector<std::size_t> chain;     ///< a chain of point indices (stack, hull so far)
  bool closed = false;                ///< the chain is a closed polygon (a hull), not an open path
  std::vector<Tri> triangles;         ///< the finite triangles so far (triangulations)
  /// The structure as lines of text, when it is neither a chain nor triangles (a trapezoidal
  /// map's DAG: its size, or a query's path down it); a player shows them beside the picture,
  /// the last one in focus.
  std::vector<std::string> entries;
  // What to highlight.
  std::vector<std::size_t> points;  ///< points in focus; the first is the current point
  std::vector<Edge> edges;          ///< edges in focus (a candidate edge, a bridge, a new edge)
  std::vector<Tri> touched;         ///< triangles in focus (the two triangles of a flip)
  // What the algorithm constructed, drawn over the picture (the file comment).
  Scene overlay;  ///< constructed geometry: circles, lines, points, segments (empty: none)
  /// Curves that are not kernel objects (the parabolic arcs of Fortune's beach line), each an
  /// open polyline of sample points: an approximation, drawn only, never used for a decision.
  std::vector<std::vector<Point>> curves;
};

}  // namespace t2::trace
