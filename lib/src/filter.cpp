#include "t2/filter.hpp"

namespace t2 {

FilterStats& filter_stats() {
  static FilterStats stats;
  return stats;
}

}  // namespace t2
