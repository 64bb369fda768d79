#pragma once
/// @file empty_circle.hpp
/// @brief The largest empty circle of sites of T² with a proper centre (seed 000 §5.5,
/// Algorithm 13; seed 003 §4.3.4): the centre in the convex hull of the sites, from the
/// Voronoi vertices in the hull and the crossings of Voronoi edges with the hull's edges.
///
/// **The definition in T².** A circle has a proper centre z and a radius in T¹ (distance.hpp);
/// it is *empty* when no site is strictly nearer to z than the radius, so the largest empty
/// circle centred at z has radius r(z) = min_{s ∈ S} d(z, s). Without a constraint r grows
/// without bound; the classic problem keeps z in the convex hull of the sites. In T² the hull
/// is the convex hull of chapter 07, and a *proper centre* is a proper point of it (w ≠ 0).
/// The answer maximizes r(z) over the proper centres.
///  - *All sites proper, on one side σ:* the hull is the planar hull of their drawn positions,
///    on side σ, and d(z, s) is Euclidean there: the classic answer of the drawn positions,
///    centred on side σ (for back sites, the antipode of the front answer of the mirrored
///    sites ¬s, as in enclosing_circle.hpp).
///    - Not collinear: Algorithm 13 below.
///    - Collinear (at least two distinct sites): the hull is a segment, and the centre is the
///      midpoint of the widest gap between consecutive sites along it.
///    - All sites equal: the hull is one point, the site itself, at distance 0 from a site: no
///      circle is empty with a positive radius. Undefined.
///  - *A site on Ω, or sites on both sides:* the hull holds a segment from a proper site to a
///    point of Ω (the T² segment from a front site to a back one crosses Ω), and so proper
///    centres arbitrarily far, as drawn, from every site of their side; the distances to the
///    other side's sites are beyond infinity, larger still. r(z) has no maximum. Undefined.
///
/// **Why the candidates suffice** (chapter 12). In one Voronoi cell V(s) the radius is |Z − S|,
/// a convex function of Z, so its maximum over the convex polygon V(s) ∩ hull is at a corner of
/// that polygon: a Voronoi vertex in the hull, a crossing of a Voronoi edge with a hull edge, or
/// a hull vertex (a site: radius 0). Collinear sites: the same on the segment.
///
/// **Exactness.** The candidates are rational points, computed with GMP rationals and no
/// square root: a circumcentre of a Delaunay triangle (a Voronoi vertex), tested against the
/// hull by exact orientations; a crossing, the point A + λ(B − A) of the hull edge ab with
/// λ = (|T − A|² − |S − A|²) / 2(B − A)·(T − S) on the bisector of the Delaunay neighbours s,
/// t. The squared radii are compared as rationals.
///
/// **The tie rule.** Among the centres of largest radius, the one with the smallest drawn
/// position (X, Y) lexicographically (for back sites, of the mirrored problem).
///
/// **Cost.** The planar Delaunay triangulation, O(n log n). The triangles: sorted by a double
/// upper bound of their circumradius (proved in empty_circle.cpp; +∞ where it cannot be
/// trusted) and evaluated exactly (rational centre, O(log h) exact orientations against the h
/// hull corners) only while the bound reaches the best radius so far: O(n log n). The walks
/// along the hull edges: each step crosses one Voronoi edge (a Voronoi edge meets the hull's
/// boundary at most twice, so O(n) steps) and scans the current site's Delaunay neighbours:
/// O(n) for bounded degrees, O(Σ deg(s)²) at worst. Measured: chapter 12, section 6.

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "t2/kernel/error.hpp"
#include "t2/kernel/number.hpp"
#include "t2/kernel/point.hpp"
#include "t2/proximity/enclosing_circle.hpp"
#include "t2/trace/hook.hpp"

namespace t2 {

/// The largest empty circle with a proper centre (file comment).
struct EmptyCircle {
  using Index = std::uint32_t;  ///< site indices
  /// The centre [W, X, Y]: exact integers with no common factor, W ≠ 0 of the sites' sign.
  ExactPoint center{Integer(1), Integer(0), Integer(0)};
  /// The squared Euclidean radius of the drawn circle, |C − S|² for a site s on it.
  Rational radius2;
  /// Every site on the circle (at distance exactly the radius from the centre), ascending.
  std::vector<Index> on_circle;
};

/// The largest empty circle is undefined for these sites (file comment): `site` and `other`
/// are a front and a back site, or else `site` = `other` is a site on Ω or (all sites equal)
/// the first site. The fields and the message are those of `UndefinedEnclosing`.
class UndefinedEmptyCircle : public UndefinedEnclosing {
 public:
  using UndefinedEnclosing::UndefinedEnclosing;
};

/// The largest empty circle of `points` with its centre in their hull (file comment). Throws
/// `BadInput` for no sites or more than 2³² − 2, `UndefinedEmptyCircle` for a site on Ω (the
/// first), sites on both sides (the first front and the first back site), or all sites equal.
EmptyCircle largest_empty_circle(std::span<const Point> points);

/// The same, telling `hook` (trace/hook.hpp) every candidate it evaluates (`Event::empty_circle`,
/// in input indices): each crossing of a Voronoi edge with a hull edge, each Voronoi vertex whose
/// bound can still beat the best (also those outside the hull, with sign NEGATIVE), or each
/// midpoint of collinear sites, the circle lent exact. Only this overload carries trace code.
EmptyCircle largest_empty_circle(std::span<const Point> points, const trace::AnyHook& hook);

}  // namespace t2
