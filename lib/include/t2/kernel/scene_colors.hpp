#pragma once
/// @file scene_colors.hpp
/// @brief The colours a scene file may name (`color=dark_grey`), in the kernel: reading a scene
/// resolves a name to "#rrggbb" without the drawing layer, and the drawing's palette
/// (`t2/draw/palette.hpp`) takes its item colours from here.
///
/// They are the ten "category" colours of matplotlib and d3 (distinct in colour, and of
/// distinct lightness where it matters), then greys and white.

#include <string_view>

namespace t2::scene_colors {

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

/// A colour and its name in scene files.
struct Named {
  const char* name;  ///< the name, as a scene file writes it
  const char* rgb;   ///< the colour, "#rrggbb"
};

/// The colours by name, in the order of the category palette, then the greys.
inline constexpr Named names[] = {
    {"black", black}, {"blue", blue}, {"orange", orange}, {"green", green}, {"red", red},
    {"purple", purple}, {"brown", brown}, {"pink", pink}, {"olive", olive}, {"cyan", cyan},
    {"dark_grey", dark_grey}, {"grey", grey}, {"light_grey", light_grey}, {"pale_grey", pale_grey},
    {"white", white},
};

/// The colour named `name` ("#rrggbb"), or nullptr when no scene colour has that name.
constexpr const char* named(std::string_view name) {
  for (const auto& n : names)
    if (name == n.name) return n.rgb;
  return nullptr;
}

}  // namespace t2::scene_colors
