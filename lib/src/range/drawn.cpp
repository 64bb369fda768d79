// The points of T² as the range structures store them (range/drawn.hpp).
#include "t2/range/drawn.hpp"

#include <limits>
#include <stdexcept>

namespace t2 {
namespace {

std::size_t slot(int sx, int sy) { return static_cast<std::size_t>((sx + 1) * 3 + (sy + 1)); }

// The slots of the box's part of Ω (bbox.hpp): the vertex b if only Δx is infinite, d if only
// Δy is, and b, d and the open quarter between them if both are. At most three; `n` of them.
int omega_slots(const ExactBBox& b, std::size_t (&out)[3]) {
  const bool ix = is_infinite(b.dx()), iy = is_infinite(b.dy());
  int n = 0;
  if (!ix && !iy) return 0;
  const int sx = sign_of(b.vertex(1).x()), sy = sign_of(b.vertex(3).y());
  if (ix) out[n++] = slot(sx, 0);
  if (iy) out[n++] = slot(0, sy);
  if (ix && iy) out[n++] = slot(sx, sy);
  return n;
}

}  // namespace

void OmegaPoints::add(const Point& p, std::uint32_t index) {
  slot_[slot(sign_of(p.x()), sign_of(p.y()))].push_back(index);
}

std::size_t OmegaPoints::count(const ExactBBox& b) const {
  std::size_t s[3], n = 0;
  for (int k = 0, m = omega_slots(b, s); k < m; ++k) n += slot_[s[k]].size();
  return n;
}

void OmegaPoints::report(const ExactBBox& b, std::vector<std::size_t>& out) const {
  std::size_t s[3];
  for (int k = 0, m = omega_slots(b, s); k < m; ++k) out.insert(out.end(), slot_[s[k]].begin(), slot_[s[k]].end());
}

Sides split_sides(std::span<const Point> points) {
  if (points.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("range search: more points than 32-bit indices hold");
  Sides out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    const auto k = static_cast<std::uint32_t>(i);
    if (p.w() == 0)
      out.omega.add(p, k);
    else if (p.w() > 0)
      out.side[0].push_back({p.w(), p.x(), p.y(), k});
    else
      out.side[1].push_back({-p.w(), -p.x(), -p.y(), k});
  }
  return out;
}

}  // namespace t2
