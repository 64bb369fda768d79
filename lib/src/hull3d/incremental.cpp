// The incremental 3-D hull with conflict lists (seed 004 §8; Clarkson and Shor; Barber, Dobkin
// and Huhdanpaa's Quickhull order). Every outside point waits in the list of one face it sees;
// inserting p deletes the faces p sees, closes the hole with a cone of new faces from p, and
// hands the waiting points of the deleted faces to the new faces they see (or drops them: they
// are inside). Lemma (why the new faces suffice): if q sees a deleted face f and lies outside
// H' = conv(H ∪ {p}), the segment from q to a point y inside f meets H only at y, and y is
// interior to H' (p sees f strictly); so the segment leaves H' through a face of ∂H' \ H, which
// is a new face, and q sees it.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "t2/hull3d/convex_hull_3d.hpp"
#include "t2/hull3d/degenerate.hpp"

namespace t2 {

namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// Face (v0, v1, v2), counter-clockwise seen from outside; nb[k] is the face across the edge
// v[k] -> v[k+1]; `head` starts the list of the points waiting on this face (they see it).
struct Face {
  std::uint32_t v[3];
  std::uint32_t nb[3];
  std::uint32_t head = kNone;
  std::uint32_t visible_at = 0, hidden_at = 0;  // insertion stamps of the visibility search
  bool alive = true;
};

class Builder {
 public:
  explicit Builder(std::span<const Point3> P) : P_(P), next_(P.size(), kNone), conflict_(P.size(), kNone), start_(P.size(), kNone) {}

  // The tetrahedron of four affinely independent points; every other point waits on a face it sees.
  void start(std::array<std::uint32_t, 4> s) {
    auto [a, b, c, d] = s;
    if (orient3d(P_[a], P_[b], P_[c], P_[d]) == POSITIVE) std::swap(b, c);
    const std::uint32_t tri[4][3] = {{a, b, c}, {a, d, b}, {b, d, c}, {c, d, a}};
    for (auto& t : tri) F_.push_back(Face{{t[0], t[1], t[2]}, {kNone, kNone, kNone}});
    for (std::uint32_t f = 0; f < 4; ++f)
      for (int k = 0; k < 3; ++k)
        for (std::uint32_t g = 0; g < 4; ++g)
          for (int j = 0; j < 3; ++j)
            if (F_[g].v[j] == F_[f].v[(k + 1) % 3] && F_[g].v[(j + 1) % 3] == F_[f].v[k]) F_[f].nb[k] = g;
    for (std::uint32_t q = 0; q < P_.size(); ++q) {
      if (q == a || q == b || q == c || q == d) continue;
      for (std::uint32_t f = 0; f < 4; ++f)
        if (sees(q, f)) {
          wait(q, f);
          break;
        }
    }
  }

  bool outside(std::uint32_t q) const { return conflict_[q] != kNone; }

  // Quickhull's order: while a face has waiting points, insert the farthest from its plane.
  void farthest_first() {
    std::vector<std::uint32_t> stack(F_.size());
    std::iota(stack.begin(), stack.end(), 0u);
    while (!stack.empty()) {
      const std::uint32_t f = stack.back();
      stack.pop_back();
      if (!F_[f].alive || F_[f].head == kNone) continue;
      std::uint32_t best = F_[f].head;
      double far = -1;
      for (std::uint32_t q = F_[f].head; q != kNone; q = next_[q]) {
        const double h = volume6(P_[F_[f].v[0]], P_[F_[f].v[1]], P_[F_[f].v[2]], P_[q]);
        if (h > far) far = h, best = q;
      }
      insert(best);
      for (std::uint32_t g : cone_)
        if (F_[g].head != kNone) stack.push_back(g);
    }
  }

  // Inserts p, which sees the face it waits on.
  void insert(std::uint32_t p) {
    //> hull3-insert
    ++stamp_;
    visible_.assign(1, conflict_[p]);
    F_[conflict_[p]].visible_at = stamp_;
    for (std::size_t i = 0; i < visible_.size(); ++i)  // the faces p sees: a connected set
      for (std::uint32_t g : F_[visible_[i]].nb) {
        if (F_[g].visible_at == stamp_ || F_[g].hidden_at == stamp_) continue;
        if (sees(p, g)) {
          F_[g].visible_at = stamp_;
          visible_.push_back(g);
        } else {
          F_[g].hidden_at = stamp_;
        }
      }
    cone_.clear();
    for (std::uint32_t f : visible_)  // a new face (a, b, p) on each horizon edge a -> b
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t g = F_[f].nb[k];
        if (F_[g].visible_at == stamp_) continue;
        const std::uint32_t a = F_[f].v[k], b = F_[f].v[(k + 1) % 3], h = new_face(a, b, p);
        F_[h].nb[0] = g;
        for (std::uint32_t& x : F_[g].nb)
          if (x == f) x = h;
        start_[a] = h;
        cone_.push_back(h);
      }
    for (std::uint32_t h : cone_) {  // (a, b, p) and (b, c, p) share the edge b -> p
      const std::uint32_t next = start_[F_[h].v[1]];
      F_[h].nb[1] = next;
      F_[next].nb[2] = h;
    }
    //< hull3-insert
    conflict_[p] = kNone;
    for (std::uint32_t f : visible_) {  // hand the waiting points over, delete the face
      for (std::uint32_t q = F_[f].head, after; q != kNone; q = after) {
        after = next_[q];
        conflict_[q] = kNone;
        if (q == p) continue;
        for (std::uint32_t h : cone_)
          if (sees(q, h)) {
            wait(q, h);
            break;
          }
      }
      F_[f].alive = false;
      F_[f].head = kNone;
      free_.push_back(f);
    }
  }

