#pragma once
/// @file scene.hpp
/// @brief Scene files: points, segments, polygons, lines, circles and labels of T² as plain text.
///
/// The format (README, section "Scene files") in short:
///
///     # a comment runs to the end of the line; blank lines are ignored
///     1 2                # the front point [1, 1, 2]: two numbers are x y
///     -1 0 3             # three numbers are homogeneous w x y: a back point
///     label A 0 0        # a named point of the scene
///     segment            # a block of exactly two points, or names of labelled points
///       A
///       0 5
///     end
///     polygon            # a block of three or more vertices, in order
///       0 0
///       1 0
///       0 1
///     end
///     line               # two points: the line through them, oriented from the first
///       0 0
///       A
///     end
///     circle             # the centre, then a point of the circle (any radius kind)
///       A
///       3 0
///     end
///     style color=red width=2   # attributes of every object after this line
///     3 4 color=blue label="P"  # an object's own attributes end its line (scene_style.hpp)
///     polygon fill=none layer=1 # a block's go on its keyword line
///
/// A file of plain points is a valid scene. Errors throw `ParseError`, whose message reads
/// `file:line: what is wrong`.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "t2/kernel/circle.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/polygon.hpp"
#include "t2/kernel/scene_style.hpp"
#include "t2/kernel/segment.hpp"

namespace t2 {

/// A scene file could not be read as a scene: `what()` is `file:line: message`.
class ParseError : public BadInput {
 public:
  /// @param file the name of the file (as given to the parser)
  /// @param line the 1-based line of the error
  /// @param message what is wrong, without the `file:line:` prefix
  ParseError(std::string file, int line, const std::string& message);
  /// The name of the file.
  const std::string& file() const { return file_; }
  /// The 1-based line number of the error.
  int line() const { return line_; }
  /// The message without the `file:line: ` prefix.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  std::string message_;
};

/// A point of a scene, where it was written, and its name (empty when it has none).
struct ScenePoint {
  Point point;        ///< the point of T²
  int line = 0;       ///< the 1-based line of the file that gave it
  std::string label;  ///< its name from a `label` line, or empty
  SceneStyle style;   ///< its attributes (a point of a block has none: the block has them)
};

/// A `segment ... end` block: two endpoints that are not antipodes.
struct SceneSegment {
  ScenePoint a;   ///< the first endpoint
  ScenePoint b;   ///< the second endpoint
  int line = 0;   ///< the line of the `segment` keyword
  SceneStyle style;  ///< its attributes
  /// The segment of T² from a to b (the parser has checked that it is defined).
  Segment segment() const { return Segment(a.point, b.point); }
};

/// A `polygon ... end` block: three or more vertices in order; no two consecutive ones
/// (cyclically) are antipodes, so every edge is a defined segment of T².
struct ScenePolygon {
  std::vector<ScenePoint> vertices;  ///< the vertices, in the order of the file
  int line = 0;                      ///< the line of the `polygon` keyword
  SceneStyle style;                  ///< its attributes
  /// The vertices as a `t2::Polygon`, for the algorithms of polygon.hpp.
  Polygon polygon() const {
    Polygon p;
    p.reserve(vertices.size());
    for (const auto& v : vertices) p.push_back(v.point);
    return p;
  }
};

/// A `line ... end` block: two points, neither equal nor antipodal, so that their join is a
/// line of T².
struct SceneLine {
  ScenePoint a;  ///< the first point
  ScenePoint b;  ///< the second point
  int line = 0;  ///< the line of the `line` keyword
  SceneStyle style;  ///< its attributes
  /// The line a ∨ b, oriented from a to b (the parser has checked that it is defined).
  Line join() const { return t2::join(a.point, b.point); }
};

/// A `circle ... end` block: the centre and a point of the circle, not both on Ω (circle.hpp).
/// The circle is positive (counter-clockwise in T²).
struct SceneCircle {
  ScenePoint center;   ///< the centre
  ScenePoint through;  ///< a point of the circle
  int line = 0;        ///< the line of the `circle` keyword
  SceneStyle style;    ///< its attributes
  /// The circle (the parser has checked that it is defined).
  Circle circle() const { return Circle(center.point, through.point); }
};

/// Everything a scene file holds.
struct Scene {
  std::string name;                    ///< the file name used in messages
  std::vector<ScenePoint> points;      ///< the points outside blocks (labelled ones included)
  std::vector<SceneSegment> segments;  ///< the `segment` blocks, in order
  std::vector<ScenePolygon> polygons;  ///< the `polygon` blocks, in order
  std::vector<SceneLine> lines;        ///< the `line` blocks, in order
  std::vector<SceneCircle> circles;    ///< the `circle` blocks, in order

  /// The labelled point named `label`, or nullptr.
  const ScenePoint* find(std::string_view label) const;
};

/// The keywords that open a block of a scene file (segment, polygon, line, circle), in the
/// order of the parser's table of block kinds (lib/src/kernel/scene.cpp: one row per kind, with how
/// many points it holds and the builder that checks and adds it).
std::vector<std::string_view> scene_block_keywords();

/// Parses the text of a scene file; `name` is used in error messages (`name:line: ...`).
/// Throws `ParseError` on the first error.
Scene parse_scene(std::string_view text, std::string name);

/// The text of a scene file that parses back to s: the same points (in the same order, with
/// their names and attributes), then the blocks kind by kind, each with its attributes and its
/// points written as coordinates (a block's reference to a named point is not kept). Numbers are
/// written in the shortest form that reads back to the same double.
std::string to_string(const Scene& s);

/// Reads and parses a scene file. Throws `BadInput` when the file cannot be read and
/// `ParseError` when it is not a valid scene.
Scene read_scene(const std::filesystem::path& path);

}  // namespace t2
