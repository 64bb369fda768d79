// Great arcs and hemispheres of the unit sphere (see sphere_math.hpp).
#include "sphere_math.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "t2/draw/view.hpp"

namespace t2::draw {

std::vector<Vec3> slerp_samples(const Vec3& a, const Vec3& b) {
  const double ang = std::atan2(std::sqrt(dot(cross(a, b), cross(a, b))), dot(a, b));
  const int n = std::max(1, static_cast<int>(std::ceil(ang / (1.5 * kPi / 180))));
  std::vector<Vec3> out{a};
  if (ang == 0) {
    out.push_back(b);
    return out;
  }
  // Orthonormal frame of the arc's plane: a and the unit vector towards b perpendicular to a.
  const Vec3 perp = unit(b + -dot(a, b) * a);
  for (int i = 1; i < n; ++i) {
    const double t = ang * i / n;
    out.push_back(std::cos(t) * a + std::sin(t) * perp);
  }
  out.push_back(b);
  return out;
}

std::vector<Vec3> dense_loop(const std::vector<Point>& pts) {
  std::vector<Vec3> dense;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i) {
    auto s = slerp_samples(on_sphere(pts[i]), on_sphere(pts[(i + 1) % n]));
    dense.insert(dense.end(), s.begin(), s.end() - 1);
  }
  return dense;
}

Vec3 crossing(const Vec3& a, const Vec3& b, const Vec3& axis) {
  const double da = std::fabs(dot(a, axis)), db = std::fabs(dot(b, axis));
  return unit(db * a + da * b);
}

std::vector<Vec3> clip_to_hemisphere(const std::vector<Vec3>& loop, const Vec3& axis) {
  std::vector<Vec3> out;
  const std::size_t n = loop.size();
  std::size_t start = n;
  for (std::size_t i = 0; i < n && start == n; ++i)
    if (dot(loop[i], axis) > 0) start = i;
  if (start == n) return out;
  std::optional<Vec3> exit;  // set while the loop is on the other side
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 &a = loop[(start + k) % n], &b = loop[(start + k + 1) % n];
    const bool in_a = dot(a, axis) >= 0, in_b = dot(b, axis) >= 0;
    if (in_a) out.push_back(a);
    if (in_a && !in_b) exit = crossing(a, b, axis);
    if (!in_a && in_b) {
      const Vec3 entry = crossing(a, b, axis);
      const auto arc = slerp_samples(*exit, entry);  // along the great circle ⟂ axis
      out.insert(out.end(), arc.begin(), arc.end());
      exit.reset();
    }
  }
  return out;
}

Vec3 arc_middle(const Point& p, const Point& q) { return unit(on_sphere(p) + on_sphere(q)); }

std::vector<Vec3> great_circle(const Line& l) {
  const Vec3 n = unit({l.X(), l.Y(), l.W()});
  const Vec3 t = std::fabs(n.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  const Vec3 b1 = unit(cross(n, t)), b2 = cross(n, b1);
  std::vector<Vec3> out;
  const int N = 480;
  for (int i = 0; i < N; ++i) {
    const double a = 2 * kPi * i / N;
    out.push_back(std::cos(a) * b1 + std::sin(a) * b2);
  }
  return out;
}

}  // namespace t2::draw
