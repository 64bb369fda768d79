#pragma once
/// @file union_find.hpp
/// @brief Disjoint sets of the indices 0 … n−1 with union by size and path halving: the forest
/// of Kruskal's algorithm (seed 000, Algorithm 12). m operations on n elements take
/// O(m α(n)) time (Tarjan).

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace t2 {

/// Disjoint sets of 0 … n−1 (see the file comment).
class UnionFind {
 public:
  using Index = std::uint32_t;  ///< an element
  /// n singletons.
  explicit UnionFind(std::size_t n) : parent_(n), size_(n, 1), sets_(n) {
    std::iota(parent_.begin(), parent_.end(), Index(0));
  }
  /// The representative of x's set (path halving).
  Index find(Index x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  /// The representative of x's set, read only (no halving): what a trace reads (hook.hpp).
  Index root(Index x) const {
    while (parent_[x] != x) x = parent_[x];
    return x;
  }
  /// The number of elements.
  std::size_t size() const { return parent_.size(); }
  /// Merges the sets of a and b; false when they were one set already.
  bool join(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    --sets_;
    return true;
  }
  /// The number of sets.
  std::size_t sets() const { return sets_; }

 private:
  std::vector<Index> parent_;
  std::vector<Index> size_;
  std::size_t sets_;
};

}  // namespace t2
