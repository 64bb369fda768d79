#pragma once
// The judge's wire: how a checker (trusted: the tests and their oracles, never linked with
// student code) asks the driver (the student's functions in their sandbox) for answers.
//
// One call per line, `name arg arg ...\n`, answered by one line: `R value ...\n`, or
// `E kind message\n` when the student's function threw. Doubles travel as hexadecimal floats
// (%a: exact), integers as decimal text. Each exercise's remote.cpp uses this header twice:
// compiled with T2_JUDGE_CHECKER it defines the exercise's API as calls over the wire (what the
// tests link against); compiled without, it lists the driver's table of the student's functions.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <istream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <t2/kernel/error.hpp>
#include <t2/kernel/number.hpp>
#include <t2/kernel/orient3d.hpp>
#include <t2/kernel/point.hpp>

namespace t2judge {

/// A malformed value on the wire.
struct WireError : std::runtime_error {
  using std::runtime_error::runtime_error;  ///< the message says what could not be read
};

/// Encoding (put) and decoding (take) of one value type.
template <class T, class = void>
struct Codec;

/// Writes all of `s` to the file descriptor `fd` (a pipe of the wire); false when the other
/// end is gone.
inline bool write_all(int fd, const std::string& s) {
  size_t off = 0;
  while (off < s.size()) {
    const ssize_t n = ::write(fd, s.data() + off, s.size() - off);
    if (n <= 0) return false;
    off += static_cast<size_t>(n);
  }
  return true;
}

/// Reads one space-separated token (throws WireError at the end of the line).
inline std::string token(std::istream& in) {
  std::string t;
  if (!(in >> t)) throw WireError("a value is missing");
  return t;
}

/// Doubles, exactly (hexadecimal floating point; also inf and nan).
template <>
struct Codec<double> {
  static void put(std::string& o, double v) {  ///< appends v
    char b[64];
    std::snprintf(b, sizeof b, "%a ", v);
    o += b;
  }
  static double take(std::istream& in) {  ///< reads a double
    const std::string t = token(in);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end) throw WireError("not a number: " + t.substr(0, 40));
    return v;
  }
};

/// Integers (long) and the enumerations of the exercises' APIs (as their underlying value).
template <class T>
struct Codec<T, std::enable_if_t<std::is_integral_v<T> || std::is_enum_v<T>>> {
  static void put(std::string& o, T v) { o += std::to_string(static_cast<long long>(v)) + " "; }  ///< appends v
  static T take(std::istream& in) {  ///< reads an integer
    const std::string t = token(in);
    char* end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (end == t.c_str() || *end) throw WireError("not an integer: " + t.substr(0, 40));
    return static_cast<T>(v);
  }
};

/// Big integers, in decimal.
template <>
struct Codec<t2::Integer> {
  static void put(std::string& o, const t2::Integer& v) { o += v.get_str() + " "; }  ///< appends v
  static t2::Integer take(std::istream& in) {  ///< reads a big integer
    const std::string t = token(in);
    t2::Integer v;
    if (t.size() > 100000 || v.set_str(t, 10) != 0) throw WireError("not an integer: " + t.substr(0, 40));
    return v;
  }
};

/// Points [w, x, y] of either coordinate type.
template <class T>
struct Codec<t2::BasicPoint<T>> {
  static void put(std::string& o, const t2::BasicPoint<T>& p) {  ///< appends w, x, y
    Codec<T>::put(o, p.w());
    Codec<T>::put(o, p.x());
    Codec<T>::put(o, p.y());
  }
  static t2::BasicPoint<T> take(std::istream& in) {  ///< reads w, x, y (throws Undefined for [0,0,0])
    T w = Codec<T>::take(in), x = Codec<T>::take(in), y = Codec<T>::take(in);
    return t2::BasicPoint<T>(std::move(w), std::move(x), std::move(y));
  }
};

/// Points of R³ (chapter 08): x, y, z.
template <>
struct Codec<t2::Point3> {
  static void put(std::string& o, const t2::Point3& p) {  ///< appends x, y, z
    Codec<double>::put(o, p.x);
    Codec<double>::put(o, p.y);
    Codec<double>::put(o, p.z);
  }
  static t2::Point3 take(std::istream& in) {  ///< reads x, y, z
    t2::Point3 p;
    p.x = Codec<double>::take(in);
    p.y = Codec<double>::take(in);
    p.z = Codec<double>::take(in);
    return p;
  }
};

/// Sequences: their length, then the elements.
template <class T>
struct Codec<std::vector<T>> {
  static void put(std::string& o, const std::vector<T>& v) {  ///< appends the length and elements
    Codec<long>::put(o, static_cast<long>(v.size()));
    for (const auto& e : v) Codec<T>::put(o, e);
  }
  static std::vector<T> take(std::istream& in) {  ///< reads a sequence
    const long n = Codec<long>::take(in);
    if (n < 0 || n > 10000000) throw WireError("bad length");
    std::vector<T> v;
    for (long i = 0; i < n; ++i) v.push_back(Codec<T>::take(in));
    return v;
  }
};

/// How the checker exchanges one line with the driver (set by the checker's main).
struct Channel {
  int calls = -1;    ///< the checker writes calls here
  int answers = -1;  ///< and reads answers here
  bool gone = false;       ///< the driver stopped answering (ended, crashed, killed)
  bool too_long = false;   ///< an answer longer than the limit
};
/// The checker's channel (defined in checker_main.cpp).
Channel& channel();
/// Sends one call line and returns the answer line; throws DriverGone when there is none.
std::string exchange(const std::string& line);
/// The driver stopped answering: the test cannot go on (how the driver ended decides the verdict).
struct DriverGone : std::runtime_error {
  DriverGone() : std::runtime_error("the program running your code stopped answering") {}  ///< constructs it
};

/// The checker's side: calls `name` with `args` in the driver and returns its answer, or
/// throws what the student's function threw (t2::Undefined, t2::BadInput, else runtime_error).
template <class R, class... A>
R call(const char* name, const A&... args) {
  std::string line = name;
  line += ' ';
  (Codec<std::decay_t<A>>::put(line, args), ...);
  line.back() = '\n';
  std::istringstream in(exchange(line));
  const std::string tag = token(in);
  if (tag == "R") {
    try {
      return Codec<R>::take(in);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("the answer of your code could not be read: ") + e.what());
    }
  }
  std::string kind, message;
  in >> kind;
  std::getline(in, message);
  if (!message.empty() && message[0] == ' ') message.erase(0, 1);
  if (kind == "undefined") throw t2::Undefined(message);
  if (kind == "bad_input") throw t2::BadInput(message);
  throw std::runtime_error(message);
}

/// The driver's side: one function of the exercise's API, called from a line's arguments.
using Handler = std::function<std::string(std::istream&)>;
/// The driver's table of the student's functions, by name (defined in the exercise's remote.cpp).
const std::map<std::string, Handler>& table();

/// A handler for `f`: decodes its arguments, calls it, encodes its result.
template <class R, class... A>
Handler handler(R (*f)(A...)) {
  return [f](std::istream& in) {
    std::tuple<std::decay_t<A>...> args{Codec<std::decay_t<A>>::take(in)...};
    std::string o = "R ";
    Codec<std::decay_t<R>>::put(o, std::apply(f, args));
    return o;
  };
}

}  // namespace t2judge
