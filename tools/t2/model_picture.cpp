#include "model_picture.hpp"

#include <algorithm>
#include <cmath>

namespace t2cli {

std::string render_models(const t2::draw::Figure& f, const std::vector<t2::Point>& points, const std::string& model) {
  namespace dr = t2::draw;
  double r = 0;  // the planar view holds every finite point
  for (const auto& p : points)
    if (p.w() != 0 && std::isfinite(std::hypot(p.x() / p.w(), p.y() / p.w())))
      r = std::max(r, std::hypot(p.x() / p.w(), p.y() / p.w()));
  dr::PlaneView plane;
  plane.half_width = std::max(1.0, 1.2 * r);
  const dr::SphereView sphere;
  if (model == "plane") return dr::render(f, plane);
  if (model == "sphere") return dr::render(f, sphere);
  return dr::render_both(f, plane, sphere);
}

}  // namespace t2cli
