#pragma once
// The beach line of Fortune's sweep (t2/voronoi/fortune.hpp): arcs left to right in a treap
// whose order is the position (no keys: an arc is inserted next to a known arc), with the arcs
// also linked as a list. Private to lib/src/voronoi.

#include <cstdint>
#include <deque>

namespace t2::detail {

/// One arc of the beach line.
struct Arc {
  int site;                 ///< the site (index into the sweep's sorted sites)
  std::uint32_t priority;   ///< the treap's heap key
  Arc* prev = nullptr;      ///< the arc on the left
  Arc* next = nullptr;      ///< the arc on the right
  Arc* left = nullptr;      ///< tree: left child
  Arc* right = nullptr;     ///< tree: right child
  Arc* up = nullptr;        ///< tree: parent
  int event = -1;           ///< its pending circle event, or -1
  int edge = -1;            ///< the edge traced by the breakpoint (prev, this)
  int end = 0;              ///< which end of that edge the breakpoint reaches
};

/// Arcs in position order: insert next to an arc, erase, and the root for a search.
class BeachLine {
 public:
  Arc* root = nullptr;  ///< the root of the treap

  /// A new arc of `site`, not yet in the line.
  Arc* make(int site) {
    seed_ = seed_ * 6364136223846793005ULL + 1442695040888963407ULL;
    const Arc a{site, std::uint32_t(seed_ >> 33)};
    if (free_) {  // an erased arc's place (the line holds O(√n) arcs on uniform input, not 2n)
      Arc* n = free_;
      free_ = n->next;
      *n = a;
      return n;
    }
    arcs_.push_back(a);
    return &arcs_.back();
  }
  /// Puts `n` first (the line is empty).
  void start(Arc* n) { root = n; }
  /// Puts `n` just right of `x`.
  void insert_after(Arc* x, Arc* n) {
    n->prev = x, n->next = x->next;
    if (x->next) x->next->prev = n;
    x->next = n;
    if (!x->right) {
      x->right = n, n->up = x;
    } else {
      Arc* y = x->right;
      while (y->left) y = y->left;
      y->left = n, n->up = y;
    }
    while (n->up && n->up->priority < n->priority) rotate(n);
  }
  /// Takes `n` out of the line.
  void erase(Arc* n) {
    while (n->left || n->right) {
      Arc* c = !n->left ? n->right : !n->right ? n->left : (n->left->priority > n->right->priority ? n->left : n->right);
      rotate(c);
    }
    if (!n->up) root = nullptr;
    else if (n->up->left == n) n->up->left = nullptr;
    else n->up->right = nullptr;
    if (n->prev) n->prev->next = n->next;
    if (n->next) n->next->prev = n->prev;
    n->next = free_, free_ = n;  // reused by `make`: nothing points to an erased arc
  }

 private:
  /// Lifts n above its parent.
  void rotate(Arc* n) {
    Arc* p = n->up;
    Arc* g = p->up;
    if (n == p->left) {
      p->left = n->right;
      if (n->right) n->right->up = p;
      n->right = p;
    } else {
      p->right = n->left;
      if (n->left) n->left->up = p;
      n->left = p;
    }
    p->up = n, n->up = g;
    if (!g) root = n;
    else if (g->left == p) g->left = n;
    else g->right = n;
  }
  std::deque<Arc> arcs_;             // stable addresses
  Arc* free_ = nullptr;              // erased arcs, linked by `next`
  std::uint64_t seed_ = 0x9e3779b97f4a7c15ULL;
};

}  // namespace t2::detail
