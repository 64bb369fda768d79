// Wrong on purpose: throws t2::Undefined for every input, the answer of a student who read
// only the "undefined" cases. It must score 0: every test that expects Undefined also checks
// an input where it must not be thrown.
#include "vertex.hpp"

#include <t2/kernel/error.hpp>

namespace ex11 {

t2::ExactPoint voronoi_vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  (void)a;
  (void)b;
  (void)c;
  throw t2::Undefined("voronoi_vertex(): undefined, whatever the input");
}

}  // namespace ex11
