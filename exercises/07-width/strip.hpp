#pragma once
// Exercise 07: how both test files judge an answer (part of the tests, not of your solution).
// The answer's strip is checked exactly: its first line L = P[i] × P[j] has a direction (it is
// not Ω), every point of Ω in P lies on it (the strip's ends), and every proper point p has its
// drawn signed distance L·p / w_p between 0 and that of P[k]. Its squared width
// (L·P[k] / w_k)² / (L_x² + L_y²) must equal the least over all candidate strips, by brute force:
// a narrowest strip has a side through two points of P (a hull edge), or through one point in
// the direction of P's points of Ω.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <t2/kernel/number.hpp>
#include <t2/kernel/point.hpp>

namespace ex07test {

/// A vector of Z³.
using V = std::array<t2::Integer, 3>;

/// The exact coordinates of p (a positive multiple of them).
inline V vec(const t2::Point& p) {
  const t2::ExactPoint e = t2::to_exact(p);
  return {e.w(), e.x(), e.y()};
}

/// The squared width of the strip with one line L, holding P, and its other line through the
/// farthest point; nullopt when L is not a side of a strip holding P.
inline std::optional<t2::Rational> strip(const std::vector<V>& P, const V& L, long* farthest = nullptr) {
  const t2::Integer n2 = L[1] * L[1] + L[2] * L[2];
  if (n2 == 0) return std::nullopt;
  t2::Rational far = 0;
  int side = 0;
  for (long k = 0; k < long(P.size()); ++k) {
    const V& p = P[k];
    const t2::Integer a = L[0] * p[0] + L[1] * p[1] + L[2] * p[2];
    if (p[0] == 0) {
      if (a != 0) return std::nullopt;  // a point of Ω off the strip's direction
      continue;
    }
    const t2::Rational v = t2::Rational(a) / t2::Rational(p[0]);
    const int s = sgn(v);
    if (s != 0 && side != 0 && s != side) return std::nullopt;
    if (s != 0) side = s;
    if (v * v > far) {
      far = v * v;
      if (farthest) *farthest = k;
    }
  }
  return far / t2::Rational(n2);
}

/// p × q.
inline V cross(const V& p, const V& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}

/// "" when {i, j, k} is a strip holding P of squared width `least`, else what is wrong.
inline std::string judge(const std::vector<t2::Point>& P, const std::vector<long>& got, const t2::Rational& least) {
  if (got.size() != 3) return "the answer has " + std::to_string(got.size()) + " indices, not 3";
  for (long i : got)
    if (i < 0 || i >= long(P.size())) return "index " + std::to_string(i) + " is out of range";
  std::vector<V> E;
  for (const t2::Point& p : P) E.push_back(vec(p));
  const V L = cross(E[got[0]], E[got[1]]);
  const auto w = strip(E, L);
  const std::string ijk = "p" + std::to_string(got[0]) + " p" + std::to_string(got[1]) + " p" + std::to_string(got[2]);
  if (!w) return "the line of " + ijk.substr(0, ijk.rfind(' ')) + " is not a side of a strip holding the points";
  const V& k = E[got[2]];
  if (k[0] == 0) return "the other side must pass through a proper point";
  const t2::Rational v = t2::Rational(L[0] * k[0] + L[1] * k[1] + L[2] * k[2]) / t2::Rational(k[0]);
  if (v * v / t2::Rational(L[1] * L[1] + L[2] * L[2]) != *w) return ijk + ": some point lies beyond the parallel through the third";
  if (*w != least) return ijk + " is a strip of squared width " + w->get_str() + "; a narrower one has " + least.get_str();
  return "";
}

/// "" when {i, j, k} is a narrowest strip of P (which has one), else what is wrong. The least
/// width by brute force: O(n³).
inline std::string check(const std::vector<t2::Point>& P, const std::vector<long>& got) {
  std::vector<V> E;
  for (const t2::Point& p : P) E.push_back(vec(p));
  std::optional<t2::Rational> best;
  for (std::size_t i = 0; i < E.size(); ++i)
    for (std::size_t j = 0; j < E.size(); ++j)
      if (E[i][0] != 0 && i != j)
        if (const auto w = strip(E, cross(E[i], E[j])); w && (!best || *w < *best)) best = w;
  if (!best) return "bad test input: no strip holds the points";
  return judge(P, got, *best);
}

}  // namespace ex07test
