#pragma once
/// @file scene_figure.hpp
/// @brief The figure of a scene file: every block of a `t2::Scene` as an item of a `Figure`.
///
/// One conversion for every program that draws scenes (`t2 draw`, the gallery): each kind of
/// block has its default style in `SceneStyles`, each object its attributes (scene_style.hpp), and `add_scene` adds the blocks kind by kind —
/// polygons, circles, lines, segments, then points with their labels — so that within a layer
/// points are drawn over segments, segments over lines, lines over circles and polygons.

#include <string>

#include "t2/draw/figure.hpp"
#include "t2/draw/palette.hpp"
#include "t2/kernel/scene.hpp"

namespace t2::draw {

/// The style of each kind of scene block. By default, the look of `t2 draw`: black points over
/// blue segments (layer 1) over green filled polygons, grey oriented lines and red circles.
struct SceneStyles {
  /// Points (their label is the scene's, whatever this style says).
  Style point = Style().color(palette::black).layer(2);
  /// Segments.
  Style segment = Style().color(palette::blue).width(2).layer(1);
  /// Polygons (filled with `Style::fill`).
  Style polygon = Style().color(palette::green).width(2).fill(palette::green);
  /// Lines (the arrow shows the orientation).
  Style line = Style().color(palette::grey).width(1.5).arrow();
  /// Circles.
  Style circle = Style().color(palette::red).width(2);

  /// Every kind in one colour, in layer 0 (so that items added later are drawn over them).
  static SceneStyles in(const std::string& colour);
};

/// `base` with the attributes `a` of a scene object set over it. A colour given without a fill
/// recolours the fill too when `base` has one (a `polygon color=red` is filled red).
Style styled(Style base, const SceneStyle& a);

/// Adds the blocks of scene s to f, in the styles `styles` (see the file comment), each with
/// its own attributes over them (`styled`); `handles=yes` adds a small square at each point
/// that defines the object. Throws
/// `t2::ParseError` (`file:line: ...`) for a circle that cannot be drawn (its centre or radius
/// beyond the range of double).
void add_scene(Figure& f, const Scene& s, const SceneStyles& styles = {});

/// The figure of scene s (`add_scene` to an empty figure).
Figure figure_of(const Scene& s, const SceneStyles& styles = {});

}  // namespace t2::draw
