#pragma once
// What `t2 triangulate` and `t2 delaunay` share: the options, the output (one triangle per line,
// `i j k` counter-clockwise, `inf` for v∞), the messages on stderr and the picture.

#include <functional>
#include <memory>
#include <span>
#include <string>

#include "command.hpp"
#include "model_picture.hpp"
#include "t2/kernel/point.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2cli {

/// The options of both commands (what the command line says, with the defaults).
struct TrianglesOptions {
  std::string file;                   ///< the scene file, - for standard input
  std::string algorithm;              ///< t2 delaunay only
  bool infinite = false;              ///< also print the infinite triangles
  AnswerDrawing drawing;              ///< --svg and --model
};

/// Builds the triangulation of the scene's points (the command's algorithm).
using TriangulationBuilder = std::function<t2::Triangulation(std::span<const t2::Point>, const TrianglesOptions&)>;

/// Declares FILE, --infinite, --svg and --model on `app` (after the command's own options) and
/// the help's footer; returns the action that reads the scene, builds, prints and draws.
Action triangles_setup(Arguments& app, std::shared_ptr<TrianglesOptions> o, const std::string& command,
                       TriangulationBuilder build);

}  // namespace t2cli
