// Clipping in the picture plane (see clip.hpp).
#include "clip.hpp"

#include <algorithm>
#include <cmath>

#include "sphere_math.hpp"

namespace t2::draw {

bool clip_disk(Vec2 P, Vec2 D, double t0, double t1, Vec2& a, Vec2& b) {
  const double A = dot(D, D), B = 2 * dot(P, D), C = dot(P, P) - 1;
  if (A == 0) return false;
  const double disc = B * B - 4 * A * C;
  if (disc <= 0) return false;
  const double s = std::sqrt(disc);
  const double lo = std::max(t0, (-B - s) / (2 * A)), hi = std::min(t1, (-B + s) / (2 * A));
  if (!(lo < hi)) return false;
  a = P + lo * D;
  b = P + hi * D;
  return true;
}

std::vector<Vec2> disk_polygon(double r, int n) {
  std::vector<Vec2> v;
  for (int i = 0; i < n; ++i) v.push_back({r * std::cos(2 * kPi * i / n), r * std::sin(2 * kPi * i / n)});
  return v;
}

std::vector<Vec2> clip_half(const std::vector<Vec2>& poly, double k, Vec2 n) {
  std::vector<Vec2> out;
  const std::size_t m = poly.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % m];
    const double fa = k + dot(n, a), fb = k + dot(n, b);
    if (fa >= 0) out.push_back(a);
    if ((fa >= 0) != (fb >= 0)) out.push_back(a + (fa / (fa - fb)) * (b - a));
  }
  return out;
}

std::vector<Vec2> clip_poly_disk(std::vector<Vec2> poly) {
  const int n = 180;
  for (int i = 0; i < n && !poly.empty(); ++i) {
    const double a = 2 * kPi * (i + 0.5) / n;
    const Vec2 nn{-std::cos(a), -std::sin(a)};
    poly = clip_half(poly, std::cos(kPi / n), nn);
  }
  return poly;
}

}  // namespace t2::draw
