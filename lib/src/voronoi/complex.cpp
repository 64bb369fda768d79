// The Delaunay complex of T² (t2/voronoi/complex.hpp): the planar or two-sided Delaunay
// triangulation, and the faces beyond the hull that it replaces by v∞.
#include "t2/voronoi/complex.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "t2/kernel/angle.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/delaunay_ring.hpp"

namespace t2 {

namespace {

using Index = Triangulation::Index;
using Face = std::array<Index, 3>;

/// The sites `c` (in order along a line, or around a hull edge from corner to corner) as the
/// flat polygon c₀ → c_k → c_{k−1} → … → c₁ → c₀, cut by the fan from c₀.
void flat_fan(const std::vector<Index>& c, std::vector<Face>& faces) {
  for (std::size_t i = 1; i + 1 < c.size(); ++i) faces.push_back({c[0], c[i + 1], c[i]});
}

/// The kind of the face (a, b, c) (complex.hpp): its orientation if it is proper, else ZERO.
Sign turn_of(const Point& a, const Point& b, const Point& c) {
  const Sign s = sign_of(a.w());
  if (s == ZERO || sign_of(b.w()) != s || sign_of(c.w()) != s) return ZERO;
  return orient(a, b, c);
}

/// Complex part 1 beyond the hull of the front triangulation `tr`: the farthest-point faces
/// (clockwise: kind NEGATIVE), then the flat fans (ZERO).
void add_beyond_hull(const Triangulation& tr, DelaunayComplex& out) {
  auto& faces = out.faces;
  const std::vector<Index> c = detail::boundary_cycle(tr);  // counter-clockwise, from a corner
  const auto& p = tr.points();
  const std::size_t k = c.size();
  std::vector<std::size_t> at;  // the positions of the strict corners in c
  for (std::size_t s = 0; s < k; ++s)
    if (detail::cross_of_differences(p[c[(s + k - 1) % k]], p[c[s]], p[c[s]], p[c[(s + 1) % k]]) != ZERO) at.push_back(s);
  std::vector<Point> corners;
  for (std::size_t s : at) corners.push_back(p[c[s]]);
  for (const Face& t : farthest_delaunay(corners))  // reversed: around their back vertex
    faces.push_back({c[at[t[0]]], c[at[t[2]]], c[at[t[1]]]});
  out.turns.resize(faces.size(), NEGATIVE);
  for (std::size_t j = 0; j < at.size(); ++j) {  // the sites strictly inside a hull edge
    const std::size_t end = j + 1 < at.size() ? at[j + 1] : k;
    std::vector<Index> chain;
    for (std::size_t s = at[j]; s <= end; ++s) chain.push_back(c[s % k]);
    flat_fan(chain, faces);
  }
  out.turns.resize(faces.size(), ZERO);
}

/// Links the half-edges of `out` still without a twin (`Triangulation::none`) and those of the
/// faces from `first` on, by matching each directed edge u → v with v → u among them.
void link_open(DelaunayComplex& out, std::size_t first) {
  out.twins.resize(3 * out.faces.size(), Triangulation::none);
  std::unordered_map<std::uint64_t, Index> open;  // u → v: the half-edge
  auto key = [](Index u, Index v) { return (std::uint64_t(u) << 32) | v; };
  auto ends = [&](Index h) {
    const Face& t = out.faces[h / 3];
    return std::pair{t[(h + 1) % 3], t[(h + 2) % 3]};
  };
  for (Index h = 0; h < out.twins.size(); ++h)
    if (h / 3 >= first || out.twins[h] == Triangulation::none) {
      const auto [u, v] = ends(h);
      open[key(u, v)] = h;
    }
  for (const auto& [k, h] : open) {
    const auto [u, v] = ends(h);
    const auto r = open.find(key(v, u));
    if (r == open.end()) throw std::logic_error("delaunay_complex: an edge without its reverse");
    out.twins[h] = r->second;
  }
}

/// Parts 1, 4 and 5 for sites all in front.
void front_complex(std::span<const Point> pts, DelaunayComplex& out) {
  const Triangulation tr = delaunay(pts);
  out.duplicates = tr.duplicates();
  out.dimension = tr.dimension();
  if (tr.dimension() == 2) {
    std::vector<Index> id(tr.size());  // triangle → face, none for the infinite ones
    Index nf = 0;
    for (Index t = 0; t < tr.size(); ++t) id[t] = tr.is_infinite(t) ? Triangulation::none : nf++;
    out.faces.reserve(tr.size());  // one pass over fresh memory: no zeros written first
    out.twins.reserve(3 * tr.size());
    for (Index t = 0; t < tr.size(); ++t) {
      if (id[t] == Triangulation::none) continue;
      out.faces.push_back({tr.vertex(t, 0), tr.vertex(t, 1), tr.vertex(t, 2)});
      for (int i = 0; i < 3; ++i) {
        const Index e = tr.twin(t, i), g = id[e / 3];
        out.twins.push_back(g == Triangulation::none ? Triangulation::none : 3 * g + e % 3);
      }
    }
    out.turns.assign(nf, POSITIVE);  // triangulation.hpp, invariant 1
    add_beyond_hull(tr, out);
    link_open(out, nf);  // the hull edges and the faces beyond
    return;
  }
  if (tr.dimension() < 1) return;
  std::vector<Index> c = detail::boundary_cycle(tr);  // dimension 1: p₀ … p_m … p₁
  if (c.size() < 4) return;  // two distinct sites
  c.resize(c.size() / 2 + 1);  // p₀ … p_m in order along the line
  flat_fan(c, out.faces);
  std::reverse(c.begin(), c.end());
  flat_fan(c, out.faces);
  out.turns.assign(out.faces.size(), ZERO);
  link_open(out, 0);
  out.dimension = 2;
}

//> farthest-fan
/// A triangulated convex polygon grown by Chew's insertions: faces counter-clockwise,
/// the half-edge 3t + i of face t opposite its vertex i (from vertex i + 1 to i + 2),
/// its twin, or `none` on the polygon's boundary, where `hull` records it by its origin.
struct Fan {
  std::span<const Point> P;
  std::vector<Face> f;
  std::vector<Index> twin, hull;

