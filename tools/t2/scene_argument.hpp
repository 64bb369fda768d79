#pragma once
// The scene file named on a command line, as every command that reads one takes it.

#include <string>
#include <vector>

#include "t2/kernel/scene.hpp"

namespace t2cli {

/// Reads the scene file `file`, or standard input when it is "-" (named <stdin> in messages).
/// Throws t2::ParseError (file:line: what is wrong) or t2::BadInput when it cannot be read.
t2::Scene read_scene_argument(const std::string& file);

/// The scene's points (bare and labelled) in file order: what the indices printed by the
/// algorithm commands (hull, triangulate, ...) refer to.
std::vector<t2::Point> scene_points(const t2::Scene& s);

}  // namespace t2cli
