#pragma once
// Exercise 10c: the API you implement in band.cpp. Do not change this file.
#include <vector>

#include <t2/kernel/point.hpp>

namespace ex10c {

// The sites P: points of T², at least one in front (w > 0) and one behind (w < 0), none on Ω
// (w = 0), pairwise different in T² (a site and its antipode may both be sites), not all on one
// line of T². The drawn position of a site [w, x, y] is its Cartesian point (x/w, y/w): for a
// back site, where its antipode is (chapter 10, section 8 writes it b̄).

/// The owners of the point z = [0, ux, uy] of Ω (chapter 10, section 8, Lemma 1): {a, b}, with
/// a the front site whose drawn position A is extreme in the direction u (largest u · A) and b
/// the back site whose drawn position B̄ is extreme in the direction −u (smallest u · B̄).
/// Throws t2::Undefined when two front sites tie for a, or two back sites tie for b: z is then a
/// break, a Voronoi vertex on Ω.
std::vector<long> owners(const std::vector<t2::Point>& P, const t2::Point& z);

/// The band across Ω (chapter 10, section 8, Definition and Theorem 2): three indices into P per
/// face, the faces in any order, each face in any rotation of the order given here.
///
/// The hull edges of one side are those of its drawn positions, counter-clockwise as drawn,
/// through every site on the hull's boundary (a site inside a hull edge splits it in two); if
/// the side's sites lie on one line, sorted along it s0, s1, …, sk, they are s0 → s1 → … → sk and
/// back, sk → … → s0 (2k edges); one site has none. Then the band has one face per hull edge:
/// - for a front hull edge a1 → a2: (a2, a1, b), b the *back owner* of the edge: the back site
///   whose drawn position lies farthest to the left of the directed line a1 → a2 (the owner at
///   the edge's outer normal n: smallest n · B̄); among equally far ones, the farthest in the
///   direction a1 → a2;
/// - for a back hull edge b1 → b2 (as drawn: b̄1 → b̄2): (b1, b2, a), a the *front owner* of the
///   edge: the front site farthest to the left of the directed line b̄1 → b̄2 (the owner at −n,
///   n the edge's outer normal as drawn); among equally far ones, the farthest in the direction
///   b̄2 → b̄1.
/// (The ties are those of a front and a back break at one point of Ω: walking u counter-clockwise
/// around Ω, the front break is taken first.) Every face is returned, also a face that turns
/// clockwise (t2::orient < 0: then the sites have a hull, and t2::delaunay puts v∞ in its place).
/// A face with t2::orient = 0 is *flat*: its third vertex is drawn on the line of its edge. If
/// it is drawn at an end of the edge (the antipode of a1 or a2, of b1 or b2), the flat face is
/// returned; else the band is undefined: throws t2::Undefined.
std::vector<long> band(const std::vector<t2::Point>& P);

}  // namespace ex10c
