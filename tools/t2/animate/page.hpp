#pragma once
// The page of `t2 animate`: the player (tools/t2/animate/player.html, compiled in) filled with
// the recorded steps as JSON (deflated, in base64) and one SVG frame per step. One self-contained
// HTML file.
#include <string>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/trace/step.hpp"

namespace t2cli::animate {

/// The whole HTML page: title, the steps (as JSON) and their frames. `segments`: the input
/// segments as pairs of points of P, drawn on every frame (frame.hpp).
std::string page(const std::string& title, const std::vector<t2::Point>& P, const std::vector<t2::trace::Step>& steps,
                 const std::vector<t2::trace::Edge>& segments = {});

}  // namespace t2cli::animate
