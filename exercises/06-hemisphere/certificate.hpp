#pragma once
// Exercise 06: the exact certificates both test files check an answer with (part of the tests,
// not of your solution). By Gordan's theorem exactly one of the two exists: a line L with
// L·p > 0 for every p (an open hemisphere), or a combination Σ λᵢ pᵢ = 0 with λᵢ ≥ 0 not all
// zero. Each is checked in big integers, so an answer that passes is proven right.
#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

#include "hemisphere.hpp"

namespace ex06test {

/// A vector of Z³ (the coordinates [w, x, y] of a point, or of a line).
using V = std::array<t2::Integer, 3>;

/// The exact coordinates of p (a positive multiple of them: the same point).
inline V vec(const t2::Point& p) {
  const t2::ExactPoint e = t2::to_exact(p);
  return {e.w(), e.x(), e.y()};
}
/// p × q.
inline V cross(const V& p, const V& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
/// p · q.
inline t2::Integer dot(const V& p, const V& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
/// p = 0.
inline bool zero(const V& p) { return p[0] == 0 && p[1] == 0 && p[2] == 0; }

/// "" when L·p > 0 for every p of P, else what is wrong.
inline std::string check_hemisphere(const std::vector<t2::Point>& P, const t2::ExactPoint& L) {
  const V l{L.w(), L.x(), L.y()};
  for (std::size_t i = 0; i < P.size(); ++i)
    if (dot(l, vec(P[i])) <= 0)
      return "p" + std::to_string(i) + " = " + t2::to_string(P[i]) + " is not on the positive side of the line " +
             t2::to_string(L);
  return "";
}

/// True when the vectors S are a *minimal* positive dependence: rank |S| − 1 and the one
/// combination that vanishes has all its coefficients of one sign, none zero.
inline bool minimal_dependence(const std::vector<V>& S) {
  if (S.size() == 2) return zero(cross(S[0], S[1])) && dot(S[0], S[1]) < 0;
  if (S.size() == 3) {
    const V a = cross(S[1], S[2]), b = cross(S[2], S[0]), c = cross(S[0], S[1]);
    if (dot(S[0], a) != 0) return false;  // not coplanar: independent
    const V n = !zero(a) ? a : (!zero(b) ? b : c);
    if (zero(n)) return false;  // rank 1
    const t2::Integer l0 = dot(n, a), l1 = dot(n, b), l2 = dot(n, c);  // l0 S0 + l1 S1 + l2 S2 = 0
    return (l0 > 0 && l1 > 0 && l2 > 0) || (l0 < 0 && l1 < 0 && l2 < 0);
  }
  auto det = [&](int i, int j, int k) { return dot(S[i], cross(S[j], S[k])); };
  const t2::Integer l[4] = {det(1, 2, 3), -det(0, 2, 3), det(0, 1, 3), -det(0, 1, 2)};  // Σ l_i S_i = 0
  return std::all_of(l, l + 4, [](const t2::Integer& v) { return v > 0; }) ||
         std::all_of(l, l + 4, [](const t2::Integer& v) { return v < 0; });
}

/// "" when the indices W name 2 to 4 different points of P with a vanishing non-negative
/// combination, else what is wrong. (Some subset is then a minimal one: every subset is tried.)
inline std::string check_witness(const std::vector<t2::Point>& P, const std::vector<long>& W) {
  if (W.size() < 2 || W.size() > 4) return "a witness has 2, 3 or 4 points, not " + std::to_string(W.size());
  if (std::set<long>(W.begin(), W.end()).size() != W.size()) return "the witness repeats an index";
  for (long i : W)
    if (i < 0 || i >= long(P.size())) return "the witness index " + std::to_string(i) + " is out of range";
  for (unsigned mask = 1; mask < (1u << W.size()); ++mask) {
    std::vector<V> S;
    for (std::size_t k = 0; k < W.size(); ++k)
      if (mask & (1u << k)) S.push_back(vec(P[W[k]]));
    if (S.size() >= 2 && minimal_dependence(S)) return "";
  }
  std::string s = "no non-negative combination of";
  for (long i : W) s += " p" + std::to_string(i);
  return s + " vanishes: they lie in an open hemisphere";
}

/// What the test expects: a hemisphere, none, or whichever is true (both answers are checked).
enum class Expect { hemisphere, none, either };

/// Calls both functions on P and checks their answers against each other and exactly; "" when
/// right, else what is wrong.
inline std::string judge(const std::vector<t2::Point>& P, Expect e) {
  std::string h;
  bool has = false;
  try {
    h = check_hemisphere(P, ex06::hemisphere(P));
    has = true;
  } catch (const t2::Undefined&) {
  }
  if (!h.empty()) return "hemisphere(): " + h;
  const std::vector<long> W = ex06::witness(P);
  if (has && !W.empty()) return "hemisphere() found a hemisphere, yet witness() returned points";
  if (has && e == Expect::none) return "hemisphere() returned a line although no open hemisphere holds the points";
  if (!has && e == Expect::hemisphere) return "hemisphere() threw t2::Undefined, but an open hemisphere holds the points";
  if (!has && W.empty()) return "hemisphere() threw t2::Undefined, yet witness() found no witness";
  if (!has) {
    const std::string w = check_witness(P, W);
    if (!w.empty()) return "witness(): " + w;
  }
  return "";
}

}  // namespace ex06test
