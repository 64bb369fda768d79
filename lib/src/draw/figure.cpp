// Figures: the list of styled items (see t2/draw/figure.hpp).
#include "t2/draw/figure.hpp"

namespace t2::draw {

Figure& Figure::push(ItemKind k, std::vector<Point> pts, Style s) {
  const std::size_t n = pts.size();
  const bool chain = k == ItemKind::segment || k == ItemKind::polygon || k == ItemKind::polyline;
  if (chain) {
    for (std::size_t i = 0; i + 1 < n || (k == ItemKind::polygon && n > 2 && i < n); ++i) {
      const Point& a = pts[i];
      const Point& b = pts[(i + 1) % n];
      if (a == antipode(b)) throw Undefined("segment(p, q) is undefined when q = antipode(p)");
    }
  }
  Item it;
  it.kind = k;
  it.points = std::move(pts);
  it.style = std::move(s);
  items_.push_back(std::move(it));
  return *this;
}

}  // namespace t2::draw
