#pragma once
// The Voronoi diagram of T² drawn (voronoi_dual.cpp): what `t2 voronoi --svg` draws and what
// `t2 animate voronoi` shows, one drawing for both.

#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/voronoi/voronoi.hpp"

namespace t2cli::algorithms {

/// The edge e of `vd` drawn into `s` with `style`: the segment of T² between its vertices when a
/// point of it, a + b, has no site nearer than e.s; otherwise the other arc of the bisector,
/// through ¬(a + b), as two segments. Nothing for an edge between antipodal vertices (either
/// half of the bisector).
void add_voronoi_edge(const std::vector<t2::Point>& P, const t2::VoronoiDiagram& vd,
                      const t2::VoronoiDiagram::Edge& e, const t2::SceneStyle& style, t2::Scene& s);

/// The bisector lines of the pairs `lines` (sites without a Voronoi vertex) drawn into `s`.
void add_bisector_lines(const std::vector<t2::Point>& P, const std::vector<std::pair<t2::VoronoiDiagram::Index,
                        t2::VoronoiDiagram::Index>>& lines, const t2::SceneStyle& style, t2::Scene& s);

/// The diagram as a scene: its edges and bisector lines with `edge`, its vertices with `vertex`.
t2::Scene voronoi_scene(const std::vector<t2::Point>& P, const t2::VoronoiDiagram& vd, const t2::SceneStyle& edge,
                        const t2::SceneStyle& vertex);

}  // namespace t2cli::algorithms
