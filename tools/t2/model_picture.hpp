#pragma once
// The picture of a command's answer (t2 hull, t2 triangulate, t2 delaunay, ...), and of t2 draw:
// the --svg/--model options, the planar view that fits the input, a figure rendered in the planar
// model, the spherical model or both, and the atomic write.

#include <span>
#include <string>
#include <vector>

#include "t2/draw/figure.hpp"
#include "t2/draw/render.hpp"
#include "t2/draw/view.hpp"
#include "t2/point.hpp"
#include "t2/scene.hpp"

namespace CLI {
class App;
}

namespace t2cli {

/// The drawing an algorithm command was asked for: `--svg OUT` and `--model plane|sphere|both`.
struct AnswerDrawing {
  std::string svg;             ///< where to write the picture; empty: no picture
  std::string model = "both";  ///< plane, sphere or both side by side
};

/// Declares `--svg OUT` and `--model M` on `app`, stored in `d`; `what` says what is drawn
/// ("the points and the hull").
void add_drawing_options(CLI::App& app, AnswerDrawing& d, const std::string& what);

/// The planar viewport centred at the origin, wide enough for every finite point of `points`
/// (points at infinity sit on the Ω ring whatever the width).
t2::draw::PlaneView fit_plane(std::span<const t2::Point> points);

/// The same for every object of a scene: points, ends of segments and lines, polygon vertices,
/// and the farthest point of every circle of finite radius.
t2::draw::PlaneView fit_plane(const t2::Scene& s);

/// `f` rendered in `model` (plane, sphere or both side by side).
std::string render_model(const t2::draw::Figure& f, const std::string& model, const t2::draw::PlaneView& plane,
                         const t2::draw::SphereView& sphere = {}, t2::draw::Format format = t2::draw::Format::svg);

/// Renders `f` as SVG in the models named by `model` (plane, sphere or both); the planar view is
/// large enough to hold every finite point of `points`.
std::string render_models(const t2::draw::Figure& f, const std::vector<t2::Point>& points, const std::string& model);

/// Writes `f`, drawn as `d` asks with the planar viewport `plane`, to d.svg atomically; nothing
/// when d.svg is empty.
void write_drawing(const AnswerDrawing& d, const t2::draw::Figure& f, const t2::draw::PlaneView& plane);

}  // namespace t2cli
