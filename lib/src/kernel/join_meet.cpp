// The exact construction of (a ∨ b) ∧ (c ∨ d) for Cartesian points (join_meet.hpp): GMP
// integers kept from call to call, so that a reported crossing costs no allocation but its
// result's.
#include <gmp.h>

#include <algorithm>
#include <cmath>

#include "t2/kernel/join_meet.hpp"

namespace t2::detail {
namespace {

/// GMP integers initialised once per thread and reused.
struct Scratch {
  mpz_t z[14];
  Scratch() {
    for (auto& v : z) mpz_init(v);
  }
  ~Scratch() {
    for (auto& v : z) mpz_clear(v);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

/// z = v·2^s exactly, for s ≥ 53 − e where v = m·2^e, 1/2 ≤ |m| < 1 (then m·2^53 is an
/// integer below 2^53, and v·2^s is it shifted left by e − 53 + s ≥ 0 bits).
void scaled(mpz_t z, double v, int s) {
  if (v == 0) {
    mpz_set_ui(z, 0);
    return;
  }
  int e = 0;
  const double m = std::frexp(v, &e);
  mpz_set_d(z, std::ldexp(m, 53));
  mpz_mul_2exp(z, z, static_cast<mp_bitcnt_t>(e - 53 + s));
}

}  // namespace

ExactPoint exact_join_meet_cartesian(const Point& a, const Point& b, const Point& c, const Point& d) {
  // Every point times 2^s is an integer point [2^s, X, Y] (s ≥ 0, the least such). Then
  // (a × b) × (c × d) = Δ(a, b, d)·c − Δ(a, b, c)·d (the vector quadruple product), and for
  // points with one weight W, Δ(a, b, r) = W·((b − a) × (r − a)) in the plane: dropping the
  // positive factor W, the point is [(D₁ − D₂)·W, D₁·c.X − D₂·d.X, D₁·c.Y − D₂·d.Y] with
  // D₁ = (b − a) × (d − a), D₂ = (b − a) × (c − a): the same point of T² as meet(join(a, b),
  // join(c, d)) on the exact points, times a positive factor.
  int s = 0;
  for (const Point* p : {&a, &b, &c, &d})
    for (const double v : {p->x(), p->y()}) {
      if (v == 0) continue;
      int e = 0;
      (void)std::frexp(v, &e);
      s = std::max(s, 53 - e);
    }
  thread_local Scratch scratch;
  mpz_t* z = scratch.z;
  mpz_t &ax = z[0], &ay = z[1], &ux = z[2], &uy = z[3], &cx = z[4], &cy = z[5], &dx = z[6], &dy = z[7];
  mpz_t &t = z[8], &d1 = z[9], &d2 = z[10], &w = z[11], &x = z[12], &y = z[13];
  scaled(ax, a.x(), s);
  scaled(ay, a.y(), s);
  scaled(ux, b.x(), s);
  scaled(uy, b.y(), s);
  mpz_sub(ux, ux, ax);  // u = b − a
  mpz_sub(uy, uy, ay);
  scaled(cx, c.x(), s);
  scaled(cy, c.y(), s);
  scaled(dx, d.x(), s);
  scaled(dy, d.y(), s);
  const auto cross_from_a = [&](mpz_t out, mpz_t rx, mpz_t ry) {  // u × (r − a)
    mpz_sub(t, ry, ay);
    mpz_mul(out, ux, t);
    mpz_sub(t, rx, ax);
    mpz_submul(out, uy, t);
  };
  cross_from_a(d1, dx, dy);
  cross_from_a(d2, cx, cy);
  mpz_sub(w, d1, d2);
  mpz_mul_2exp(w, w, static_cast<mp_bitcnt_t>(s));
  mpz_mul(x, d1, cx);
  mpz_submul(x, d2, dx);
  mpz_mul(y, d1, cy);
  mpz_submul(y, d2, dy);
  if (mpz_sgn(w) == 0 && mpz_sgn(x) == 0 && mpz_sgn(y) == 0)
    throw Undefined("meet(l, m) is undefined when l and m are the same line");
  return ExactPoint(Integer(w), Integer(x), Integer(y));
}

}  // namespace t2::detail
