#pragma once
/// @file palette.hpp
/// @brief The colours of the figures: one palette for items, one for the models' own marks and
/// a few marks of particular figures.
///
/// Scene files name the item colours by the names below (`color=dark_grey`, see `named`).
///
/// Item colours are the ten "category" colours of matplotlib and d3 (distinct in colour, and
/// of distinct lightness where it matters); the decorations of the models (Ω, axes, outline,
/// shading) are greys and one light blue, so that they never compete with the items.

#include <string_view>

namespace t2::draw::palette {

// ---------------------------------------------------------------- items
inline constexpr const char* black = "#000000";       ///< points of a scene, titles
inline constexpr const char* blue = "#1f77b4";        ///< segments of a scene
inline constexpr const char* orange = "#ff7f0e";      ///< a second highlight
inline constexpr const char* green = "#2ca02c";       ///< polygons of a scene
inline constexpr const char* red = "#d62728";         ///< circles of a scene
inline constexpr const char* purple = "#9467bd";      ///< a third highlight
inline constexpr const char* brown = "#8c564b";       ///< a fourth highlight
inline constexpr const char* pink = "#e377c2";        ///< a fifth highlight
inline constexpr const char* olive = "#bcbd22";       ///< a sixth highlight
inline constexpr const char* cyan = "#17becf";        ///< a seventh highlight
inline constexpr const char* dark_grey = "#555555";   ///< a point set apart (the antipode of o)
inline constexpr const char* grey = "#7f7f7f";        ///< lines of a scene
inline constexpr const char* light_grey = "#999999";  ///< auxiliary items (construction lines)
inline constexpr const char* pale_grey = "#bbbbbb";   ///< items in the background
inline constexpr const char* white = "#ffffff";       ///< the inside of hollow arrowheads

/// A colour of the items and its name in scene files.
struct Named {
  const char* name;  ///< the name, as a scene file writes it
  const char* rgb;   ///< the colour, "#rrggbb"
};

/// The item colours by name, in the order of the category palette, then the greys.
inline constexpr Named names[] = {
    {"black", black}, {"blue", blue}, {"orange", orange}, {"green", green}, {"red", red},
    {"purple", purple}, {"brown", brown}, {"pink", pink}, {"olive", olive}, {"cyan", cyan},
    {"dark_grey", dark_grey}, {"grey", grey}, {"light_grey", light_grey}, {"pale_grey", pale_grey},
    {"white", white},
};

/// The colour named `name` ("#rrggbb"), or nullptr when no item colour has that name.
constexpr const char* named(std::string_view name) {
  for (const auto& n : names)
    if (name == n.name) return n.rgb;
  return nullptr;
}

// ---------------------------------------------------------------- the models' own marks
inline constexpr const char* omega = "#8c8c8c";      ///< Ω (ring, equator) and its name; T¹ notes
inline constexpr const char* axis = "#c8c8c8";       ///< coordinate axes
inline constexpr const char* shade = "#9ecae1";      ///< the positive side of a line, by default
inline constexpr const char* disk_edge = "#dddddd";  ///< the edge of the shown disk (planar model)
inline constexpr const char* sphere = "#f3f6f9";     ///< the face of the sphere
inline constexpr const char* graticule = "#d9d9d9";  ///< meridians and parallels
inline constexpr const char* outline = dark_grey;    ///< the outline of the sphere
inline constexpr const char* t1_ink = "#333333";     ///< the models of T¹ and their notes

// ---------------------------------------------------------------- marks of particular figures
inline constexpr const char* positive = "#3b6fb6";   ///< a positive sign in a sign map (chapter 04)
inline constexpr const char* negative = "#d9534f";   ///< a negative sign in a sign map
inline constexpr const char* zero = "#f2c200";       ///< a zero sign in a sign map
inline constexpr const char* pale_blue = "#dbe9f6";  ///< a fill under blue edges (chapter 08's triangles)

}  // namespace t2::draw::palette
