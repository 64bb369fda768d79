// The one dispatch from items to models (see painter.hpp).
#include "painter.hpp"

#include <algorithm>

#include "canvas.hpp"
#include "labels.hpp"

namespace t2::draw {

void paint(const Figure& f, Painter& p) {
  std::vector<const Item*> items;
  for (const auto& it : f.items()) items.push_back(&it);
  std::stable_sort(items.begin(), items.end(),
                   [](const Item* a, const Item* b) { return a->style.layer() < b->style.layer(); });
  for (const Item* it : items) {
    const Style& st = it->style;
    switch (it->kind) {
      case ItemKind::point: p.point(it->points[0], st); break;
      case ItemKind::line: p.line(it->line, st); break;
      case ItemKind::segment: p.segment(it->points[0], it->points[1], st); break;
      case ItemKind::polygon: p.chain(it->points, st, true); break;
      case ItemKind::polyline: p.chain(it->points, st, false); break;
      case ItemKind::circle: p.circle(it->points, st); break;
      case ItemKind::label: p.label(it->points[0], it->text, st); break;
      case ItemKind::t1: p.t1(it->t1w, it->t1x, st); break;
    }
  }
}

std::vector<Shape> display(const Figure& f, Painter& p, Canvas& c, bool titled) {
  paint(f, p);
  place_labels(c);
  if (titled) add_title(c, f, c.width);
  return std::move(c.shapes);
}

}  // namespace t2::draw
