// Brute-force segment intersection (chapter 13): every pair, the reference of the sweep.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <variant>

#include "t2/intersect/intersections.hpp"
#include "t2/kernel/lexicographic.hpp"

namespace t2 {

const char* name(IntersectAlgorithm a) {
  switch (a) {
    case IntersectAlgorithm::brute: return "brute";
    case IntersectAlgorithm::sweep: return "sweep";
    case IntersectAlgorithm::circular: return "circular";
  }
  return "?";
}

ExactPoint reduced(const ExactPoint& p) {
  Integer g;
  mpz_gcd(g.get_mpz_t(), p.w().get_mpz_t(), p.x().get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), p.y().get_mpz_t());
  if (g == 1) return p;
  return ExactPoint(Integer(p.w() / g), Integer(p.x() / g), Integer(p.y() / g));
}

std::string to_line(const IntersectionPoint& p) {
  std::string s = fmt::format("{} {} {} ", p.point.w().get_str(), p.point.x().get_str(), p.point.y().get_str());
  for (std::size_t i : p.segments) s += fmt::format(" {}", i);
  return s;
}

std::vector<IntersectionPoint> intersections(const std::vector<Segment>& segments, IntersectAlgorithm algorithm) {
  switch (algorithm) {
    case IntersectAlgorithm::brute: return intersections_brute(segments);
    case IntersectAlgorithm::circular: return intersections_circular(segments);
    case IntersectAlgorithm::sweep: break;
  }
  return intersections_sweep(segments);
}

namespace {

/// The reduced triple as a key (equal points of T² have equal reduced triples).
using Key = std::array<Integer, 3>;

struct KeyLess {
  bool operator()(const Key& a, const Key& b) const {
    for (int i = 0; i < 3; ++i) {
      const int c = cmp(a[i], b[i]);
      if (c != 0) return c < 0;
    }
    return false;
  }
};

/// The closed box of a front segment's drawn positions, for a cheap exact rejection: two front
/// segments whose boxes are disjoint do not meet (each lies in its box, being convex).
struct Box {
  double x0, y0, x1, y1;  ///< rounded outward, so the true box lies inside
  bool front;             ///< false: no box (not a front segment)
};

Box box_of(const Segment& s) {
  const Point &a = s.source(), &b = s.target();
  if (!(a.w() > 0 && b.w() > 0)) return {0, 0, 0, 0, false};
  // x/w rounded to nearest errs by half an ulp; one step outward covers it.
  auto lo = [](double v) { return std::nextafter(v, -HUGE_VAL); };
  auto hi = [](double v) { return std::nextafter(v, HUGE_VAL); };
  const double ax = a.x() / a.w(), ay = a.y() / a.w(), bx = b.x() / b.w(), by = b.y() / b.w();
  return {lo(std::min(ax, bx)), lo(std::min(ay, by)), hi(std::max(ax, bx)), hi(std::max(ay, by)), true};
}

bool disjoint(const Box& a, const Box& b) {
  return a.front && b.front && (a.x1 < b.x0 || b.x1 < a.x0 || a.y1 < b.y0 || b.y1 < a.y0);
}

}  // namespace

std::vector<IntersectionPoint> intersections_brute(const std::vector<Segment>& segments) {
  const std::size_t n = segments.size();
  std::vector<ExactSegment> exact;
  std::vector<Box> boxes;
  exact.reserve(n);
  boxes.reserve(n);
  for (const Segment& s : segments) {
    exact.emplace_back(to_exact(s.source()), to_exact(s.target()));
    boxes.push_back(box_of(s));
  }
  std::map<Key, std::vector<std::size_t>, KeyLess> found;
  auto add = [&](const ExactPoint& p, std::size_t i, std::size_t j) {
    const ExactPoint r = reduced(p);
    auto& v = found[Key{r.w(), r.x(), r.y()}];
    v.push_back(i);
    v.push_back(j);
  };
  //> brute-pairs
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (disjoint(boxes[i], boxes[j])) continue;
      if (!intersects(segments[i], segments[j])) continue;  // exact on doubles
      const auto r = intersection(exact[i], exact[j]);
      if (const auto* p = std::get_if<ExactPoint>(&r)) {
        add(*p, i, j);
      } else if (const auto* s = std::get_if<ExactSegment>(&r)) {
        add(s->source(), i, j);
        add(s->target(), i, j);
      }
    }
  }
  //< brute-pairs
  std::vector<IntersectionPoint> out;
  out.reserve(found.size());
  for (auto& [k, v] : found) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    out.push_back({ExactPoint(k[0], k[1], k[2]), std::move(v)});
  }
  std::sort(out.begin(), out.end(), [](const IntersectionPoint& a, const IntersectionPoint& b) {
    return less_wxy(a.point, b.point);
  });
  return out;
}

}  // namespace t2
