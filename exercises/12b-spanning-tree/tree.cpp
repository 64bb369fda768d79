// Exercise 12b: your solution. Replace the `throw` with your code, then run `t2 check 12b`.
#include "tree.hpp"

#include <stdexcept>

namespace ex12b {

std::vector<long> spanning_tree(const std::vector<t2::Point>& P, const std::vector<long>& E) {
  (void)P;
  (void)E;
  throw std::logic_error("spanning_tree() is not implemented yet");
}

}  // namespace ex12b
