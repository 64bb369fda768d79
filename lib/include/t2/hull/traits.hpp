#pragma once
/// @file traits.hpp
/// @brief What the hull algorithms ask of geometry (their traits), how they report their steps (a
/// trace), and the chart that lets a planar algorithm run on any open hemisphere of T².
///
/// **Traits.** Every hull algorithm is a template on a traits type `K` with two static members:
/// `K::orient(p, q, r)` (the sign Δ(p, q, r)) and `K::equal(p, q)` (equality in T²). The default,
/// `HullTraits`, calls the library's exact `t2::orient` and `operator==`. Traits that count
/// or record calls, or faster ones, change nothing else. ("Kernel" is kept for the library's
/// layer of predicates and for the kernel of a polygon.)
///
/// **Trace.** An algorithm reports its steps to a hook `Tr` (t2/trace/hook.hpp, the protocol
/// of every algorithm): a `trace::Report` with the event (consider, push, pop, vertex, bridge,
/// the halves of the merge), the input index it concerns and the current chain or stack. The
/// default `NoTrace` builds no report at all (bench/bench_hull.cpp measures that it costs
/// nothing).
///
/// **Chart.** The chart that lets a planar algorithm run on any open hemisphere is a kernel
/// notion (t2/kernel/chart.hpp): its order is `ChartOrder<K>`, on the traits' `orient`.

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "t2/kernel/chart.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/orient.hpp"
#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

/// The library's exact predicates: the default traits of the hull algorithms.
struct HullTraits {
  /// Δ(p, q, r), exact.
  static Sign orient(const Point& p, const Point& q, const Point& r) { return t2::orient(p, q, r); }
  /// p = q in T² (a positive multiple), exact.
  static bool equal(const Point& p, const Point& q) { return p == q; }
};

/// Thrown by the hull algorithms when the points lie in no open hemisphere, so that their hull
/// is undefined: `what()` names the points (p0, p1, ... in input order) and `witnesses()` holds
/// their indices — two antipodes, three points with an antipode on a segment, or four.
class NoHull : public Undefined {
 public:
  /// @param rule the explanation
  /// @param witnesses the indices of the points that lie in no open hemisphere
  NoHull(const std::string& rule, std::vector<std::size_t> witnesses)
      : Undefined(rule), witnesses_(std::move(witnesses)) {}
  /// The indices of the points that prevent a hull.
  const std::vector<std::size_t>& witnesses() const { return witnesses_; }

 private:
  std::vector<std::size_t> witnesses_;
};

}  // namespace t2
