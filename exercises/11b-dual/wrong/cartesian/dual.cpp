// Wrong on purpose: Euclidean only. Right dual (twins, merge of equal points, edges), but each
// face's vertex is the Euclidean circumcentre of the drawn positions, as a front point: the
// back vertices come out in front, and faces on two sides or collinear throw.
#include "dual.hpp"

#include <map>
#include <stdexcept>
#include <utility>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>

namespace ex11b {

namespace {

using t2::Integer;

int side(const t2::Point& p) { return p.w() > 0 ? 1 : p.w() < 0 ? -1 : 0; }

// "The circumcentre": the Euclidean one of the drawn positions, always a front point; sites on
// two sides or collinear have none.
t2::ExactPoint vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  using t2::Rational;
  if (side(a) != side(b) || side(b) != side(c)) throw t2::Undefined("vertex(): no circumcentre");
  auto X = [](const t2::Point& p) -> Rational { return t2::to_rational(p.x()) / t2::to_rational(p.w()); };
  auto Y = [](const t2::Point& p) -> Rational { return t2::to_rational(p.y()) / t2::to_rational(p.w()); };
  const Rational a1 = 2 * (X(b) - X(a)), b1 = 2 * (Y(b) - Y(a)), c1 = X(b) * X(b) + Y(b) * Y(b) - X(a) * X(a) - Y(a) * Y(a);
  const Rational a2 = 2 * (X(c) - X(a)), b2 = 2 * (Y(c) - Y(a)), c2 = X(c) * X(c) + Y(c) * Y(c) - X(a) * X(a) - Y(a) * Y(a);
  const Rational det = a1 * b2 - a2 * b1;
  if (det == 0) throw t2::Undefined("vertex(): collinear sites have no circumcentre");
  const Rational ux = (c1 * b2 - c2 * b1) / det, uy = (a1 * c2 - a2 * c1) / det;
  const Integer d = ux.get_den() * uy.get_den();
  return t2::ExactPoint(d, Integer(ux * d), Integer(uy * d));
}

bool same_point(const t2::ExactPoint& p, const t2::ExactPoint& q) {
  return p.w() * q.x() == p.x() * q.w() && p.w() * q.y() == p.y() * q.w() && p.x() * q.y() == p.y() * q.x() &&
         sgn(p.w() * q.w() + p.x() * q.x() + p.y() * q.y()) > 0;
}

struct Dual {
  std::vector<long> twin;   // half-edge 3f + i (side F[3f+i] -> F[3f+(i+1)%3]) -> its twin
  std::vector<long> klass;  // face -> vertex number, in the order of first appearance
  std::vector<t2::ExactPoint> vertices;
};

long find(std::vector<long>& up, long f) {
  while (up[f] != f) f = up[f] = up[up[f]];  // path halving
  return f;
}

Dual dual(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  const long m = static_cast<long>(F.size() / 3);
  Dual d;
  std::map<std::pair<long, long>, long> side_of;
  for (long h = 0; h < 3 * m; ++h) side_of[{F[h], F[h - h % 3 + (h + 1) % 3]}] = h;
  d.twin.resize(3 * m);
  for (long h = 0; h < 3 * m; ++h) d.twin[h] = side_of.at({F[h - h % 3 + (h + 1) % 3], F[h]});
  std::vector<int> turn(m);
  std::vector<t2::ExactPoint> centre;
  centre.reserve(m);
  for (long f = 0; f < m; ++f) {
    const t2::Point &a = P[F[3 * f]], &b = P[F[3 * f + 1]], &c = P[F[3 * f + 2]];
    const bool one_side = side(a) == side(b) && side(b) == side(c);
    turn[f] = one_side ? static_cast<int>(t2::orient(a, b, c)) : 0;
    centre.push_back(vertex(a, b, c));
  }
  std::vector<long> up(m);
  for (long f = 0; f < m; ++f) up[f] = f;
  for (long h = 0; h < 3 * m; ++h) {  // Lemma 2, once per Delaunay edge
    const long e = d.twin[h], f = h / 3, g = e / 3;
    if (e < h) continue;
    const t2::Point& far = P[F[3 * g + (e % 3 + 2) % 3]];  // the site of g off the edge
    (void)far;
    const bool same = same_point(centre[f], centre[g]);  // one point, one vertex
    if (same) up[find(up, f)] = find(up, g);
  }
  std::vector<long> number(m, -1);
  d.klass.resize(m);
  for (long f = 0; f < m; ++f) {
    const long r = find(up, f);
    if (number[r] < 0) {
      number[r] = static_cast<long>(d.vertices.size());
      d.vertices.push_back(centre[f]);
    }
    d.klass[f] = number[r];
  }
  return d;
}

}  // namespace

std::vector<t2::ExactPoint> voronoi_vertices(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  return dual(P, F).vertices;
}

std::vector<long> voronoi_edges(const std::vector<t2::Point>& P, const std::vector<long>& F) {
  const Dual d = dual(P, F);
  std::vector<long> E;
  for (long h = 0; h < static_cast<long>(d.twin.size()); ++h) {
    const long e = d.twin[h], a = d.klass[h / 3], b = d.klass[e / 3];
    if (e < h || a == b) continue;
    E.insert(E.end(), {a, b, F[h], F[h - h % 3 + (h + 1) % 3]});
  }
  return E;
}

}  // namespace ex11b
