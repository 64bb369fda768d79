// Wrong on purpose: the walk answers `outside` as soon as the query is beyond a boundary edge, as
// if the map were one convex piece. A map in several pieces (front and back grids), or one whose
// complement is not convex as drawn, has faces that are reached only across the complement.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <t2/kernel/orient.hpp>

#include "walk.hpp"

namespace ex14 {

namespace {

using t2::Point;

class Map {
 public:
  Map(const std::vector<Point>& P, const std::vector<Triangle>& T) : P_(P), T_(T), across_(3 * T.size(), -1) {
    // Half-edge h = 3f + k runs from T[f][k] to T[f][k + 1]; its twin runs back.
    std::vector<std::pair<std::uint64_t, int>> key;
    key.reserve(3 * T.size());
    const auto pack = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
    for (int h = 0; h < int(3 * T.size()); ++h) key.emplace_back(pack(org(h), dest(h)), h);
    std::sort(key.begin(), key.end());
    for (int h = 0; h < int(3 * T.size()); ++h) {
      const auto it = std::lower_bound(key.begin(), key.end(), std::make_pair(pack(dest(h), org(h)), -1));
      if (it != key.end() && it->first == pack(dest(h), org(h))) across_[h] = it->second;
    }
    // The least face at each vertex, with its slot (faces in increasing order: the first wins).
    least_.assign(P.size(), Location{});
    for (int h = 0; h < int(3 * T.size()); ++h)
      if (least_[org(h)].face < 0) least_[org(h)] = {Location::Kind::vertex, h / 3, h % 3};
  }

  std::size_t faces() const { return T_.size(); }

  /// The answer for p when face f holds p (closed), given the three signs.
  Location answer(int f, const int s[3]) const {
    int zeros = 0, z = 0;
    for (int k = 0; k < 3; ++k)
      if (s[k] == 0) ++zeros, z += k;
    if (zeros == 0) return {Location::Kind::face, f, 0};
    if (zeros == 2) return least_[T_[f][(5 - z) % 3]];  // the vertex off the nonzero edge 3 − z
    int h = 3 * f;
    while (s[h - 3 * f] != 0) ++h;
    if (across_[h] >= 0 && across_[h] / 3 < f) h = across_[h];
    return {Location::Kind::edge, h / 3, h % 3};
  }

  /// The signs Δ(v_k, v_{k+1}, p) of face f.
  void signs(int f, const Point& p, int s[3]) const {
    for (int k = 0; k < 3; ++k) s[k] = int(t2::orient(P_[T_[f][k]], P_[T_[f][(k + 1) % 3]], p));
  }

  /// Walks from face f towards p; sets f to the face reached.
  Location walk(int& f, const Point& p) const {
    const long limit = 64 + 8 * long(std::sqrt(double(faces())));
    int s[3];
    for (long step = 0; step < limit; ++step) {
      signs(f, p, s);
      int k = 0;
      while (k < 3 && s[(k + step) % 3] >= 0) ++k;  // start at a rotating edge: no fixed cycle
      if (k == 3) return answer(f, s);
      const int h = across_[3 * f + (k + step) % 3];
      if (h < 0) return {};  // beyond the boundary: taken for the complement
      f = h / 3;
    }
    return brute(f, p);
  }

  /// Tests every face in order; sets f to the face found (unchanged when outside).
  Location brute(int& f, const Point& p) const {
    int s[3];
    for (int g = 0; g < int(faces()); ++g) {
      signs(g, p, s);
      if (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) return answer(f = g, s);
    }
    return {};
  }

 private:
  int org(int h) const { return T_[h / 3][h % 3]; }
  int dest(int h) const { return T_[h / 3][(h + 1) % 3]; }
  const std::vector<Point>& P_;
  const std::vector<Triangle>& T_;
  std::vector<int> across_;      // the twin half-edge, or −1 on the boundary
  std::vector<Location> least_;  // per vertex: the least face and slot
};

}  // namespace

std::vector<Location> locate_all(const std::vector<Point>& P, const std::vector<Triangle>& T,
                                 const std::vector<Point>& Q) {
  const Map M(P, T);
  std::vector<Location> r;
  r.reserve(Q.size());
  int f = 0;
  for (const Point& q : Q) r.push_back(T.empty() ? Location{} : M.walk(f, q));
  return r;
}

}  // namespace ex14
