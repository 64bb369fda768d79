// Exercise 11b: your solution. Replace the `throw`s with your code, then run `t2 check 11b`.
#include "dual.hpp"

#include <stdexcept>

namespace ex11b {

std::vector<t2::ExactPoint> voronoi_vertices(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  (void)P;
  (void)F;
  throw std::logic_error("voronoi_vertices() is not implemented yet");
}

std::vector<long> voronoi_edges(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  (void)P;
  (void)F;
  throw std::logic_error("voronoi_edges() is not implemented yet");
}

}  // namespace ex11b
