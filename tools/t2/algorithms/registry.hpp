#pragma once
// The algorithms of the course, one registration each: `t2 animate`, `t2 bench`, their help
// texts, the benchmark worker (bench/t2_bench_worker.cpp) and the book's animations
// (book_animations.cpp) all read this list, and nothing else names an algorithm. The entries
// live in tools/t2/algorithms/*.cpp, one file per family, compiled once (the object library
// t2_algorithms) into the `t2` tool and into the worker; none of them links CGAL.
//
// How to add an algorithm `frob` of the problem "hull" (its own code in lib/, then one entry):
//
//   T2_ALGORITHM({.name = "frob", .problem = "hull",
//                 .summary = "t2's frob hull, O(n log h)",     // one line for the help texts
//                 .title = "the frob hull",                    // the page's title
//                 .run = [](const Points& P) { return hull_scene(P, t2::frob(P)); },
//                 .record = record_frob,                       // nullptr: not animated
//                 .time = [](BenchInput& in) -> Timed { return [&P = in.points] { return t2::frob(P).size(); }; },
//                 .peers = {"graham", "cgal"}});               // timed with it by default
//
// An entry in a new family file (algorithms/frob.cpp) adds that file to t2_algorithms in
// tools/t2/CMakeLists.txt. A new *problem* (what an answer is: hull vertices, triangles...) is one
// T2_PROBLEM line in its family's file, and a foreign peer (CGAL, qhull) one T2_PEER line in
// peers.cpp plus its timed run in the worker, which alone links them. tests/test_registry.cpp
// checks that the help texts, the worker and the book agree with the registry.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "t2/kernel/orient3d.hpp"
#include "t2/kernel/point.hpp"
#include "t2/kernel/scene.hpp"
#include "t2/kernel/segment.hpp"

namespace t2::trace {
class Recording;
}

namespace t2cli::algorithms {

using Points = std::vector<t2::Point>;

/// The input of one timed run, made by the worker before the clock starts: points of T² (w = 1)
/// for the problems of the plane, points of R³ for those of space, segments for those of
/// segments. A run may take them (std::move).
struct BenchInput {
  Points points;
  std::vector<t2::Point3> points3;
  std::vector<t2::Segment> segments;
};

/// One timed run, prepared (conversions done): returns the answer's size (Problem::size_word).
using Timed = std::function<std::size_t()>;

/// What a problem's input is.
enum class Input {
  plane,     ///< points of T² (the t2 gen point kinds)
  space,     ///< points of R³ (cube, sphere)
  segments,  ///< segments of the plane (`t2 gen segments`)
};

/// What an answer is.
struct Problem {
  std::string name;            ///< "hull", "delaunay", "hull3d"
  std::string size_word;       ///< what the answer's size counts: "vertices", "triangles", "layers"
  Input input = Input::plane;  ///< what it takes
};

/// An algorithm of t2: one registration (file comment).
struct Algorithm {
  // Every member has an initializer ({}): an entry names only the fields it has.
  std::string name{};     ///< the word of `t2 animate ALGO` and `t2 bench ALGO`
  std::string problem{};  ///< a registered Problem
  std::string summary{};  ///< one line for the help texts
  std::string title{};    ///< how an animation's page names it: "Graham's scan"
  /// Runs it on points of the plane; the answer as a scene (nullptr for other inputs).
  std::function<t2::Scene(const Points&)> run{};
  /// Runs it with its recorder on the points of the scene `name`, adding every step and the
  /// answer to the recording; throws t2::BadInput or t2::Undefined naming the scene. nullptr:
  /// `t2 animate` does not show it.
  std::function<void(const Points&, const std::string& name, t2::trace::Recording&)> record{};
  /// The same for a problem of segments (Input::segments): runs it with its recorder on the
  /// segments of the scene `name`, whose endpoints are the page's points 2i and 2i + 1.
  std::function<void(const std::vector<t2::Segment>&, const std::string& name, t2::trace::Recording&)>
      record_segments{};
  /// Prepares a timed run on `in` (which outlives the run); nullptr: `t2 bench` does not time it.
  std::function<Timed(BenchInput& in)> time{};
  std::vector<std::string> peers{};  ///< timed with it when `t2 bench` has no --vs
  /// True when `t2 animate` shows it (a recorder of points or of segments).
  bool animates() const { return bool(record) || bool(record_segments); }
};

/// An implementation that is not t2's, timed by `t2 bench` beside t2's algorithms; its run is
/// the worker's own (it links CGAL and qhull).
struct Peer {
  std::string name;                   ///< its name after --vs
  std::vector<std::string> problems;  ///< the problems it solves
  std::string summary;                ///< one line for the help
  bool exact = true;                  ///< exact predicates: its answer must equal t2's
  /// The same t2 code on other predicates: a peer of the algorithm named as its problem only
  /// (`hull`, `delaunay`), the one whose predicates it swaps.
  bool same_code = false;
};

void register_problem(const Problem& p);
void register_algorithm(const Algorithm& a);
void register_peer(const Peer& p);

/// Every registration, sorted by name (static registration has no order of its own).
const std::vector<Problem>& problems();
const std::vector<Algorithm>& all();
const std::vector<Peer>& peers();

const Problem* find_problem(const std::string& name);
const Algorithm* find(const std::string& name);
const Peer* find_peer(const std::string& name);

/// The algorithms `t2 animate` shows (`animates()`), and those `t2 bench` times (time given).
std::vector<const Algorithm*> animated();
std::vector<const Algorithm*> timed();

/// "a, b or c"
std::string words(const std::vector<std::string>& names, const char* last = "or");

struct Registrar {
  explicit Registrar(const Problem& p) { register_problem(p); }
  explicit Registrar(const Algorithm& a) { register_algorithm(a); }
  explicit Registrar(const Peer& p) { register_peer(p); }
};

}  // namespace t2cli::algorithms

#define T2_ALGO_CONCAT_(a, b) a##b
#define T2_ALGO_CONCAT(a, b) T2_ALGO_CONCAT_(a, b)
#define T2_ALGO_REGISTER_(type, ...)                                                       \
  static const ::t2cli::algorithms::Registrar T2_ALGO_CONCAT(t2_algorithm_, __COUNTER__){ \
      ::t2cli::algorithms::type __VA_ARGS__};
/// Registers an algorithm: T2_ALGORITHM({.name = "graham", .problem = "hull", ...});
#define T2_ALGORITHM(...) T2_ALGO_REGISTER_(Algorithm, __VA_ARGS__)
/// Registers a problem: T2_PROBLEM({"hull", "vertices", Input::plane});
#define T2_PROBLEM(...) T2_ALGO_REGISTER_(Problem, __VA_ARGS__)
/// Registers a foreign peer: T2_PEER({"cgal", {"hull", "delaunay"}, "CGAL: ...", true});
#define T2_PEER(...) T2_ALGO_REGISTER_(Peer, __VA_ARGS__)
