#pragma once
// Label placement: every label of a picture at its own direction, or at the first direction
// where it clears the drawn geometry and the labels placed before it.
#include "canvas.hpp"

namespace t2::draw {

/// Queues the labels of styled items (`Canvas::styled`) after the label items, then places
/// every pending label as text shapes of the canvas.
void place_labels(Canvas& c);

}  // namespace t2::draw
