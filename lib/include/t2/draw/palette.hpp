#pragma once
/// @file palette.hpp
/// @brief The colours of the figures: one palette for items, one for the models' own marks and
/// a few marks of particular figures.
///
/// Scene files name the item colours (`color=dark_grey`): t2/kernel/scene_colors.hpp, in the kernel.
///
/// Item colours are the ten "category" colours of matplotlib and d3 (distinct in colour, and
/// of distinct lightness where it matters); the decorations of the models (Ω, axes, outline,
/// shading) are greys and one light blue, so that they never compete with the items.

#include "t2/kernel/scene_colors.hpp"

namespace t2::draw::palette {

// ---------------------------------------------------------------- items
// The item colours are the scene files' colours (black, blue, ..., white), with their names
// (`names`, `named`): the kernel owns them, since reading a scene resolves the names.
using namespace t2::scene_colors;

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
