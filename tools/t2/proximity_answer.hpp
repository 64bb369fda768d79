#pragma once
// The answers of the proximity commands (t2 emst, t2 ann, t2 closest-pair, t2 sec): pairs of a
// scene's points, printed one 'i j' per line and drawn as segments over the input.
#include <string>
#include <utility>
#include <vector>

#include "model_picture.hpp"
#include "t2/kernel/scene.hpp"

namespace t2cli {

/// The arguments of a proximity command: FILE and --svg, --model, --scene.
struct ProximityOptions {
  std::string file;       ///< the scene file, - for standard input
  AnswerDrawing drawing;  ///< --svg, --model and --scene
};

/// Prints the pairs, one 'i j' per line, and writes the picture and the answer scene of `d`:
/// each pair a red segment (none between equal or antipodal points, which have no segment).
void print_pairs(const AnswerDrawing& d, const t2::Scene& scene, const std::vector<t2::Point>& P,
                 const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs, const std::string& header);

}  // namespace t2cli
