#pragma once
// Exercise 07b: how both test files judge an answer (part of the tests, not of your solution).
// Every pair's squared distance is a key (class, value) compared lexicographically, in exact
// rationals from the drawn positions: class 0, |A − B|² for two points of one side (and 0 for
// two equal points of Ω); class 1 for a proper point and a point of Ω (+∞); class 2, −|A − B|²
// for a front and a back point (beyond infinity: nearer as drawn is farther). The answer must
// reach the largest key over all pairs, found by brute force.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

namespace ex07btest {

/// A point with its drawn position in rationals (when it is proper).
struct Drawn {
  t2::Point p;        ///< the point
  t2::Rational x, y;  ///< x/w and y/w (0 on Ω)
};

/// The drawn positions of P.
inline std::vector<Drawn> drawn(const std::vector<t2::Point>& P) {
  std::vector<Drawn> D;
  for (const t2::Point& p : P) {
    D.push_back({p, 0, 0});
    if (p.w() != 0) {
      D.back().x = t2::to_rational(p.x()) / t2::to_rational(p.w());
      D.back().y = t2::to_rational(p.y()) / t2::to_rational(p.w());
    }
  }
  return D;
}

/// The key of the squared distance of a and b; nullopt for two different points of Ω.
inline std::optional<std::pair<int, t2::Rational>> key(const Drawn& a, const Drawn& b) {
  const t2::Point &p = a.p, &q = b.p;
  if (p.w() == 0 && q.w() == 0) {
    if (p == q) return std::pair<int, t2::Rational>{0, 0};
    return std::nullopt;
  }
  if (p.w() == 0 || q.w() == 0) return std::pair<int, t2::Rational>{1, 0};
  const t2::Rational dx = a.x - b.x, dy = a.y - b.y;
  const t2::Rational d = dx * dx + dy * dy;
  if ((p.w() > 0) == (q.w() > 0)) return std::pair<int, t2::Rational>{0, d};
  return std::pair<int, t2::Rational>{2, -d};
}

/// "" when `got` is a farthest pair of P (P with at most one point of Ω, up to repeats), else
/// what is wrong.
inline std::string check(const std::vector<t2::Point>& P, const std::vector<long>& got) {
  if (got.size() != 2) return "the answer has " + std::to_string(got.size()) + " indices, not 2";
  for (long i : got)
    if (i < 0 || i >= long(P.size())) return "index " + std::to_string(i) + " is out of range";
  const std::vector<Drawn> D = drawn(P);
  std::pair<int, t2::Rational> best{0, 0};
  std::pair<long, long> at{0, 0};
  for (long i = 0; i < long(P.size()); ++i)
    for (long j = i + 1; j < long(P.size()); ++j)
      if (const auto k = key(D[i], D[j]); k && *k > best) best = *k, at = {i, j};
  const auto k = key(D[got[0]], D[got[1]]);
  if (k && *k == best && (got[0] != got[1] || best == std::pair<int, t2::Rational>{0, 0})) return "";
  return "p" + std::to_string(got[0]) + " p" + std::to_string(got[1]) + " is not a farthest pair; p" +
         std::to_string(at.first) + " p" + std::to_string(at.second) + " is farther";
}

}  // namespace ex07btest
