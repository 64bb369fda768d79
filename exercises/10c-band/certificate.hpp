#pragma once
// Exercise 10c: how both test files compare an answer of band with the faces the test knows
// (part of the tests, not of your solution): as sets of faces, each face rotated to start at its
// smallest index, so that the order of the faces and the rotation of each are free, but not the
// turn of a face: (a2, a1, b) and (a1, a2, b) are different faces.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace ex10ctest {

using Tri = std::array<long, 3>;

/// The faces of a flat list, each rotated to start at its smallest index, sorted.
inline std::vector<Tri> canonical(const std::vector<long>& T) {
  std::vector<Tri> r;
  for (std::size_t k = 0; k + 2 < T.size(); k += 3) {
    Tri t = {T[k], T[k + 1], T[k + 2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    r.push_back(t);
  }
  std::sort(r.begin(), r.end());
  return r;
}

inline std::string name(const Tri& t) {
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

/// "" when `out` (the answer for n sites) has the faces of `want`, else what is wrong.
inline std::string check(long n, const std::vector<long>& out, const std::vector<long>& want) {
  if (out.size() % 3 != 0) return "the answer's length is not a multiple of 3";
  for (long v : out)
    if (v < 0 || v >= n) return "a site index out of range: " + std::to_string(v);
  const std::vector<Tri> got = canonical(out), w = canonical(want);
  for (std::size_t k = 1; k < got.size(); ++k)
    if (got[k] == got[k - 1]) return "the face " + name(got[k]) + " is there twice";
  for (const Tri& t : w)
    if (!std::binary_search(got.begin(), got.end(), t)) return "the face " + name(t) + " is missing";
  for (const Tri& t : got)
    if (!std::binary_search(w.begin(), w.end(), t)) return "the face " + name(t) + " should not be there";
  return "";
}

}  // namespace ex10ctest
