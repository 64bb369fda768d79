#pragma once
/// @file scene_style.hpp
/// @brief The style attributes of the objects of a scene file: `color=red width=2 label="hull"`.
///
/// A scene object (a point line, a `label` line, a block's keyword line) may end with
/// attributes `key=value`; a `style` line gives attributes to every object after it (README,
/// section "Scene files"). Seed 003 (GeoLab, §A.4) lets the user set, per object or per group,
/// the colour and kind of stroke, a label, and whether the object's handles are shown; this
/// file keeps those that make sense in a printed figure and adds the rest of a lecture
/// figure's needs (width, fill, layer, marker). GeoLab's *removable* and *fixed* flags belong to
/// its interactive editor and have no meaning here.
///
/// The values are checked here, in the kernel (no drawing): colours are resolved to "#rrggbb"
/// through the names of `t2/kernel/scene_colors.hpp`; `t2::draw::add_scene` turns them into a
/// `t2::draw::Style`.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace t2 {

/// The kinds of scene objects an attribute may apply to.
enum class SceneKind { point, segment, polygon, line, circle };

/// The name of a kind as the file writes it ("point", "segment", ...).
std::string_view name(SceneKind k);

/// The attributes of one scene object, each unset when the file does not give it.
struct SceneStyle {
  std::optional<std::string> color;         ///< stroke (and marker) colour, "#rrggbb"
  std::optional<double> width;              ///< stroke width in pixels, in (0, 50]
  std::optional<std::vector<double>> dash;  ///< dash pattern in pixels; empty: solid
  std::optional<std::string> fill;          ///< fill colour "#rrggbb"; empty: no fill
  std::optional<double> opacity;            ///< opacity of the fill, in [0, 1]
  std::optional<std::string> marker;        ///< dot, square, diamond, cross or none
  std::optional<double> size;               ///< marker radius in pixels, in (0, 50]
  std::optional<std::string> label;         ///< text drawn next to the object; empty: none
  std::optional<double> label_angle;        ///< direction of the label, degrees in [-360, 360]
  std::optional<int> layer;                 ///< drawing order, an integer in [-100, 100]
  std::optional<bool> arrow;                ///< an arrowhead showing the orientation
  std::optional<bool> shade;                ///< shade the positive side of a line
  std::optional<bool> handles;              ///< mark the points that define the object (GeoLab)

  /// Whether no attribute is set.
  bool empty() const { return *this == SceneStyle{}; }
  /// Attribute-wise equality.
  bool operator==(const SceneStyle&) const = default;
};

/// The attribute keys, in the order of the table of lib/src/kernel/scene_style.cpp.
std::vector<std::string_view> scene_style_keys();

/// Whether attribute `key` applies to objects of kind `k` (`fill` to polygons, lines and
/// circles; `marker` to points; ...). False for an unknown key.
bool scene_style_applies(std::string_view key, SceneKind k);

/// Sets attribute `key` of `s` from the text `value` (quotes already removed). Throws
/// `t2::BadInput` with a message saying what is wrong (no `file:line:` prefix: the parser adds
/// it) for an unknown key or a bad value; `kind` (when given) must be a kind the key applies to.
void set_scene_attribute(SceneStyle& s, std::string_view key, std::string_view value,
                         std::optional<SceneKind> kind);

/// The style of an object of kind `k`: its own attributes `own` over the attributes of the
/// `style` line in force `defaults`, of which only those that apply to `k` are kept.
SceneStyle merged(const SceneStyle& defaults, const SceneStyle& own, SceneKind k);

/// The attributes of `s` as the text a scene file writes (` key=value` each, with a leading
/// space; labels quoted), so that parsing the text gives `s` back.
std::string to_attributes(const SceneStyle& s);

}  // namespace t2
