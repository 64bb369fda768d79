#pragma once
// The input of `t2 bench locate` beyond the points (location.cpp): the query points, the same
// for t2's walk and for the peers; and what the animations of point location share (the walk's
// in location.cpp, the trapezoidal map's in location_trapezoid.cpp): the map and the words.

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/location/subdivision.hpp"
#include "t2/location/walk.hpp"
#include "t2/trace/step.hpp"

namespace t2cli::algorithms {

/// As many queries as points, uniform in the points' bounding box (a fixed seed), in random
/// order or, with `sorted`, in t2's spatial order (spatial_sort.hpp, BRIO rounds of Hilbert
/// order), so that each query lies near the one before.
std::vector<t2::Point> locate_queries(std::span<const t2::Point> points, bool sorted);

/// The queries of `t2 animate walk` and `t2 animate trapezoid`, seven: q0 to q3 uniform in the
/// bounding box of the proper points' drawn positions (a fixed seed), q4 the middle input point
/// p[n/2] (a vertex of the map, unless a duplicate), q5 the antipode of q0 (on the back side) and
/// q6 = [0, 1, 0] on Omega.
std::vector<t2::Point> animation_queries(std::span<const t2::Point> points);

/// The map of `t2 bench locate`: the Delaunay triangles of the points, as a subdivision.
std::shared_ptr<const t2::Subdivision> delaunay_map(const std::vector<t2::Point>& points);

/// The map of the animations: `delaunay_map`, or t2::Undefined / t2::BadInput naming the scene
/// `name` (no triangle: nothing to locate in).
std::shared_ptr<const t2::Subdivision> animation_map(const std::vector<t2::Point>& P, const std::string& name);

/// The triangles of the map (its faces), as trace triples.
std::vector<t2::trace::Tri> map_triangles(const t2::Subdivision& S);

/// Face f of a map of triangles, as a trace triple.
t2::trace::Tri face_triangle(const t2::Subdivision& S, t2::Subdivision::Index f);

/// "p3 p8 p5"
std::string tri_text(const t2::trace::Tri& t);

/// "(x, y)", "(x, y) on the back" or "[0, x, y] on Omega".
std::string query_text(const t2::Point& q);

/// What the answer l is, in words ("inside triangle p1 p2 p3"), and what a picture of it
/// highlights, added to `s`.
std::string answer_text(const t2::Subdivision& S, const t2::Location& l, t2::trace::Step& s);

/// A point location method: where q lies in S.
using Locate = std::function<t2::Location(const t2::Subdivision& S, const t2::Point& q)>;

/// The answer of an animation of point location as a scene (an algorithm's `run`): the triangle
/// holding each of the `animation_queries` that lies inside one, in the order of the queries,
/// and the queries.
t2::Scene answers_scene(const std::vector<t2::Point>& P, const Locate& locate);

}  // namespace t2cli::algorithms
