// t2 draw: the picture of a scene file in the planar model, the spherical model, or both.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "model_picture.hpp"
#include "t2/draw.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/scene.hpp"

namespace t2cli {
namespace cmd_draw {

namespace dr = t2::draw;

double parse_degrees(const std::string& s, const char* what, double limit) {
  char* end = nullptr;
  const double d = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(d) || std::fabs(d) > limit)
    throw UsageError(fmt::format("--view: {} must be a number of degrees in [-{}, {}], not '{}'", what,
                                 limit, limit, s));
  return d;
}

struct Options {
  std::vector<std::string> files;
  std::string output;
  std::optional<std::string> format;
  std::string model = "both";
  dr::SphereView sphere;
};

// --view LAT,LON
dr::SphereView parse_view(const std::string& v) {
  const auto comma = v.find(',');
  if (comma == std::string::npos) throw UsageError(fmt::format("--view takes LAT,LON, not '{}'", v));
  dr::SphereView sphere;
  sphere.lat = parse_degrees(v.substr(0, comma), "LAT", 90);
  sphere.lon = parse_degrees(v.substr(comma + 1), "LON", 360);
  return sphere;
}

dr::Format format_named(const std::string& s) {
  if (s == "svg") return dr::Format::svg;
  if (s == "png") return dr::Format::png;
  return dr::Format::pdf;  // --format allows only these three
}

int draw(const Options& o) {
  // The format first: a bad extension must not cost a parse, and must not leave a file.
  const dr::Format fmt = o.format ? format_named(*o.format) : dr::format_of(o.output);
  // Every file is read before anything is drawn (ParseError: file:line: message, exit 2); the
  // files are drawn in order, so within a layer a later file is drawn over an earlier one.
  std::vector<t2::Scene> scenes;
  for (const auto& file : o.files) scenes.push_back(t2::read_scene(file));
  dr::PlaneView plane;
  const dr::Figure fig = compose(scenes, plane);
  t2::write_file_atomically(o.output, render_model(fig, o.model, plane, o.sphere, fmt));
  return kOk;
}

Action setup(Arguments& app) {
  auto o = std::make_shared<Options>();
  app.description(
      "Reads the scene files FILE... (the format is described in the README, section \"Scene\n"
      "files\") and draws them into one picture, each over the ones before it: points (with\n"
      "their labels), segments (blue), polygons (green), lines (grey, arrow: orientation) and\n"
      "circles (red: finite, beyond infinity on the other side, or infinite: a line or Ω),\n"
      "unless an object's style attributes say otherwise, following the conventions of the\n"
      "figures: front side solid with filled markers, back side dashed with hollow markers,\n"
      "Ω a grey ring (planar model) or the equator (spherical model). An algorithm's answer\n"
      "(t2 hull FILE --scene OUT, ...) composes with its input: t2 draw FILE OUT -o fig.svg.");
  app.add_option("FILE", o->files, "the scene files, drawn in order")->required();
  app.add_option("--model", o->model, "plane, sphere or both side by side (default both)")
      ->check(IsMember({"plane", "sphere", "both"}))
      ->type_name("plane|sphere|both");
  app.add_option_function(
         "--view", [o](const std::string& v) { o->sphere = parse_view(v); },
         "direction from which the sphere is seen, degrees (default 25,-65)")
      ->type_name("LAT,LON");
  app.add_option("--format", o->format, "svg, png or pdf (default: from the extension of OUT)")
      ->check(IsMember({"svg", "png", "pdf"}))
      ->type_name("svg|png|pdf");
  app.add_option("-o", o->output, "the picture; written atomically, only when everything succeeded")
      ->required()
      ->type_name("OUT");
  app.footer(
      "The planar view is centred at the origin and wide enough for every finite point\n"
      "and every circle of finite radius of every file.\n"
      "\n"
      "Exit status: 0 done; 2 bad usage, unreadable file or invalid scene (the message\n"
      "reads file:line: what is wrong; no output file is created).");
  return [o] { return draw(*o); };
}

}  // namespace cmd_draw

T2_COMMAND({"draw", "draw a scene file in the planar model, the spherical model, or both", cmd_draw::setup});

}  // namespace t2cli
