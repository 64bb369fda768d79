// The centre of the circular sweep (chapter 13): a point on no segment's line.
//
// The candidates are the points c(t) = [1, t, t²] of the parabola y = x². A line ⟨W, X, Y⟩
// holds c(t) exactly when W + X·t + Y·t² = 0: a polynomial in t that is not zero (a line has a
// nonzero coefficient), so it has at most two roots, and a one-point segment p equals ±c(t)
// for at most one t (the ratio x/w of p). So n segments rule out at most 2n of the 2n + 3
// values t = 0, ..., 2n + 2, and one of them is left. The roots are found exactly, with the
// lines' GMP coefficients: the integer roots of a quadratic are (−X ± √D) / 2Y with
// D = X² − 4WY a perfect square. O(n) operations on integers of the input's size, and t² ≤
// (2n + 2)² is exact in a double while n < 2²⁵.
#include "circular_centre.hpp"

#include <stdexcept>

#include "t2/kernel/line.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/orient.hpp"

namespace t2::detail {

bool valid_centre(const std::vector<Segment>& segments, const Point& o) {
  const Point no = antipode(o);
  for (const Segment& s : segments) {
    if (s.is_degenerate()) {
      if (s.source() == o || s.source() == no) return false;
    } else if (orient(s.source(), s.target(), o) == ZERO) {
      return false;
    }
  }
  return true;
}

namespace {

/// Marks t in `hit` when 0 ≤ t < hit.size().
void mark(const Integer& t, std::vector<bool>& hit) {
  if (sgn(t) >= 0 && t < Integer(static_cast<unsigned long>(hit.size()))) hit[t.get_ui()] = true;
}

/// Marks num / den when it is an integer (den ≠ 0).
void mark_ratio(const Integer& num, const Integer& den, std::vector<bool>& hit) {
  if (mpz_divisible_p(num.get_mpz_t(), den.get_mpz_t()) != 0) mark(Integer(num / den), hit);
}

/// Marks the integer roots of W + X·t + Y·t².
void mark_roots(const Integer& W, const Integer& X, const Integer& Y, std::vector<bool>& hit) {
  if (sgn(Y) == 0) {
    if (sgn(X) != 0) mark_ratio(Integer(-W), X, hit);
    return;  // X = Y = 0: the line at infinity holds no c(t)
  }
  const Integer D = X * X - 4 * W * Y;
  if (sgn(D) < 0 || mpz_perfect_square_p(D.get_mpz_t()) == 0) return;
  Integer root;
  mpz_sqrt(root.get_mpz_t(), D.get_mpz_t());
  const Integer den = 2 * Y;
  mark_ratio(Integer(-X + root), den, hit);
  mark_ratio(Integer(-X - root), den, hit);
}

}  // namespace

Point circular_centre(const std::vector<Segment>& segments) {
  const Point origin(1, 0, 0);
  if (valid_centre(segments, origin)) return origin;
  if (segments.size() >= (std::size_t{1} << 25)) throw std::length_error("circular sweep: too many segments");
  std::vector<bool> hit(2 * segments.size() + 3, false);
  for (const Segment& s : segments) {
    const ExactPoint a = to_exact(s.source()), b = to_exact(s.target());
    if (s.is_degenerate()) {
      // ±c(t) = a: w ≠ 0, t = x/w, and y = t²·w.
      if (sgn(a.w()) == 0 || mpz_divisible_p(a.x().get_mpz_t(), a.w().get_mpz_t()) == 0) continue;
      const Integer t = a.x() / a.w();
      if (a.y() == t * t * a.w()) mark(t, hit);
    } else {
      const ExactLine l = join(a, b);
      mark_roots(l.W(), l.X(), l.Y(), hit);
    }
  }
  for (std::size_t t = 0; t < hit.size(); ++t) {
    if (hit[t]) continue;
    const double d = static_cast<double>(t);
    const Point o(1, d, d * d);
    if (!valid_centre(segments, o)) throw std::logic_error("circular sweep: the centre search missed a root");
    return o;
  }
  throw std::logic_error("circular sweep: no centre among 2n + 3 candidates");  // impossible (file comment)
}

}  // namespace t2::detail
