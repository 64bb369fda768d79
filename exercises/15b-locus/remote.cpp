// Exercise 15b over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "locus.hpp"

#include "judge_wire.hpp"

/// Iso-rectangles on the wire: the corner a, then w and x of Δx and of Δy, then the orientation.
template <>
struct t2judge::Codec<t2::IsoRect> {
  static void put(std::string& o, const t2::IsoRect& r) {  ///< appends a, Δx, Δy, orientation
    Codec<t2::Point>::put(o, r.a());
    for (const double v : {r.dx().w(), r.dx().x(), r.dy().w(), r.dy().x()}) Codec<double>::put(o, v);
    Codec<int>::put(o, static_cast<int>(r.orientation()));
  }
  static t2::IsoRect take(std::istream& in) {  ///< reads a rectangle (throws for an invalid one)
    const t2::Point a = Codec<t2::Point>::take(in);
    const double xw = Codec<double>::take(in), xx = Codec<double>::take(in);
    const double yw = Codec<double>::take(in), yy = Codec<double>::take(in);
    const int o = Codec<int>::take(in);
    return t2::IsoRect(a, t2::T1(xw, xx), t2::T1(yw, yy), o < 0 ? t2::NEGATIVE : t2::POSITIVE);
  }
};

#ifdef T2_JUDGE_CHECKER
namespace ex15b {
std::vector<long> count(const std::vector<t2::Point>& P, const std::vector<t2::IsoRect>& R) {
  return t2judge::call<std::vector<long>>("count", P, R);
}
}  // namespace ex15b
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"count", handler(&ex15b::count)},
  };
  return t;
}
#endif
