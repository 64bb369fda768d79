// Wrong on purpose: the side rule misread as "front when orient(a, b, c) > 0, back when < 0"
// instead of "the sites' side when > 0, the other side when < 0": right for front sites, the
// antipode of every proper vertex of back sites.
#include "dual.hpp"

#include <map>
#include <stdexcept>
#include <utility>

#include <t2/kernel/incircle.hpp>
#include <t2/kernel/lexicographic.hpp>
#include <t2/kernel/orient.hpp>

namespace ex11b {

namespace {

using t2::Integer;

Integer det3(const Integer& a, const Integer& b, const Integer& c, const Integer& d, const Integer& e,
             const Integer& f, const Integer& g, const Integer& h, const Integer& i) {
  return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}

int side(const t2::Point& p) { return p.w() > 0 ? 1 : p.w() < 0 ? -1 : 0; }

// Exercise 11: the Voronoi vertex of the face (a, b, c).
t2::ExactPoint vertex(const t2::Point& a, const t2::Point& b, const t2::Point& c) {
  const t2::Point* v[3] = {&a, &b, &c};
  const t2::ExactPoint e[3] = {t2::to_exact(a), t2::to_exact(b), t2::to_exact(c)};
  const bool one_side = side(a) != 0 && side(a) == side(b) && side(b) == side(c);
  if (one_side && t2::orient(a, b, c) != t2::ZERO) {
    Integer R[3], X[3], Y[3], W[3];
    for (int i = 0; i < 3; ++i) {
      R[i] = e[i].x() * e[i].x() + e[i].y() * e[i].y();
      X[i] = e[i].w() * e[i].x();
      Y[i] = e[i].w() * e[i].y();
      W[i] = e[i].w() * e[i].w();
    }
    const Integer A = det3(X[0], Y[0], W[0], X[1], Y[1], W[1], X[2], Y[2], W[2]);
    const Integer B = -det3(R[0], Y[0], W[0], R[1], Y[1], W[1], R[2], Y[2], W[2]);
    const Integer C = det3(R[0], X[0], W[0], R[1], X[1], W[1], R[2], X[2], W[2]);
    if ((sgn(A) > 0) != (t2::orient(a, b, c) == t2::POSITIVE))  // "in front when counter-clockwise"
      return t2::ExactPoint(Integer(-2 * A), Integer(B), Integer(C));
    return t2::ExactPoint(Integer(2 * A), Integer(-B), Integer(-C));
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (side(*v[i]) == 0 || side(*v[i]) != side(*v[j])) continue;
    if (one_side) {  // collinear: not the pair with the third strictly between its ends
      const t2::Sign s = t2::compare_xy(*v[i], *v[k]);
      if (s != t2::ZERO && s == t2::compare_xy(*v[k], *v[j])) continue;
    }
    const t2::ExactPoint &p = e[i], &q = e[j];
    return t2::ExactPoint(Integer(0), Integer(p.y() * q.w() - p.w() * q.y()), Integer(p.w() * q.x() - p.x() * q.w()));
  }
  throw std::logic_error("no two consecutive sites on one side: not a face of proper sites");
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
    if (e < h || turn[f] != turn[g]) continue;
    const t2::Point& far = P[F[3 * g + (e % 3 + 2) % 3]];  // the site of g off the edge
    const bool same = turn[f] != 0 ? t2::in_circle(P[F[3 * f]], P[F[3 * f + 1]], P[F[3 * f + 2]], far) == t2::ZERO
                                   : same_point(centre[f], centre[g]);
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
