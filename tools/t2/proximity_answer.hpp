#pragma once
// The answers of the proximity commands (t2 emst, t2 ann, t2 closest-pair, t2 sec, t2 lec):
// pairs of a scene's points, printed one 'i j' per line and drawn as segments over the input;
// circles, printed as their exact centre and the points on them.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "model_picture.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/number.hpp"
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

/// Prints a circle: a line 'W X Y' (its exact centre), a line of the indices of the points on
/// it; and writes the picture and the answer scene of `d`: the circle through P[on_circle[0]]
/// (none when it is the centre itself) and the centre, in red.
void print_circle(const AnswerDrawing& d, const t2::Scene& scene, const std::vector<t2::Point>& P,
                  const t2::ExactPoint& centre, const std::vector<std::uint32_t>& on_circle, const std::string& header);

/// The `Undefined` of a rule that names the points `site` and `other` (the same point when one
/// suffices), with their lines of the scene file: "file:line: what" or "file:line and line m:
/// what".
t2::Undefined undefined_at(const t2::Scene& scene, std::uint32_t site, std::uint32_t other, const std::string& what);

}  // namespace t2cli
