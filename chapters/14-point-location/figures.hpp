#pragma once
// Chapter 14's example map (a fan of faces around one vertex, crossing Ω) and its figures.
#include <t2/t2.hpp>

#include <filesystem>
#include <vector>

namespace chapter14 {

/// The faces of the chapter's map (data/examples/fan-map.t2): four triangles around the vertex
/// (1, 0), one of whose vertices is a back point, and a fifth triangle on the far side of Ω.
std::vector<t2::Polygon> fan_map();

/// Writes the chapter's figures into `dir`.
void figures(const std::filesystem::path& dir);

}  // namespace chapter14
