// Hostile (issue 29, break 4): the sandbox's /usr holds Boost; Boost.Multiprecision computes the
// 2×2 minors exactly, and no t2 name is used. The compile sees only the standard library and the
// exercise's allowed headers: boost/ is not there, the code does not compile (0 points).
#include "classify.hpp"
#include <boost/multiprecision/cpp_int.hpp>
#include <cmath>
#include <stdexcept>
namespace ex01 {
namespace {
using boost::multiprecision::cpp_int;
// A double as an exact fraction n / 2^1100 (every finite double is one).
cpp_int exact(double v) {
  int e = 0;
  const double m = std::frexp(v, &e);  // v = m·2^e, |m| in [0.5, 1)
  cpp_int n = static_cast<long long>(std::ldexp(m, 60));  // exact: 53 bits of m
  const int shift = e - 60 + 1100;
  return shift >= 0 ? cpp_int(n << shift) : cpp_int(n >> -shift);
}
int parallel(const t2::Point& p, const t2::Point& q) {
  const cpp_int a[3] = {exact(p.w()), exact(p.x()), exact(p.y())}, b[3] = {exact(q.w()), exact(q.x()), exact(q.y())};
  if (a[0] * b[1] != a[1] * b[0] || a[0] * b[2] != a[2] * b[0] || a[1] * b[2] != a[2] * b[1]) return 0;
  const cpp_int dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return dot > 0 ? 1 : -1;
}
}  // namespace
Where where(const t2::Point& p) { return p.w() > 0 ? Where::front : p.w() < 0 ? Where::back : Where::infinity; }
bool same_point(const t2::Point& p, const t2::Point& q) { return parallel(p, q) > 0; }
bool antipodal(const t2::Point& p, const t2::Point& q) { return parallel(p, q) < 0; }
}  // namespace ex01
