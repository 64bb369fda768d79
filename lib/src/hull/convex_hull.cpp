// The hull algorithms with the library's own traits and no trace, compiled once here: the
// headers declare these instantiations `extern template` (convex_hull.hpp, merge.hpp,
// monotone.hpp, layers.hpp, calipers.hpp, diameter.hpp), so a program that calls
// `t2::convex_hull(P)` links this code instead of compiling it again (issue 23, CI time).
// Any other traits or trace is instantiated where it is used, as before.
#include "t2/hull/calipers.hpp"
#include "t2/hull/convex_hull.hpp"
#include "t2/hull/diameter.hpp"
#include "t2/hull/layers.hpp"
#include "t2/hull/merge.hpp"
#include "t2/hull/monotone.hpp"

namespace t2 {

template std::vector<std::size_t> convex_hull<HullTraits, NoTrace>(std::span<const Point>, HullAlgorithm, NoTrace&&);
template std::vector<std::size_t> convex_hull<HullTraits, NoTrace>(const std::vector<Point>&, HullAlgorithm,
                                                                   NoTrace&&);
template std::vector<std::size_t> merge_hull<HullTraits, NoTrace>(std::span<const Point>, NoTrace&&);
template std::vector<std::size_t> merge_hull<HullTraits, NoTrace&>(std::span<const Point>, NoTrace&);
template Chart chart_for<HullTraits>(std::span<const Point>, std::vector<std::size_t>&);
template std::vector<std::size_t> monotone_chain<HullTraits, NoTrace>(std::span<const Point>, std::vector<std::size_t>,
                                                                      const Chart&, NoTrace&&);
template std::vector<std::size_t> monotone_chain<HullTraits, NoTrace&>(std::span<const Point>,
                                                                       std::vector<std::size_t>, const Chart&, NoTrace&);
template std::vector<std::vector<std::size_t>> convex_layers<HullTraits>(std::span<const Point>, LayersMethod);
template std::optional<Width> width<HullTraits>(std::span<const Point>);
template std::optional<std::pair<std::size_t, std::size_t>> diameter<HullTraits>(std::span<const Point>);

}  // namespace t2
