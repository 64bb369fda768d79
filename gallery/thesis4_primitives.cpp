// Gallery: figures of chapter 4 of seed 000 (primitives). To be drawn.
#include "gallery.hpp"

namespace gallery {

std::vector<Entry> thesis4_primitives() { return {}; }

}  // namespace gallery
