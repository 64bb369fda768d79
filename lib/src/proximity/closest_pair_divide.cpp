// The closest pair of T² by Shamos–Hoey divide and conquer (t2/proximity/closest_pair.hpp).
//
// **The filter and its proof.** Each side's distinct sites are sorted once by exact x (then y),
// the back ones drawn (antipodes); each keeps its Cartesian position rounded once, X̃ = fl(x/w),
// Ỹ = fl(y/w), so |X̃ − X| ≤ u|X| + η (u = 2⁻⁵³, η = 2⁻¹⁰⁷⁴ for an underflow). Let M be the
// largest |X̃|, |Ỹ| of the side, at most 2⁵⁰⁰ (else the filter is not used, see below). Then a
// difference D̃ = fl(X̃_a − X̃_b) is within 5uM + 3η of X_a − X_b, and δ̃ = fl(√fl(fl(D̃ₓ²) +
// fl(D̃ᵧ²))) of the best pair so far is within 20uM + 2⁻⁵³⁶ of its true length δ (√2·(5uM + 3η)
// from the differences, 3u·3M from the three roundings, 2⁻⁵³⁷ from squares that underflow).
// So with s = 2⁻⁴⁸M + 2⁻⁵⁰⁰ (32uM: the sum B = fl(δ̃ + s) loses at most u(3M + s)), every pair
// with |X_a − X_b| ≤ δ has |D̃ₓ| ≤ B, and likewise for y. The filter only *skips* pairs that are
// farther than δ; every pair it keeps is compared exactly (pair_before), so the answer is the
// exact one, ties included. Sites whose quotient leaves [−2⁵⁰⁰, 2⁵⁰⁰]: that side is answered
// from its sorted order by brute force over the pairs the (then conservative) test keeps — all
// of them — which is O(m²) but exact; no such input arises from a scene of finite doubles with
// |w| ≥ 2⁻⁵⁰⁰·max(|x|, |y|).
#include <algorithm>
#include <cmath>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/pair_distance.hpp"
#include "t2/proximity/closest_pair.hpp"
#include "t2/triangulation/delaunay_t2.hpp"
#include "pair_rules.hpp"

namespace t2 {
namespace {

using Index = Triangulation::Index;
using Pair = std::pair<Index, Index>;
constexpr Index no_site = Triangulation::none;

/// A distinct site of one side: its input index and rounded Cartesian position.
struct Site {
  double x, y;
  Index id;
};

/// The divide and conquer over the sites of one side sorted by exact x, telling `hook`
/// (NoTrace: nothing) each split, strip and pair compared.
template <class H>
class Divide {
 public:
  Divide(std::span<const Point> P, std::vector<Site> s, double M, H& hook)
      : P_(P), s_(std::move(s)), tmp_(s_.size()), hook_(hook) {
    all_ = !(M <= 0x1p500);  // infinite quotients too
    slack_ = 0x1p-48 * M + 0x1p-500;
  }

  /// The first pair of the side in the order of pair_before, or {no_site, no_site} under two sites.
  Pair run() {
    if (s_.size() >= 2) solve(0, s_.size());
    return best_;
  }

 private:
  /// Tries the pair (a, b) against the best so far, exactly; a nearer pair lowers the bound.
  void consider(const Site& a, const Site& b) {
    const bool nearer = best_.first == no_site || pair_before(P_, a.id, b.id, best_.first, best_.second);
    tell(hook_, trace::Event::compare_pair, {a.id, b.id}, {}, nearer ? POSITIVE : ZERO);
    if (!nearer) return;
    best_ = {std::min(a.id, b.id), std::max(a.id, b.id)};
    const double dx = a.x - b.x, dy = a.y - b.y;
    if (!all_) bound_ = std::sqrt(dx * dx + dy * dy) + slack_;
  }
  /// The filter: |d| within the bound (always, out of the filter's range).
  bool near(double d) const { return all_ || std::abs(d) <= bound_; }

