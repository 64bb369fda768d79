// Exercise 11: your solution. Replace the `throw` with your code, then run `t2 check 11`.
#include "vertex.hpp"

#include <stdexcept>

namespace ex11 {

t2::ExactPoint voronoi_vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  (void)a;
  (void)b;
  (void)c;
  throw std::logic_error("voronoi_vertex() is not implemented yet");
}

}  // namespace ex11
