// The Delaunay triangulations with the library's own predicates (DelaunayTraits), compiled once
// here: delaunay.hpp and divide.hpp declare these instantiations `extern template`, so a program
// that calls `t2::delaunay(P)` links this code instead of compiling it again (issue 23, CI
// time). Any other traits (a recorder, a benchmark's raw predicates) is instantiated where it
// is used, as before.
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/divide.hpp"

namespace t2 {

template Triangulation delaunay_with<DelaunayTraits, NoTrace>(std::span<const Point>, DelaunayTraits, NoTrace&&);
template Triangulation delaunay_with<DelaunayTraits>(std::vector<Point>&&, DelaunayTraits);
template Triangulation delaunay_divide_with<DelaunayTraits>(std::span<const Point>, DelaunayTraits);

}  // namespace t2
