#pragma once
// The canvas every painter draws on: maps model units to pixels and collects the shapes of the
// display list, and the labels still to be placed (see labels.hpp).
#include <string>
#include <utility>
#include <vector>

#include "t2/draw/figure.hpp"
#include "t2/draw/render.hpp"

namespace t2::draw {

/// Which part of T² a point of weight w is on.
inline Part part_of(double w) { return w > 0 ? Part::front : (w < 0 ? Part::back : Part::infinity); }

/// The point normalized to |w| = 1 (or to max(|x|, |y|) = 1 on Ω). A proper point so far
/// away that x/w overflows a double is drawn as the point at infinity in its direction: at
/// more than 10^308 from the origin, no picture can tell them apart.
Point drawable(const Point& p);

/// Opacity of a hatched (back side) fill: hatching lines cover less than a flat fill, so they
/// are drawn stronger.
double back_opacity(const Style& st);

/// A label waiting to be placed: its anchor (pixels), text, direction (NaN: automatic), the
/// distance from the anchor and its colour.
struct Pending {
  Vec2 at;
  std::string text;
  double angle;
  double gap;
  std::string colour;
  bool halo = true;  ///< Style::halo
};

/// Maps model units (y up) to pixels (y down) and collects shapes.
struct Canvas {
  double ox = 0, oy = 0, scale = 1;  ///< pixel of the model origin, pixels per model unit
  double width = 0, height = 0;      ///< the picture, for label placement (0: unbounded)
  std::vector<Shape> shapes;         ///< the display list so far
  std::vector<Pending> pending;      ///< labels to place, in order
  /// The labels of styled items (`Style::label`), queued after all geometry is drawn.
  std::vector<std::pair<Vec2, const Style*>> styled;

  Canvas() = default;
  /// A canvas with the model origin at pixel (ox, oy) and `scale` pixels per model unit.
  Canvas(double ox, double oy, double scale) : ox(ox), oy(oy), scale(scale) {}

  /// A square canvas of `size` pixels whose middle shows the model origin and whose half-width
  /// shows `extent` model units.
  static Canvas square(int size, double extent) {
    Canvas c(size / 2.0, size / 2.0, size / 2.0 / extent);
    c.width = c.height = size;
    return c;
  }

  /// The pixel of a point in model units.
  Vec2 px(Vec2 a) const { return {ox + scale * a.x, oy - scale * a.y}; }
  /// Queues text `t` next to the pixel `at` for placement.
  void label(Vec2 at, const std::string& t, double angle, double gap, const std::string& colour, bool halo = true);
  /// Queues the label of a styled item anchored at model point `a`.
  void label_of(Vec2 a, const Style& st) { styled.push_back({px(a), &st}); }
  /// A stroked polyline (back parts dashed, whatever the style).
  Shape& path(const std::vector<Vec2>& pts, Part part, const Style& st, bool closed = false);
  /// A filled closed polygon (hatched when `hatch`).
  Shape& fill(const std::vector<Vec2>& pts, Part part, const std::string& colour, double opacity, bool hatch);
  /// A point marker (hollow and dashed on the back side).
  Shape& marker(Vec2 at, Part part, const Style& st, bool hollow);
  /// Text next to the pixel `at`, `gap` pixels away in direction `deg`.
  Shape& text(Vec2 at, const std::string& t, double deg, double gap, const std::string& colour, double size = 14);
  /// A filled arrowhead at `tip` pointing along `dir` (model units).
  void arrowhead(Vec2 tip, Vec2 dir, const Style& st, Part part, bool hollow);
};

/// Moves the picture down by `title_band` and writes the title in the band above it.
void add_title(Canvas& c, const Figure& f, double width);

}  // namespace t2::draw
