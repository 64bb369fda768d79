#pragma once
/// @file style.hpp
/// @brief How an item of a figure looks: colour, width, dash, marker, label, layer, fill.
///
/// Geometry types know nothing of colours: a `t2::draw::Figure` pairs each geometric item with
/// a `Style`. Setters return the style, so styles are written in one expression:
/// `Style().color("#d62728").width(2).label("p")`.

#include <limits>
#include <string>
#include <vector>

namespace t2::draw {

/// The mark drawn at a point. Back points are always drawn hollow, whatever the marker.
enum class Marker { dot, square, diamond, cross, none };

/// The look of one item of a figure (see the file comment).
class Style {
 public:
  /// Stroke colour as "#rrggbb" (default black).
  Style& color(std::string c) { color_ = std::move(c); return *this; }
  /// Stroke colour.
  const std::string& color() const { return color_; }

  /// Stroke width in pixels of the default 360-pixel view (default 1.6).
  Style& width(double w) { width_ = w; return *this; }
  /// Stroke width.
  double width() const { return width_; }

  /// Dash pattern (on, off, ... in pixels) for the *front* part; empty = solid. The back part of
  /// an item is always dashed (Stolfi's convention), so that print without colour shows it.
  Style& dash(std::vector<double> d) { dash_ = std::move(d); return *this; }
  /// Dash pattern.
  const std::vector<double>& dash() const { return dash_; }

  /// Marker of a point (default `Marker::dot`).
  Style& marker(Marker m) { marker_ = m; return *this; }
  /// Marker of a point.
  Marker marker() const { return marker_; }

  /// Marker radius in pixels (default 3.5).
  Style& size(double r) { size_ = r; return *this; }
  /// Marker radius.
  double size() const { return size_; }

  /// Text drawn next to the item, placed so that it does not cover the item.
  Style& label(std::string t) { label_ = std::move(t); return *this; }
  /// Label text.
  const std::string& label() const { return label_; }

  /// Direction of the label from its anchor, in degrees counter-clockwise from east. By default
  /// (NaN) the direction is chosen automatically: the first of eight directions (up-right first)
  /// where the label clears everything already drawn and the other labels.
  Style& label_angle(double deg) { label_angle_ = deg; return *this; }
  /// Direction of the label.
  double label_angle() const { return label_angle_; }

  /// A white halo around the label's glyphs (default on: readable over lines). Off, the label
  /// costs a few bytes of SVG instead of its glyphs' outlines (an animation's many frames).
  Style& halo(bool on) { halo_ = on; return *this; }
  /// Whether the label has its halo.
  bool halo() const { return halo_; }

  /// Drawing order: lower layers first (default 0); equal layers keep insertion order.
  Style& layer(int l) { layer_ = l; return *this; }
  /// Layer.
  int layer() const { return layer_; }

  /// Fill colour "#rrggbb" for polygons and shaded half-planes; empty (default) = no fill.
  Style& fill(std::string c) { fill_ = std::move(c); return *this; }
  /// Fill colour.
  const std::string& fill() const { return fill_; }

  /// Opacity of the fill in [0, 1] (default 0.25).
  Style& fill_opacity(double a) { fill_opacity_ = a; return *this; }
  /// Opacity of the fill.
  double fill_opacity() const { return fill_opacity_; }

  /// For a line: shade its positive side (the half-planes of fig. 3.11, the hemisphere of
  /// fig. 3.12) with the fill colour (light blue when no fill is set). The back half-plane is
  /// hatched rather than filled, so that print without colour tells them apart.
  Style& shade(bool on = true) { shade_ = on; return *this; }
  /// Whether the positive side is shaded.
  bool shade() const { return shade_; }

  /// Draw an arrowhead showing the orientation (end of a segment or ray, direction of a line).
  Style& arrow(bool on = true) { arrow_ = on; return *this; }
  /// Whether an arrowhead is drawn.
  bool arrow() const { return arrow_; }

 private:
  std::string color_ = "#000000";
  double width_ = 1.6;
  std::vector<double> dash_;
  Marker marker_ = Marker::dot;
  double size_ = 3.5;
  std::string label_;
  double label_angle_ = std::numeric_limits<double>::quiet_NaN();
  bool halo_ = true;
  int layer_ = 0;
  std::string fill_;
  double fill_opacity_ = 0.25;
  bool shade_ = false;
  bool arrow_ = false;
};

}  // namespace t2::draw
