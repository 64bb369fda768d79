#pragma once
// The answer of a command (t2 hull, t2 layers, t2 diameter, t2 kernel, t2 triangulate, t2 delaunay)
// as a scene and as a picture, and the picture of t2 draw: the --svg/--model/--scene options, the
// composition of scenes into one figure, the planar view that fits them, a figure rendered in the
// planar model, the spherical model or both, and the atomic writes.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "arguments.hpp"
#include "t2/draw/figure.hpp"
#include "t2/draw/render.hpp"
#include "t2/draw/view.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/scene.hpp"

namespace t2cli {

/// What an algorithm command was asked to write besides its answer on stdout: `--svg OUT`,
/// `--model plane|sphere|both` and `--scene OUT`.
struct AnswerDrawing {
  std::string svg;             ///< where to write the picture; empty: no picture
  std::string model = "both";  ///< plane, sphere or both side by side
  std::string scene;           ///< where to write the answer as a scene file; empty: nowhere
};

/// Declares `--svg OUT`, `--model M` and `--scene OUT` on `app`, stored in `d`; `what` says
/// what is drawn ("the points and the hull").
void add_drawing_options(Arguments& app, AnswerDrawing& d, const std::string& what);

/// The attributes written as in a scene file, `key=value` separated by spaces (no quoted
/// values: set a label with spaces directly), e.g. `style_of("color=green width=2 layer=1")`.
t2::SceneStyle style_of(std::string_view attributes);

/// A point of an answer scene, with its attributes.
t2::ScenePoint scene_point(const t2::Point& p, t2::SceneStyle style = {});

/// The planar viewport centred at the origin, wide enough for every finite point of `points`
/// (points at infinity sit on the Ω ring whatever the width).
t2::draw::PlaneView fit_plane(std::span<const t2::Point> points);

/// The same for every object of a scene: points, ends of segments and lines, polygon vertices,
/// and the farthest point of every circle of finite radius.
t2::draw::PlaneView fit_plane(const t2::Scene& s);

/// The scenes drawn in order into one figure (a later one over an earlier one within a layer),
/// each object in its own style (`t2::draw::add_scene`); `plane` becomes the view that fits all.
t2::draw::Figure compose(std::span<const t2::Scene> scenes, t2::draw::PlaneView& plane);

/// `f` rendered in `model` (plane, sphere or both side by side).
std::string render_model(const t2::draw::Figure& f, const std::string& model, const t2::draw::PlaneView& plane,
                         const t2::draw::SphereView& sphere = {}, t2::draw::Format format = t2::draw::Format::svg);

/// Writes what `d` asks for `answer`, the answer of a command to the scene `input`: to d.scene
/// the answer as a scene file (first a comment line `# header`), to d.svg the picture of the
/// input with the answer over it — the picture `t2 draw INPUT ANSWER` draws. Both atomically;
/// nothing for an empty name.
void write_answer(const AnswerDrawing& d, const t2::Scene& input, t2::Scene answer, const std::string& header);

}  // namespace t2cli
