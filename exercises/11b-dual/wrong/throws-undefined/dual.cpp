// Wrong on purpose: throws t2::Undefined for every input. It must score 0: every input of the
// exercise has a diagram.
#include "dual.hpp"

#include <t2/kernel/error.hpp>

namespace ex11b {

std::vector<t2::ExactPoint> voronoi_vertices(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  (void)P;
  (void)F;
  throw t2::Undefined("voronoi_vertices(): undefined, whatever the input");
}

std::vector<long> voronoi_edges(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  (void)P;
  (void)F;
  throw t2::Undefined("voronoi_edges(): undefined, whatever the input");
}

}  // namespace ex11b
