#pragma once
// Exercise 06b: how both test files compare an answer with the expected hull (part of the tests,
// not of your solution). Repeated points (equal as points of T², whatever their scale) count as
// one: each index is replaced by the first index of its point before comparing, and the answer
// must be the expected cycle, rotated (a segment: either order).
#include <algorithm>
#include <string>
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex06btest {

/// The first index of P holding the same point of T² as P[i].
inline long first_of(const std::vector<t2::Point>& P, long i) {
  for (long k = 0; k < i; ++k)
    if (P[k] == P[i]) return k;
  return i;
}

/// "" when `got` is `want` as a cycle (up to repeated points and rotation), else what differs.
inline std::string compare(const std::vector<t2::Point>& P, std::vector<long> got, std::vector<long> want) {
  auto show = [](const std::vector<long>& v) {
    std::string s;
    for (long i : v) s += " p" + std::to_string(i);
    return s;
  };
  for (long i : got)
    if (i < 0 || i >= long(P.size())) return "index " + std::to_string(i) + " is out of range";
  for (long& i : got) i = first_of(P, i);
  for (long& i : want) i = first_of(P, i);
  const std::string msg = "got" + show(got) + ", expected" + show(want) + " (as a cycle, counter-clockwise)";
  if (got.size() != want.size()) return msg;
  if (want.empty()) return "";
  const auto at = std::find(got.begin(), got.end(), want[0]);
  if (at == got.end()) return msg;
  std::rotate(got.begin(), at, got.end());
  if (got == want) return "";
  if (want.size() == 2 && got[0] == want[1] && got[1] == want[0]) return "";
  return msg;
}

}  // namespace ex06btest
