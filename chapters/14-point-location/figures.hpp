#pragma once
// Chapter 14's example map (a fan of faces around one vertex, crossing Ω) and its figures.
#include <t2/t2.hpp>

#include <filesystem>
#include <vector>

namespace chapter14 {

/// The faces of the chapter's map (data/examples/fan-map.t2): four triangles around the vertex
/// (1, 0), one of whose vertices is a back point, and a fifth triangle on the far side of Ω.
std::vector<t2::Polygon> fan_map();

/// A comb of m teeth, in eighths ([8, x, y] is the point (x/8, y/8)): the face of 4m vertices
/// made of [0, 2m − 1] × [0, 1] and the teeth [2i, 2i + 1] × [1, 2], i < m; counter-clockwise.
t2::Polygon comb(int m);
/// The triangle beside the comb whose vertex [8, −1, 1.5] starts the walk across the teeth.
t2::Polygon comb_start();

/// Writes the chapter's figures into `dir`.
void figures(const std::filesystem::path& dir);

}  // namespace chapter14
