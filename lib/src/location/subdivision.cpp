// The half-edge structure of a polygonal subdivision of T² (subdivision.hpp).
#include "t2/location/subdivision.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "t2/kernel/orient.hpp"

namespace t2 {

//> in-corner
bool in_corner(const Point& u, const Point& v, const Point& w, const Point& d) {
  const Sign turn = orient(u, v, w);
  const bool left_in = orient(u, v, d) == POSITIVE;
  if (turn == ZERO) return left_in;
  const bool left_out = orient(v, w, d) == POSITIVE;
  return turn == POSITIVE ? left_in && left_out : left_in || left_out;
}
//< in-corner

namespace {
// The primitive integer vector of p: to_exact(p) divided by the gcd of its coordinates (a
// positive factor), so equal points of T² have equal keys and antipodes opposite ones.
std::tuple<Integer, Integer, Integer> key(const Point& p) {
  const ExactPoint e = to_exact(p);
  Integer g;
  mpz_gcd(g.get_mpz_t(), e.w().get_mpz_t(), e.x().get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), e.y().get_mpz_t());
  return {e.w() / g, e.x() / g, e.y() / g};
}
}  // namespace

Subdivision::Subdivision(std::span<const Polygon> faces) {
  std::vector<Point> all;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!is_simple(faces[f]))
      throw MapError(f, "the face is not a simple polygon of T2 (a repeated or antipodal vertex, or edges that meet)");
    all.insert(all.end(), faces[f].begin(), faces[f].end());
  }
  std::vector<std::tuple<Integer, Integer, Integer>> keys;
  keys.reserve(all.size());
  for (const auto& p : all) keys.push_back(key(p));
  std::vector<Index> order(all.size());
  std::iota(order.begin(), order.end(), Index(0));
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return keys[a] < keys[b]; });
  std::vector<Index> id(all.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || keys[order[i]] != keys[order[i - 1]]) points_.push_back(all[order[i]]);
    id[order[i]] = static_cast<Index>(points_.size() - 1);
  }
  std::vector<std::vector<Index>> cycles(faces.size());
  std::size_t at = 0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t k = 0; k < faces[f].size(); ++k) cycles[f].push_back(id[at++]);
  build(cycles);
}

Subdivision::Subdivision(std::vector<Point> points, const std::vector<std::vector<Index>>& faces)
    : points_(std::move(points)) {
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() < 3) throw MapError(f, "a face needs three or more vertices");
    for (const Index v : faces[f])
      if (v >= points_.size()) throw MapError(f, fmt::format("vertex index {} out of range", v));
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      const Point &a = points_[faces[f][k]], &b = points_[faces[f][(k + 1) % faces[f].size()]];
      if (a == b || a == antipode(b)) throw MapError(f, fmt::format("edge {} joins equal or antipodal points", k));
    }
  }
  build(faces);
}

void Subdivision::build(const std::vector<std::vector<Index>>& faces) {
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      face_.push_back(static_cast<Index>(f));
      org_.push_back(faces[f][k]);
    }
    first_.push_back(static_cast<Index>(org_.size()));
  }
  // Twins: each directed edge once; the reverse one, when given, is the twin.
  std::unordered_map<std::uint64_t, Index> edge;
  edge.reserve(org_.size());
  const auto code = [](Index a, Index b) { return (std::uint64_t(a) << 32) | b; };
  for (Index h = 0; h < org_.size(); ++h) {
    const auto [it, fresh] = edge.emplace(code(org(h), dest(h)), h);
    if (!fresh)
      throw MapError(face(h), fmt::format("edge {} -> {} of the face is also an edge of face {} in the same direction: "
                                          "the two faces overlap (or one is clockwise)",
                                          slot(h), slot(next(h)), face(it->second)));
  }
  twin_.assign(org_.size(), none);
  for (Index h = 0; h < org_.size(); ++h) {
    const auto it = edge.find(code(dest(h), org(h)));
    if (it != edge.end()) twin_[h] = it->second;
    else boundary_.push_back(h);
  }
  // Corners around each vertex (counting sort by vertex).
  corner_first_.assign(points_.size() + 1, 0);
  for (Index h = 0; h < org_.size(); ++h) ++corner_first_[org(h) + 1];
  std::partial_sum(corner_first_.begin(), corner_first_.end(), corner_first_.begin());
  corner_.resize(org_.size());
  std::vector<Index> fill(corner_first_.begin(), corner_first_.end() - 1);
  for (Index h = 0; h < org_.size(); ++h) corner_[fill[org(h)]++] = {face(h), slot(h)};
  check_corners();
  convex_.assign(faces.size(), 0);
  for (Index f = 0; f < faces.size(); ++f)
    if (size(f) == 3) {
      const Index h = first(f);
      convex_[f] = orient(points_[org(h)], points_[org(h + 1)], points_[org(h + 2)]) == POSITIVE;
    }
}

// At each vertex, no corner holds a ray of another (file comment of subdivision.hpp).
void Subdivision::check_corners() const {
  for (Index v = 0; v < points_.size(); ++v) {
    const auto C = corners(v);
    for (const Corner& c : C) {
      const Index h = first(c.face) + c.k;
      const Point &u = points_[org(prev(h))], &w = points_[dest(h)];
      for (const Corner& o : C) {
        if (o.face == c.face) continue;
        const Index g = first(o.face) + o.k;
        for (const Index r : {dest(g), org(prev(g))})
          if (in_corner(u, points_[v], w, points_[r]))
            throw MapError(o.face, fmt::format("at its vertex {} the face overlaps face {}", o.k, c.face));
      }
    }
  }
}

}  // namespace t2
