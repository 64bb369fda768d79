// Exercise 14b over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "locate.hpp"

#include "judge_wire.hpp"

/// Triangles on the wire: the three indices.
template <>
struct t2judge::Codec<ex14b::Triangle> {
  static void put(std::string& o, const ex14b::Triangle& t) {  ///< appends a, b, c
    for (const int v : t) Codec<int>::put(o, v);
  }
  static ex14b::Triangle take(std::istream& in) {  ///< reads a, b, c
    ex14b::Triangle t{};
    for (int& v : t) v = Codec<int>::take(in);
    return t;
  }
};

/// Locations on the wire: kind, face, slot.
template <>
struct t2judge::Codec<ex14b::Location> {
  static void put(std::string& o, const ex14b::Location& l) {  ///< appends kind, face, k
    Codec<int>::put(o, static_cast<int>(l.kind));
    Codec<int>::put(o, l.face);
    Codec<int>::put(o, l.k);
  }
  static ex14b::Location take(std::istream& in) {  ///< reads a location (any kind value is kept)
    ex14b::Location l;
    l.kind = static_cast<ex14b::Location::Kind>(Codec<int>::take(in));
    l.face = Codec<int>::take(in);
    l.k = Codec<int>::take(in);
    return l;
  }
};

#ifdef T2_JUDGE_CHECKER
namespace ex14b {
std::vector<Location> locate_all(const std::vector<t2::Point>& P, const std::vector<Triangle>& T,
                                 const std::vector<t2::Point>& Q) {
  return t2judge::call<std::vector<Location>>("locate_all", P, T, Q);
}
}  // namespace ex14b
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"locate_all", handler(&ex14b::locate_all)},
  };
  return t;
}
#endif
