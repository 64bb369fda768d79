// Wrong on purpose: the planar test of chapter 05 section 2 without the fifth sign. c and d on
// opposite sides of ab and a and b on opposite sides of cd is taken to mean "they cross", and the
// crossing is taken to be the meet a×b × c×d as it comes out. In T² the lines meet twice
// (x and ¬x): half of the answers are the antipode, and segments on opposite sides of the
// sphere "cross".
#include "crossing.hpp"

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>

namespace ex05b {

namespace {

struct V {
  t2::Integer w, x, y;
};
V vec(const t2::Point& p) {
  const t2::ExactPoint e = t2::to_exact(p);
  return {e.w(), e.x(), e.y()};
}
V cross(const V& p, const V& q) { return {p.x * q.y - p.y * q.x, p.y * q.w - p.w * q.y, p.w * q.x - p.x * q.w}; }
int sign_dot(const V& p, const V& q) { return sgn(p.w * q.w + p.x * q.x + p.y * q.y); }

}  // namespace

t2::ExactPoint crossing(const t2::Point& a, const t2::Point& b, const t2::Point& c, const t2::Point& d) {
  const V A = vec(a), B = vec(b), C = vec(c), D = vec(d);
  const V L = cross(A, B), M = cross(C, D), x = cross(L, M);
  if (x.w == 0 && x.x == 0 && x.y == 0) throw t2::Undefined("one line");
  if (sign_dot(L, C) * sign_dot(L, D) > 0 || sign_dot(M, A) * sign_dot(M, B) > 0)
    throw t2::Undefined("the segments do not meet");
  return t2::ExactPoint(x.w, x.x, x.y);
}

}  // namespace ex05b