  //> closest-pair-divide
  /// Solves s_[lo, hi) (sorted by x on entry, by ỹ on return).
  void solve(std::size_t lo, std::size_t hi) {
    const auto by_y = [](const Site& a, const Site& b) { return a.y < b.y; };
    if (hi - lo <= 3) {
      for (std::size_t i = lo; i < hi; ++i)
        for (std::size_t j = i + 1; j < hi; ++j) consider(s_[i], s_[j]);
      std::sort(s_.begin() + lo, s_.begin() + hi, by_y);
      return;
    }
    const std::size_t mid = lo + (hi - lo) / 2;
    const double xm = s_[mid].x;  // the dividing line: x̃ of the first site on the right
    const Index line = s_[mid].id;
    tell_sites(trace::Event::split, line, lo, hi, s_);
    solve(lo, mid);
    solve(mid, hi);
    const auto first = s_.begin() + lo, middle = s_.begin() + mid, last = s_.begin() + hi;
    std::merge(first, middle, middle, last, tmp_.begin() + lo, by_y);
    std::copy(tmp_.begin() + lo, tmp_.begin() + hi, s_.begin() + lo);
    // The strip: the sites within the bound of the line, by ỹ; each against those above it
    // within the bound (at most 7 of them in exact terms, chapter 12).
    std::size_t k = lo;
    for (std::size_t i = lo; i < hi; ++i)
      if (near(s_[i].x - xm)) tmp_[k++] = s_[i];
    tell_sites(trace::Event::strip, line, lo, k, tmp_);
    for (std::size_t i = lo; i < k; ++i)
      for (std::size_t j = i + 1; j < k && near(tmp_[j].y - tmp_[i].y); ++j)
        consider(tmp_[i], tmp_[j]);
  }
  //< closest-pair-divide

  /// Tells the hook of the sites v[lo, hi) (their input indices lent as the chain).
  void tell_sites(trace::Event e, Index at, std::size_t lo, std::size_t hi, const std::vector<Site>& v) {
    if constexpr (trace::traced<H>) {
      std::vector<std::size_t> ids;
      for (std::size_t i = lo; i < hi; ++i) ids.push_back(v[i].id);
      hook_(trace::about(e, {at}, ids));
    }
  }

  std::span<const Point> P_;
  std::vector<Site> s_, tmp_;
  H& hook_;
  bool all_ = false;  ///< no filter: the quotients leave its range
  double slack_ = 0, bound_ = INFINITY;
  Pair best_{no_site, no_site};
};

/// The closest pair of one side's sites `list` (as front points `F`, parallel to `list`);
/// records equal sites in `kept`.
template <class H>
Pair side_pair(std::span<const Point> P, const std::vector<Index>& list, const std::vector<Point>& F,
               std::vector<Index>& kept, H& hook) {
  std::vector<Index> order(list.size());
  for (Index k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    const Sign c = compare_xy(F[a], F[b]);
    return c != ZERO ? c == NEGATIVE : a < b;
  });
  std::vector<Site> s;
  s.reserve(order.size());
  double M = 0;
  for (std::size_t m = 0; m < order.size(); ++m) {
    const Index k = order[m];
    if (m > 0 && compare_xy(F[order[m - 1]], F[k]) == ZERO) {  // equal: the first (smallest index) kept
      kept[list[k]] = kept[list[order[m - 1]]];
      continue;
    }
    const double x = F[k].x() / F[k].w(), y = F[k].y() / F[k].w();
    M = std::max({M, std::abs(x), std::abs(y)});
    s.push_back({x, y, list[k]});
  }
  return Divide<H>(P, std::move(s), M, hook).run();
}

template <class H>
Pair divide_pair(std::span<const Point> P, H& hook) {
  if (P.size() < 2) throw BadInput("closest_pair: needs at least two sites");
  if (P.size() > Triangulation::none) throw BadInput("closest_pair: too many sites for 32-bit indices");
  const Index n = static_cast<Index>(P.size());
  std::vector<Index> kept(n), front, back, omega;
  for (Index k = 0; k < n; ++k) {
    kept[k] = k;
    (P[k].w() > 0 ? front : P[k].w() < 0 ? back : omega).push_back(k);
  }
  std::vector<Point> F, B;
  for (Index k : front) F.push_back(P[k]);
  for (Index k : back) B.push_back(antipode(P[k]));
  const Pair pf = side_pair(P, front, F, kept, hook), pb = side_pair(P, back, B, kept, hook);
  if (!omega.empty()) {
    Triangulation merged;
    detail::omega_order(P, omega, merged);
    for (auto [d, k] : merged.duplicates()) kept[d] = k;
  }
  Pair best = detail::equal_sites_pair(kept);
  if (best.first != no_site) return best;
  best = pf;
  if (pb.first != no_site && (best.first == no_site || pair_before(P, pb.first, pb.second, best.first, best.second)))
    best = pb;
  if (best.first != no_site) return best;
  return detail::pair_without_finite_distance(P, omega.empty() ? no_site : omega.front());
}

}  // namespace

Pair closest_pair_divide(std::span<const Point> P) {
  NoTrace none;
  return divide_pair(P, none);
}

Pair closest_pair_divide(std::span<const Point> P, const trace::AnyHook& hook) {
  return divide_pair(P, hook);
}

}  // namespace t2
