#pragma once
// The labelled 3-D figures of chapter 08: the lifted points, the horizon of the incremental hull
// and one turn of gift wrapping. Each is drawn in parallel projection onto a plane figure (front
// points only, without Ω), so that the figure library places the labels and dashes hidden edges.
#include <t2/t2.hpp>

#include <filesystem>
#include <vector>

namespace chapter08 {

/// Writes lifted.svg: the points A (front points of the plane) lifted to the paraboloid, z scaled
/// by 1/8, seen from below; the lower hull's faces, each lifted point labelled.
void lifted_figure(const std::vector<t2::Point>& A, const std::filesystem::path& dir);

/// Writes horizon.svg: a hull, a new point p, the faces p sees and the horizon between them and
/// the rest.
void horizon_figure(const std::filesystem::path& dir);

/// Writes gift-wrap.svg: a facet, the pivot edge, the candidates and the facet the turn finds.
void gift_wrap_figure(const std::filesystem::path& dir);

}  // namespace chapter08
