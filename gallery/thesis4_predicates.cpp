// Gallery: figures of chapter 4 of seed 000 (predicates). To be drawn.
#include "gallery.hpp"

namespace gallery {

std::vector<Entry> thesis4_predicates() { return {}; }

}  // namespace gallery
