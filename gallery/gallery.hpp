#pragma once
// The figure gallery's shared parts: output place, style shorthands, views, scene
// loading, and the entry list each part of the gallery contributes (one file per part:
// thesis3.cpp, thesis4_primitives.cpp, thesis4_predicates.cpp).
#include <t2/kernel/scene.hpp>
#include <t2/t2.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace gallery {

namespace dr = t2::draw;
namespace fs = std::filesystem;
using t2::Point;

namespace pal = t2::draw::palette;  ///< the colours of the figures

/// Where the figures go (figures/gallery, or the directory after --figures).
const fs::path& out_dir();
/// The scene files of the gallery (gallery/scenes).
fs::path scene_path(const std::string& file);

/// A stroke of one colour.
inline dr::Style st(const char* colour) { return dr::Style().color(colour); }
/// A labelled item of one colour; the label's direction is automatic unless `angle` is given.
inline dr::Style lab(const char* colour, std::string text, double angle = std::nan("")) {
  return dr::Style().color(colour).label(std::move(text)).label_angle(angle);
}

/// The planar model showing the disk of radius hw around the origin.
inline dr::PlaneView plane(double hw = 4) {
  dr::PlaneView v;
  v.half_width = hw;
  return v;
}
/// The spherical model seen from latitude `lat`, longitude `lon` (degrees).
inline dr::SphereView sphere(double lat = 25, double lon = -65) {
  dr::SphereView v;
  v.lat = lat;
  v.lon = lon;
  return v;
}

/// Adds the blocks of a scene file of gallery/scenes, all in one colour (`t2::draw::add_scene`).
void add_scene(dr::Figure& f, const std::string& file, const char* colour);

/// One figure of the thesis: its number ("4.7"), the file it is drawn to, our caption, and the
/// function that draws it (nullptr when another entry's function draws this file too).
struct Entry {
  std::string number;
  std::string file;
  std::string caption;
  void (*make)();
};

std::vector<Entry> thesis3();             ///< figures 3.1–3.12: the models, orientation, lines, segments
std::vector<Entry> thesis4_primitives();  ///< figures 4.1–4.11: triangles, rectangles, boxes, circles
std::vector<Entry> thesis4_predicates();  ///< figures 4.12–4.20: distances, midpoints, segments, angles

}  // namespace gallery
