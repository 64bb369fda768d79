#pragma once
// The one dispatch from the items of a figure to a model: each model (planar, spherical, T¹)
// is a Painter, and `paint` hands it the items by layer. A new kind of item is a new member
// of ItemKind, one case in `paint` and one method here (the compiler then asks every model
// for it).
#include <string>
#include <vector>

#include "t2/draw/figure.hpp"
#include "t2/draw/render.hpp"

namespace t2::draw {

/// How a model draws each kind of item (see the file comment).
class Painter {
 public:
  virtual ~Painter() = default;
  /// A point of T².
  virtual void point(const Point& p, const Style& st) = 0;
  /// A whole oriented line.
  virtual void line(const Line& l, const Style& st) = 0;
  /// The segment of T² from p to q (labelled at its middle).
  virtual void segment(const Point& p, const Point& q, const Style& st) = 0;
  /// A chain of segments through `pts`: a polygon when `closed`, else a polyline.
  virtual void chain(const std::vector<Point>& pts, const Style& st, bool closed) = 0;
  /// A circle of finite or beyond-infinity radius: the dense loop `pts`, all on one side.
  virtual void circle(const std::vector<Point>& pts, const Style& st) = 0;
  /// `text` next to the point p.
  virtual void label(const Point& p, const std::string& text, const Style& st) = 0;
  /// A point [w, x] of T¹.
  virtual void t1(double w, double x, const Style& st) = 0;
};

/// Paints the items of f by layer (equal layers in the order added).
void paint(const Figure& f, Painter& p);

struct Canvas;
/// The display list of f: painted by p on c (which holds the model's own marks so far), with
/// the labels placed and, when `titled`, the title in a band above the picture.
std::vector<Shape> display(const Figure& f, Painter& p, Canvas& c, bool titled = true);

}  // namespace t2::draw
