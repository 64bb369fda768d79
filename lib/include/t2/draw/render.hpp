#pragma once
/// @file render.hpp
/// @brief From a figure and a view to drawing commands, and to SVG, PNG or PDF bytes.
///
/// Rendering has two stages. `display_list` turns the figure into a flat list of `Shape`s in
/// picture coordinates (pixels, y down) — the models' rules (what is dashed, hollow, split,
/// clipped) all live there, and the tests inspect it. A Cairo backend then paints the list.
/// Output is deterministic: the same figure gives byte-identical SVG on the same machine.
/// Text uses the font "DejaVu Sans" (Debian package fonts-dejavu-core); the glyph outlines
/// embedded in SVG depend on the installed font version, nothing else does.

#include <filesystem>
#include <string>
#include <vector>

#include "t2/draw/figure.hpp"
#include "t2/draw/view.hpp"

namespace t2::draw {

/// Which part of T² a shape shows, so that tests and backends can tell them apart.
enum class Part {
  front,       ///< the front side (w > 0)
  back,        ///< the back side (w < 0)
  infinity,    ///< Ω (the ring of the planar model, the equator of the sphere)
  decoration,  ///< outline, Ω ring, graticule, axes, labels, title
};

/// What a shape is.
enum class ShapeKind {
  path,    ///< a polyline through `pts` (closed when `closed`), stroked and/or filled
  marker,  ///< a point marker of radius `radius` at `pts[0]`
  text,    ///< `text` with its reference point at `pts[0]`
};

/// One drawing command of the display list.
struct Shape {
  ShapeKind kind = ShapeKind::path;  ///< what to draw
  Part part = Part::front;           ///< which part of T² it shows
  bool hidden = false;               ///< on the far hemisphere of the sphere (dashed, faded)
  std::vector<Vec2> pts;             ///< geometry in pixels (x to the right, y down)
  bool closed = false;               ///< a closed path
  std::string stroke;                ///< stroke colour, empty = none
  double width = 1;                  ///< stroke width, pixels
  std::vector<double> dash;          ///< dash pattern, empty = solid
  std::string fill;                  ///< fill colour, empty = none
  double fill_opacity = 1;           ///< opacity of the fill
  bool hatch = false;                ///< fill with hatching lines instead of a flat colour
  double opacity = 1;                ///< opacity of the stroke
  Marker marker = Marker::dot;       ///< marker shape (kind marker)
  bool hollow = false;               ///< a marker drawn as an outline only (back points)
  double radius = 0;                 ///< marker radius, pixels
  std::string text;                  ///< text (kind text)
  double font_size = 13;             ///< text size, pixels
  int halign = 0;                    ///< text: -1 left edge at the point, 0 centred, 1 right
  bool halo = true;                  ///< text: a white halo under the glyphs
};

/// Height in pixels of the band above the picture that holds a figure's title (a figure with
/// a title is that much taller, so the title never covers the Ω ring or the sphere).
inline constexpr double title_band = 24;

/// The drawing commands of a figure in the planar model.
std::vector<Shape> display_list(const Figure& f, const PlaneView& v);
/// The drawing commands of a figure in the spherical model.
std::vector<Shape> display_list(const Figure& f, const SphereView& v);
/// The drawing commands of the T¹ items of a figure.
std::vector<Shape> display_list(const Figure& f, const T1View& v);

/// Output formats.
enum class Format { svg, png, pdf };

/// The format named by a file extension (.svg, .png, .pdf); throws `t2::BadInput` otherwise.
Format format_of(const std::filesystem::path& path);

/// The bytes of the picture of `f` in view `v` (an SVG document, a PNG or a PDF file).
std::string render(const Figure& f, const PlaneView& v, Format fmt = Format::svg);
/// The bytes of the picture of `f` in the spherical model.
std::string render(const Figure& f, const SphereView& v, Format fmt = Format::svg);
/// The bytes of the picture of the T¹ items of `f`.
std::string render(const Figure& f, const T1View& v, Format fmt = Format::svg);
/// The planar and the spherical model side by side in one picture.
std::string render_both(const Figure& f, const PlaneView& plane, const SphereView& sphere,
                        Format fmt = Format::svg);

/// Writes the picture atomically to `path`, in the format of its extension. Writes only when
/// the content changed (so unchanged figures keep their timestamps); returns true if it wrote.
bool save(const Figure& f, const PlaneView& v, const std::filesystem::path& path);
/// Writes the spherical model of `f` to `path` (as `save` of the planar model does).
bool save(const Figure& f, const SphereView& v, const std::filesystem::path& path);
/// Writes the T¹ picture of `f` to `path` (as `save` of the planar model does).
bool save(const Figure& f, const T1View& v, const std::filesystem::path& path);
/// Writes both models side by side (see `render_both`) to `path`.
bool save_both(const Figure& f, const PlaneView& plane, const SphereView& sphere,
               const std::filesystem::path& path);

/// The figures of a chapter program in both models: `save` writes NAME-plane.svg and
/// NAME-sphere.svg into one folder (each only when it changed, as `save` does), and `summary`
/// says how many there are and how many changed.
class FigurePairs {
 public:
  /// Figures go to `dir`.
  explicit FigurePairs(std::filesystem::path dir) : dir_(std::move(dir)) {}
  /// Writes `f` as NAME-plane.svg (seen in `plane`) and NAME-sphere.svg (seen in `sphere`).
  void save(const Figure& f, const std::string& name, const PlaneView& plane, const SphereView& sphere);
  /// "figures: N in DIR (K changed)".
  std::string summary() const;

 private:
  std::filesystem::path dir_;
  int count_ = 0, written_ = 0;
};

/// The figures directory of a chapter program: the value after `--figures` in argv, else
/// `fallback` (chapters pass their compile definition T2_FIGURES_DIR).
std::filesystem::path figures_dir(int argc, char** argv, const std::filesystem::path& fallback);

}  // namespace t2::draw
