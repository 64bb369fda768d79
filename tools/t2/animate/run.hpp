#pragma once
// What `t2 animate` does, for the command and for `t2 book build` (which writes the chapters'
// animations beside the book): run an algorithm with its recorder (its entry in
// algorithms/registry.hpp), then write the page.
#include <filesystem>
#include <string>

#include "t2/kernel/scene.hpp"

namespace t2cli::animate {

/// Runs ALGO on the points of `scene` (at most 200), or on its segments for an algorithm of
/// segments (at most 100: 200 endpoints), records every step and writes the page `out`
/// atomically. Returns "OUT: N steps (M at the lecture level)". Throws t2::BadInput (too
/// many points, a triangulation of points off the front side), t2::Undefined (no hull), both
/// naming the scene, and std::invalid_argument for an ALGO that is not registered with a recorder.
std::string write_animation(const std::string& algo, const t2::Scene& scene, const std::filesystem::path& out);

}  // namespace t2cli::animate
