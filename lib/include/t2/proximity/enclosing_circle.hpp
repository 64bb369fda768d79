#pragma once
/// @file enclosing_circle.hpp
/// @brief The smallest enclosing circle of sites of T² by Welzl's randomized algorithm
/// (seed 003 §4.3.4.1; E. Welzl 1991, in the iterative form of de Berg et al. §4.7), in
/// expected O(n) exact predicates.
///
/// **The definition in T².** A circle of T² has a proper centre z and a radius r in T¹, with
/// the distances of chapter 03 (distance.hpp); its closed disk is {p : d(z, p) ≤ r}. The
/// smallest enclosing circle of S is the one whose centre minimizes max_{s ∈ S} d(z, s) in the
/// T¹ order, the radius being that maximum. So:
///  - *All sites proper and on one side σ:* a centre on side σ gives the Euclidean maximum of
///    the drawn positions, finite; one on side −σ gives a radius beyond infinity, larger. The
///    answer is the classic smallest circle of the drawn positions, centred on side σ (for
///    front sites, exactly the planar answer; for back sites, the antipode of the planar
///    answer of their drawn positions). Its disk is in_disk's (incircle.hpp): points of side σ
///    only.
///  - *Sites on both sides (and maybe on Ω):* every proper centre has a radius beyond
///    infinity, [−1, t] with t = min over the sites s of the other side of |Z − S̄|² (drawn
///    positions). Moving the centre away makes t grow without bound: the radius decreases
///    towards +∞ and never reaches it. No minimum: undefined.
///  - *A site on Ω, the proper sites on one side σ or none:* a centre on side σ (on either
///    side when there are no proper sites) is at +∞ from the Ω site and finite from the
///    others, so its radius is +∞; a centre on side −σ has a radius beyond infinity. The
///    minimum +∞ is reached by a whole side of centres, and no circle is *the* smallest.
///    Undefined.
/// Such sets can lie in an open hemisphere of the sphere, but no disk of T² with a proper
/// centre holds them with a least radius. Note that the homogeneous inequality
/// (x − X·w)² + (y − Y·w)² ≤ r²w² of a Euclidean disk holds for p and ¬p alike: it describes a
/// pair of antipodal disks, which is not a disk of the T² distances (a point of the other side
/// is beyond infinity from the centre, outside every finite radius). The library follows the
/// distances, and therefore in_disk.
///
/// **Exactness.** Every decision is the sign of a polynomial in the input coordinates, through
/// the filtered predicates: `in_circle` for the circle through three sites (kept
/// counter-clockwise, so that its sign is in_disk's), and for the circle with diameter ab the
/// sign of (P − A)·(P − B), read homogeneously as
/// Σ (p·a_w − a·p_w)(p·b_w − b·p_w) (the positive factor p_w²a_wb_w dropped). No centre or
/// radius is constructed in doubles; the centre of the answer is built once, with GMP integers
/// and no division (circle.hpp's circumcentre, or |b_w|a + |a_w|b for a diameter).
///
/// **Determinism.** The sites are shuffled by a Fisher–Yates shuffle driven by a fixed-seed
/// std::mt19937_64 (reduction by `%`, not std::uniform_int_distribution, whose algorithm the
/// standard leaves to each library), so the same input gives the same support on every platform.
/// The circle itself is unique. Which of several cocircular sites make up `support` is decided
/// after the circle is found, by the same shuffle and the same three loops run on the sites of
/// the circle alone, in input order: so the support depends on the sites, not on the order of
/// the run, and Shamos's and Bhattacharya–Toussaint's algorithms (enclosing_circle_voronoi.hpp)
/// give the same one. Welzl's move-to-front heuristic is not used: the expected O(n) bound
/// (chapter 12, Theorem 7, by backwards analysis) is proved for a uniformly random order, which
/// moving sites would spoil.

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

/// The smallest enclosing circle of sites of T² (file comment).
struct EnclosingCircle {
  using Index = std::uint32_t;  ///< site indices
  /// The 1, 2 or 3 sites that define it, ascending: one site (or two equal ones) when all sites
  /// are equal (radius zero), two ends of a diameter, or three sites on the circle that are not
  /// on one half of it. Chosen among `on_circle` as the file comment says (Determinism).
  std::vector<Index> support;
  /// The centre [W, X, Y]: exact integers with no common factor, W ≠ 0 of the sites' sign.
  ExactPoint center{Integer(1), Integer(0), Integer(0)};
  /// The squared Euclidean radius of the drawn circle, |C − S|² for a site s on it.
  Rational radius2;
  /// Every site on the circle (at distance exactly the radius from the centre), ascending.
  std::vector<Index> on_circle;
};

/// The smallest enclosing circle is undefined for these sites (file comment): `site` and
/// `other` are a front and a back site, or else `site` = `other` is a site on Ω.
class UndefinedEnclosing : public Undefined {
 public:
  /// @param site, other the sites the rule names (other = site when one suffices)
  /// @param rule the message: which rule of the file comment leaves the circle undefined
  UndefinedEnclosing(std::uint32_t site, std::uint32_t other, const std::string& rule)
      : Undefined(rule), site(site), other(other) {}
  std::uint32_t site;   ///< the input index of the first site the rule names
  std::uint32_t other;  ///< the second, or `site` again
};

/// The smallest enclosing circle of `points` by Welzl's algorithm (file comment): expected
/// O(n) predicates for any input order (the shuffle), O(n) memory. Throws `BadInput` for no
/// sites or more than 2³² − 2, `UndefinedEnclosing` for sites on both sides (the first front
/// and the first back site) or else a site on Ω (the first).
EnclosingCircle smallest_enclosing_circle(std::span<const Point> points);

/// The same, telling `hook` (trace/hook.hpp) every disk (`Event::enclose`, the defining sites)
/// and every test of a site against it (`Event::in_disk`, with its sign), in input indices.
/// Only this overload carries trace code; the one above has none.
EnclosingCircle smallest_enclosing_circle(std::span<const Point> points,
                                          const trace::AnyHook& hook);

}  // namespace t2
