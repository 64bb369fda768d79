#pragma once
// The difference between two consecutive frames of `t2 animate` (page.hpp): a shortest edit
// script (Myers, "An O(ND) difference algorithm and its variations", 1986), so that the page
// stores each step as what changed since the step before. A step changes a few triangles, a
// few highlights and one overlay; the frames share everything else.
//
// The script is a flat list of groups `copy, skip, count, e₁ … e_count`: copy `copy` elements
// of the old sequence, skip `skip` of them, insert the `count` elements that follow; what is
// left of the old sequence after the last group is copied. player.html's `patch` reads it.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <optional>
#include <vector>

namespace t2cli::animate {

/// One group of an edit script: copy, skip, then insert b[from, from + count).
struct EditGroup {
  std::size_t copy = 0;   ///< elements of the old sequence kept
  std::size_t skip = 0;   ///< elements of the old sequence dropped after them
  std::size_t from = 0;   ///< the first inserted element, an index into the new sequence
  std::size_t count = 0;  ///< how many are inserted
};

/// The shortest edit script from a to b as groups (the file comment), or nothing when more than
/// `max_d` insertions and deletions are needed (then the caller stores b whole).
template <class T>
std::optional<std::vector<EditGroup>> edit_script(const std::vector<T>& a, const std::vector<T>& b,
                                                  std::size_t max_d) {
  const long n = static_cast<long>(a.size()), m = static_cast<long>(b.size());
  const long dmax = std::min<long>(static_cast<long>(max_d), n + m);
  const long off = dmax + 1;
  std::vector<long> v(static_cast<std::size_t>(2 * dmax + 3), 0);
  std::vector<std::vector<long>> trace;  // v after each d, for the way back
  long found = -1;
  for (long d = 0; d <= dmax && found < 0; ++d) {
    for (long k = -d; k <= d; k += 2) {
      const bool down = k == -d || (k != d && v[off + k - 1] < v[off + k + 1]);
      long x = down ? v[off + k + 1] : v[off + k - 1] + 1, y = x - k;
      while (x < n && y < m && a[x] == b[y]) ++x, ++y;
      v[off + k] = x;
      if (x >= n && y >= m) {
        found = d;
        break;
      }
    }
    trace.push_back(v);
  }
  if (found < 0) return std::nullopt;
  // Back from (n, m): each d is a snake of equal elements after one insertion or deletion.
  enum Op { keep, drop, put };
  std::vector<std::pair<Op, long>> ops;  // reversed; put holds the index into b
  long x = n, y = m;
  for (long d = found; d > 0; --d) {
    const std::vector<long>& w = trace[static_cast<std::size_t>(d - 1)];
    const long k = x - y;
    const bool down = k == -d || (k != d && w[off + k - 1] < w[off + k + 1]);
    const long pk = down ? k + 1 : k - 1, px = w[off + pk], py = px - pk;
    const long mx = down ? px : px + 1, my = down ? py + 1 : py;
    for (; x > mx && y > my; --x, --y) ops.emplace_back(keep, 0);
    ops.emplace_back(down ? put : drop, down ? py : px);
    x = px, y = py;
  }
  for (; x > 0 && y > 0; --x, --y) ops.emplace_back(keep, 0);
  std::vector<EditGroup> out;
  EditGroup g;
  bool open = false;  // g has a skip or an insertion: a keep after it starts a new group
  for (auto it = ops.rbegin(); it != ops.rend(); ++it) {
    if (it->first == keep) {
      if (open) out.push_back(g), g = EditGroup{}, open = false;
      ++g.copy;
    } else if (it->first == drop) {
      if (g.count > 0) out.push_back(g), g = EditGroup{};
      ++g.skip, open = true;
    } else {
      if (g.count == 0) g.from = static_cast<std::size_t>(it->second);
      ++g.count, open = true;
    }
  }
  if (open) out.push_back(g);
  return out;
}

}  // namespace t2cli::animate