  Index origin(Index h) const { return f[h / 3][(h + 1) % 3]; }
  void link(Index h, Index g) {
    twin[h] = g;
    if (g == Triangulation::none) hull[origin(h)] = h;
    else twin[g] = h;
  }
  /// Face h / 3 = (p, a, b), p at slot h % 3, is new; its edge a → b may be illegal.
  /// Flip while the far corner's circle misses p: each flip gives p one more face.
  void legalize(Index h) {
    std::vector<Index> todo{h};
    while (!todo.empty()) {
      h = todo.back();
      todo.pop_back();
      const Index e = twin[h];
      if (e == Triangulation::none) continue;  // a boundary edge stays
      const Index t = h / 3, u = e / 3, i = h % 3, j = e % 3;
      const Index p = f[t][i], a = f[t][(i + 1) % 3], b = f[t][(i + 2) % 3], x = f[u][j];
      // Legal when the circle of u = (x, b, a) holds p, inside or on.
      if (in_circle(P[f[u][0]], P[f[u][1]], P[f[u][2]], P[p]) != NEGATIVE) continue;
      // The twins of b → p, p → a (in t) and a → x, x → b (in u).
      const Index A1 = twin[3 * t + (i + 1) % 3], A2 = twin[3 * t + (i + 2) % 3];
      const Index B1 = twin[3 * u + (j + 1) % 3], B2 = twin[3 * u + (j + 2) % 3];
      f[t] = {p, a, x};  // the quadrilateral p a x b is strictly convex: the diagonal p x
      f[u] = {p, x, b};
      link(3 * t, B1), link(3 * t + 1, 3 * u + 2), link(3 * t + 2, A2);
      link(3 * u, B2), link(3 * u + 1, A1);
      todo.push_back(3 * t), todo.push_back(3 * u);  // a → x and x → b, opposite p
    }
  }
  /// Corner p between the neighbours q → r of the polygon: the face (p, r, q) on q → r.
  void insert(Index q, Index p, Index r) {
    const Index t = static_cast<Index>(f.size());
    f.push_back({p, r, q});
    twin.resize(3 * f.size());
    const Index e = hull[q];  // q → r
    link(3 * t, e);
    link(3 * t + 1, Triangulation::none), link(3 * t + 2, Triangulation::none);
    legalize(3 * t);
  }
};
//< farthest-fan

/// splitmix64: a fixed stream, the same on every machine.
std::uint64_t next_random(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

//> farthest-delaunay
std::vector<std::array<Triangulation::Index, 3>> farthest_delaunay(
    std::span<const Point> corners) {
  const Index m = static_cast<Index>(corners.size());
  if (m < 3) return {};
  // Chew: take the corners out of the polygon in a random order (a fixed seed), each
  // remembering its two neighbours at that moment; the last three make a triangle.
  std::vector<Index> order(m), prev(m), next(m);
  std::uint64_t seed = 0xfa27'4e57;
  for (Index k = 0; k < m; ++k) {
    order[k] = k, prev[k] = (k + m - 1) % m, next[k] = (k + 1) % m;
    const Index j = static_cast<Index>(next_random(seed) % (k + 1));  // Fisher-Yates
    std::swap(order[k], order[j]);
  }
  std::vector<std::pair<Index, Index>> was(m);  // a corner's neighbours when taken out
  for (Index k = 0; k + 3 < m; ++k) {
    const Index p = order[k];
    was[p] = {prev[p], next[p]};
    next[prev[p]] = next[p], prev[next[p]] = prev[p];
  }
  const Index a = order[m - 1], b = next[a], c = next[b];
  Fan fan{corners, {}, std::vector<Index>(3, Triangulation::none), std::vector<Index>(m)};
  fan.f.push_back(Face{a, b, c});
  fan.hull[a] = 2, fan.hull[b] = 0, fan.hull[c] = 1;
  // Put them back in the reverse order: each between its two old neighbours, a new face
  // (p, r, q) on the polygon edge q → r, then the flips around p (Fan::legalize).
  for (Index k = m - 3; k-- > 0;) {
    const Index p = order[k];
    fan.insert(was[p].first, p, was[p].second);
  }
  return std::move(fan.f);
}
//< farthest-delaunay

DelaunayComplex delaunay_complex(std::span<const Point> points) {
  DelaunayComplex out;
  out.points.assign(points.begin(), points.end());
  std::size_t front = 0, back = 0;
  std::vector<Index> omega;
  for (Index k = 0; k < points.size(); ++k) {
    if (points[k].w() > 0) ++front;
    else if (points[k].w() < 0) ++back;
    else omega.push_back(k);
  }
  auto finish = [&] {
    std::sort(out.duplicates.begin(), out.duplicates.end());
    return std::move(out);
  };
  if (back == 0 && omega.empty()) {  // parts 1, 4, 5
    front_complex(points, out);
    return finish();
  }
  if (front == 0 && omega.empty()) {  // part 2: the mirror of ¬S
    std::vector<Point> anti;
    for (const Point& p : points) anti.push_back(antipode(p));
    DelaunayComplex a = delaunay_complex(anti);
    for (auto& t : a.faces) std::swap(t[1], t[2]);
    const Index swapped[3] = {0, 2, 1};  // the slot of each vertex after the swap
    out.twins.resize(a.twins.size());
    for (Index h = 0; h < a.twins.size(); ++h)
      out.twins[h - h % 3 + swapped[h % 3]] = a.twins[h] - a.twins[h] % 3 + swapped[a.twins[h] % 3];
    out.faces = std::move(a.faces);
    out.turns = std::move(a.turns);  // orient(p, r, q) = −orient(¬p, ¬q, ¬r) · −1: the same
    out.duplicates = std::move(a.duplicates);
    out.dimension = a.dimension;
    return finish();
  }
  Triangulation tr0;  // the distinct directions of Ω
  const std::vector<Index> z = detail::omega_order(points, omega, tr0);
  if ((front == 0 || back == 0) && z.size() >= 2)
    throw Undefined("voronoi: the " + std::string(front == 0 ? "front" : "back") +
                    " side holds no site while " + std::to_string(omega[0]) + " and other sites lie on Omega: " +
                    "that hemisphere would be shared among them by angles seen from a proper point, "
                    "which depend on the origin");
  if (detail::all_collinear_t2(points)) {  // part 5, or not built yet
    const Triangulation line = delaunay(points);
    out.duplicates = line.duplicates();
    out.dimension = line.dimension();
    if (points.size() - out.duplicates.size() <= 2) return finish();
  }
  if (detail::all_collinear_t2(points) || front == 0 || back == 0)
    throw std::runtime_error("voronoi: collinear sites on both sides, or one site on Omega with one side empty: "
                             "not built yet (issue 24)");
  const Triangulation t2 = detail::delaunay_t2(points, DelaunayTraits{}, true);  // part 3
  out.duplicates = t2.duplicates();
  for (Index t = 0; t < t2.size(); ++t) {
    const Face f{t2.vertex(t, 0), t2.vertex(t, 1), t2.vertex(t, 2)};
    if (t2.is_infinite(t)) throw std::logic_error("delaunay_complex: v-infinity in a two-sided complex");
    out.faces.push_back(f);
    out.turns.push_back(turn_of(points[f[0]], points[f[1]], points[f[2]]));
    for (int i = 0; i < 3; ++i) out.twins.push_back(t2.twin(t, i));
  }
  out.dimension = 2;
  return finish();
}

}  // namespace t2
