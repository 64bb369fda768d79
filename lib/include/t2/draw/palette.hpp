#pragma once
/// @file palette.hpp
/// @brief The colours of the figures: one palette for items and one for the models' own marks.
///
/// Item colours are the ten "category" colours of matplotlib and d3 (distinct in colour, and
/// of distinct lightness where it matters); the decorations of the models (Ω, axes, outline,
/// shading) are greys and one light blue, so that they never compete with the items.

namespace t2::draw::palette {

// ---------------------------------------------------------------- items
inline constexpr const char* black = "#000000";       ///< points of a scene, titles
inline constexpr const char* blue = "#1f77b4";        ///< segments of a scene
inline constexpr const char* orange = "#ff7f0e";      ///< a second highlight
inline constexpr const char* green = "#2ca02c";       ///< polygons of a scene
inline constexpr const char* red = "#d62728";         ///< circles of a scene
inline constexpr const char* purple = "#9467bd";      ///< a third highlight
inline constexpr const char* dark_grey = "#555555";   ///< a point set apart (the antipode of o)
inline constexpr const char* grey = "#7f7f7f";        ///< lines of a scene
inline constexpr const char* light_grey = "#999999";  ///< auxiliary items (construction lines)
inline constexpr const char* pale_grey = "#bbbbbb";   ///< items in the background
inline constexpr const char* white = "#ffffff";       ///< the inside of hollow arrowheads

// ---------------------------------------------------------------- the models' own marks
inline constexpr const char* omega = "#8c8c8c";      ///< Ω (ring, equator) and its name; T¹ notes
inline constexpr const char* axis = "#c8c8c8";       ///< coordinate axes
inline constexpr const char* shade = "#9ecae1";      ///< the positive side of a line, by default
inline constexpr const char* disk_edge = "#dddddd";  ///< the edge of the shown disk (planar model)
inline constexpr const char* sphere = "#f3f6f9";     ///< the face of the sphere
inline constexpr const char* graticule = "#d9d9d9";  ///< meridians and parallels
inline constexpr const char* outline = dark_grey;    ///< the outline of the sphere
inline constexpr const char* t1_ink = "#333333";     ///< the models of T¹ and their notes

}  // namespace t2::draw::palette