  std::vector<Triangle3> triangles() const {
    std::vector<Triangle3> T;
    for (const Face& f : F_)
      if (f.alive) T.push_back({f.v[0], f.v[1], f.v[2]});
    return T;
  }

 private:
  bool sees(std::uint32_t q, std::uint32_t f) const {
    const Face& x = F_[f];
    return orient3d(P_[x.v[0]], P_[x.v[1]], P_[x.v[2]], P_[q]) == POSITIVE;
  }
  void wait(std::uint32_t q, std::uint32_t f) {
    next_[q] = F_[f].head;
    F_[f].head = q;
    conflict_[q] = f;
  }
  std::uint32_t new_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Face f{{a, b, c}, {kNone, kNone, kNone}};
    if (free_.empty()) {
      F_.push_back(f);
      return static_cast<std::uint32_t>(F_.size() - 1);
    }
    const std::uint32_t h = free_.back();
    free_.pop_back();
    F_[h] = f;
    return h;
  }

  std::span<const Point3> P_;
  std::vector<Face> F_;
  std::vector<std::uint32_t> next_, conflict_, start_, visible_, cone_, free_;
  std::uint32_t stamp_ = 0;
};

// A fixed pseudo-random permutation (splitmix64 and Fisher-Yates: the same on every machine).
std::vector<std::uint32_t> shuffled(std::size_t n) {
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::uint64_t s = 0x9E3779B97F4A7C15u;
  for (std::size_t i = n; i > 1; --i) {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    std::swap(order[i - 1], order[(z ^ (z >> 31)) % i]);
  }
  return order;
}

// Quickhull's start: the extremes in x, the point farthest from their line, the point
// farthest from their plane (rounded distances: a choice, not a decision), if exactly
// independent; otherwise the first simplex in index order.
std::array<std::uint32_t, 4> wide_simplex(std::span<const Point3> P) {
  std::vector<std::uint32_t> all(P.size());
  std::iota(all.begin(), all.end(), 0u);
  if (P.size() < 4) return first_simplex(P, all);
  std::uint32_t a = 0, b = 0;
  for (std::uint32_t i = 0; i < P.size(); ++i) {
    if (P[i].x < P[a].x) a = i;
    if (P[i].x > P[b].x) b = i;
  }
  const Point3 u{P[b].x - P[a].x, P[b].y - P[a].y, P[b].z - P[a].z};
  std::uint32_t c = a, d = a;
  double best = -1;
  for (std::uint32_t i = 0; i < P.size(); ++i) {
    const Point3 w{P[i].x - P[a].x, P[i].y - P[a].y, P[i].z - P[a].z};
    const double cx = u.y * w.z - u.z * w.y, cy = u.z * w.x - u.x * w.z, cz = u.x * w.y - u.y * w.x;
    const double h = cx * cx + cy * cy + cz * cz;
    if (h > best) best = h, c = i;
  }
  best = -1;
  for (std::uint32_t i = 0; i < P.size(); ++i) {
    const double h = std::abs(volume6(P[a], P[b], P[c], P[i]));
    if (h > best) best = h, d = i;
  }
  if (!collinear(P[a], P[b], P[c]) && orient3d(P[a], P[b], P[c], P[d]) != ZERO) return {a, b, c, d};
  return first_simplex(P, all);
}

}  // namespace

Facets incremental_3d(std::span<const Point3> P, bool farthest_first) {
  require_finite(P);
  Builder B(P);
  if (farthest_first) {
    B.start(wide_simplex(P));
    B.farthest_first();
  } else {
    const std::vector<std::uint32_t> order = shuffled(P.size());
    B.start(first_simplex(P, order));
    for (std::uint32_t p : order)
      if (B.outside(p)) B.insert(p);
  }
  std::vector<Triangle3> T = B.triangles();
  // Of equal points, the smallest index is the vertex.
  auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x + 0.0); };  // −0 is 0
  auto hash = [&](const Point3& p) { return bits(p.x) * 0x9E3779B97F4A7C15u ^ bits(p.y) * 0xC2B2AE3D27D4EB4Fu ^ bits(p.z); };
  auto eq = [](const Point3& p, const Point3& q) { return same_point(p, q); };
  std::unordered_map<Point3, std::uint32_t, decltype(hash), decltype(eq)> smallest(16, hash, eq);
  for (const auto& t : T)
    for (std::uint32_t v : t) smallest.emplace(P[v], v);
  for (std::uint32_t i = 0; i < P.size(); ++i)
    if (auto it = smallest.find(P[i]); it != smallest.end() && i < it->second) it->second = i;
  for (auto& t : T)
    for (std::uint32_t& v : t) v = smallest.at(P[v]);
  return merge_coplanar(P, T);
}

}  // namespace t2
