// The figure of a scene file (t2/draw/scene_figure.hpp): every block kind becomes the item the
// scene means, in its style, and is drawn; a circle that cannot be drawn is refused with the
// file:line of its block. The oracle is the scene itself: the items must hold exactly the
// points, joins and circles the parser read, checked item by item.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "t2/draw.hpp"
#include "t2/kernel/scene.hpp"

namespace t2 {
namespace {

namespace dr = t2::draw;

// One block of every kind, and two points (one labelled).
const char* const kEveryKind =
    "label A 0 0\n"
    "-1 2 3\n"
    "segment\nA\n-1 5 5\nend\n"  // crosses Ω: drawn on both sides
    "polygon\n1 0\n0 1\n-1 -1\nend\n"
    "line\n0 0\n1 1\nend\n"
    "circle\nA\n2 0\nend\n";

std::vector<dr::ItemKind> kinds(const dr::Figure& f) {
  std::vector<dr::ItemKind> k;
  for (const auto& it : f.items()) k.push_back(it.kind);
  return k;
}

TEST(SceneFigure, EveryBlockKindBecomesItsItemInOrder) {
  const Scene s = parse_scene(kEveryKind, "every.t2");
  const dr::Figure f = dr::figure_of(s);
  using K = dr::ItemKind;
  ASSERT_EQ(kinds(f), (std::vector<K>{K::polygon, K::circle, K::line, K::segment, K::point, K::point}));
  const auto& items = f.items();
  // The polygon's vertices, the join, the segment's ends and the points are the scene's.
  ASSERT_EQ(items[0].points.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(items[0].points[i], s.polygons[0].vertices[i].point);
  EXPECT_EQ(items[2].line, join(Point(1, 0, 0), Point(1, 1, 1)));
  EXPECT_EQ(items[3].points[0], s.segments[0].a.point);
  EXPECT_EQ(items[3].points[1], s.segments[0].b.point);
  EXPECT_EQ(items[4].points[0], Point(1, 0, 0));
  EXPECT_EQ(items[4].style.label(), "A");
  EXPECT_EQ(items[5].points[0], Point(-1, 2, 3));
  EXPECT_EQ(items[5].style.label(), "");
  // The circle: every sampled point at distance 2 from A, on the front side.
  for (const Point& p : items[1].points) {
    ASSERT_GT(p.w(), 0);
    EXPECT_NEAR(std::hypot(p.x() / p.w(), p.y() / p.w()), 2, 1e-12);
  }
}

TEST(SceneFigure, DefaultStylesAreTheToolsAndOneColourStylesAreOneColour) {
  const Scene s = parse_scene(kEveryKind, "every.t2");
  const dr::Figure f = dr::figure_of(s);
  const auto& it = f.items();
  EXPECT_EQ(it[0].style.color(), dr::palette::green);
  EXPECT_EQ(it[0].style.fill(), dr::palette::green);
  EXPECT_EQ(it[1].style.color(), dr::palette::red);
  EXPECT_EQ(it[2].style.color(), dr::palette::grey);
  EXPECT_TRUE(it[2].style.arrow());
  EXPECT_EQ(it[3].style.color(), dr::palette::blue);
  EXPECT_EQ(it[4].style.color(), dr::palette::black);
  // Points over segments over the rest.
  EXPECT_EQ(it[0].style.layer(), 0);
  EXPECT_EQ(it[3].style.layer(), 1);
  EXPECT_EQ(it[4].style.layer(), 2);
  dr::Figure g;
  dr::add_scene(g, s, dr::SceneStyles::in("#123456"));
  ASSERT_EQ(g.items().size(), 6u);
  for (const auto& item : g.items()) {
    EXPECT_EQ(item.style.color(), "#123456");
    EXPECT_EQ(item.style.layer(), 0);
  }
  EXPECT_EQ(g.items()[0].style.fill(), "#123456");
}

TEST(SceneFigure, EveryBlockKindIsDrawnInBothModels) {
  const dr::Figure f = dr::figure_of(parse_scene(kEveryKind, "every.t2"));
  auto colours = [](const std::vector<dr::Shape>& list) {
    std::vector<std::string> c;
    for (const auto& s : list) {
      if (s.kind == dr::ShapeKind::path && !s.stroke.empty()) c.push_back("stroke " + s.stroke);
      if (s.kind == dr::ShapeKind::path && !s.fill.empty()) c.push_back("fill " + s.fill);
      if (s.kind == dr::ShapeKind::marker) c.push_back(std::string("marker ") + (s.hollow ? "hollow " : "") + s.stroke);
      if (s.kind == dr::ShapeKind::text) c.push_back("text " + s.text);
    }
    return c;
  };
  dr::PlaneView plane;
  plane.half_width = 8;
  for (const auto& list : {dr::display_list(f, plane), dr::display_list(f, dr::SphereView())}) {
    const auto c = colours(list);
    auto has = [&](const std::string& what) { return std::find(c.begin(), c.end(), what) != c.end(); };
    for (const char* what : {"fill #2ca02c", "stroke #2ca02c", "stroke #d62728", "stroke #7f7f7f", "stroke #1f77b4",
                             "marker #000000", "marker hollow #000000", "text A"})
      EXPECT_TRUE(has(what)) << what;
  }
  // In the planar model the segment from the front point A to the back point [-1, 5, 5] is two
  // half-rays: one front piece, one back piece.
  int front = 0, back = 0;
  for (const auto& s : dr::display_list(f, plane))
    if (s.kind == dr::ShapeKind::path && s.stroke == dr::palette::blue) (s.part == dr::Part::front ? front : back)++;
  EXPECT_EQ(front, 1);
  EXPECT_EQ(back, 1);
}

TEST(SceneFigure, ACircleBeyondTheRangeOfDoubleIsRefusedWithItsLine) {
  const Scene s = parse_scene("1 1\n\ncircle\n1e-300 1e300 1e300\n1 1e300 -1e300\nend\n", "huge.t2");
  try {
    (void)dr::figure_of(s);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "huge.t2");
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(e.message().find("beyond the range of double"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace t2
