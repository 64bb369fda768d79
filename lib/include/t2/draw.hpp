#pragma once
/// @file draw.hpp
/// @brief Figures of T²: the planar and spherical models drawn with Cairo (SVG, PNG, PDF).
///
/// Geometry and style are kept apart: a `t2::draw::Figure` holds items that refer to geometry,
/// each with a `t2::draw::Style`; a view (`PlaneView`, `SphereView`, `T1View`) says which model
/// and which part of it to show; `save` writes the picture. A chapter program does:
///
/// @code
/// #include <t2/t2.hpp>
/// namespace dr = t2::draw;
/// int main(int argc, char** argv) {
///   const auto dir = dr::figures_dir(argc, argv, T2_FIGURES_DIR);   // --figures DIR
///   const t2::Point p(1, 1, 0.5), q(-1, -2, 1);                      // q is on the back side
///   dr::Figure fig;
///   fig.add(p, dr::Style().label("p"));                  // filled marker (front)
///   fig.add(q, dr::Style().label("q").label_angle(-45)); // hollow marker (back)
///   fig.segment(p, q, dr::Style().color("#1f77b4"));    // two half-rays through Ω
///   fig.add(t2::join(p, q), dr::Style().color("#999999").shade());   // line + positive side
///   fig.add(std::vector<t2::Point>{...}, dr::Style().fill("#2ca02c")); // polygon
///   dr::PlaneView plane;  plane.half_width = 4;          // disk of radius 4, Ω ring around it
///   dr::SphereView sphere;  sphere.lat = 25;  sphere.lon = -35;
///   dr::save(fig, plane, dir / "name-plane.svg");        // format from the extension
///   dr::save(fig, sphere, dir / "name-sphere.svg");
///   dr::save_both(fig, plane, sphere, dir / "name.svg"); // both models side by side
/// }
/// @endcode
///
/// Conventions of the pictures (seed 000, §3): the front side is solid with filled markers, the
/// back side dashed with hollow markers (distinguishable in print), Ω is a grey ring (planar
/// model) or the equator (spherical model, front = upper hemisphere), the hidden hemisphere of
/// the sphere is dashed and faded. `save` only rewrites a file whose bytes changed.

#include "t2/draw/figure.hpp"
#include "t2/draw/loglog.hpp"
#include "t2/draw/palette.hpp"
#include "t2/draw/render.hpp"
#include "t2/draw/scene_figure.hpp"
#include "t2/draw/style.hpp"
#include "t2/draw/vec.hpp"
#include "t2/draw/view.hpp"
