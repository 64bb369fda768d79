#pragma once
/// @file triangulation.hpp
/// @brief A compact triangulation of points of T² with an infinite vertex v∞: flat arrays of
/// vertex and neighbour indices, insertion in a face and on an edge, edge flips, and point
/// location by a remembering stochastic walk (seed 000, §5.3, Algorithm 9).
///
/// **Storage.** Triangle t owns the slots 3t, 3t+1, 3t+2 of two arrays of 32-bit indices, as
/// the fastest planar codes store them (CGAL's triangulation data structure without pointers,
/// Delaunator's and Fade's flat arrays): `vertex(t, i)` is an index into `points()` or
/// `infinite`, and the *half-edge* `twin(3t + i)` = 3t' + j names the triangle t' across the
/// edge opposite vertex i of t *and* the slot j of t' opposite the same edge, so a flip or a
/// step of a walk never searches a triangle for its neighbour. 24 bytes per triangle, about two
/// triangles per point: 48 bytes per point, plus the points (24 bytes each) and the vertex link
/// (4 bytes each, invariant 5).
///
/// **Invariants** (checked by `valid()`, which the tests call after every construction):
///  1. Every triangle (a, b, c) with three finite vertices turns counter-clockwise:
///     orient(a, b, c) > 0 (exact), or — only in a triangulation of T² input (delaunay_t2.hpp,
///     triangulate_t2.hpp) — orient(a, b, c) = 0 with two of a, b, c antipodal (the degenerate
///     faces of seed 000's figure 5.18, lunes bounded by two half great circles), or a *flat*
///     face (figure 5.19): orient 0, no two antipodal, one vertex strictly inside the arc of
///     the other two, and no v∞ (flat faces appear only once the hull is gone). Vertex i is
///     opposite the edge (vertex(t, i+1), vertex(t, i+2)), indices mod 3.
///  2. `twin` is an involution without fixed points: twin(twin(e)) = e, and the edge opposite
///     e in its triangle has the same endpoints as the edge opposite twin(e), in reverse order.
///  3. While dimension() == 2 and the points lie in an open hemisphere (always for front
///     points), v∞ (`infinite`) is a vertex: every hull edge a → b
///     (counter-clockwise around the hull) is the finite edge of exactly one *infinite
///     triangle* (b, a, v∞), so the triangles form a triangulated sphere: with n vertices
///     (v∞ included) there are 2n − 4 triangles and 3n − 6 edges (Euler). An infinite triangle
///     (a, b, v∞) stands for the open half-plane to the left of a → b, outside the hull.
///     When no hull exists (T² input not in an open hemisphere) there is no v∞ and the finite
///     triangles alone form the triangulated sphere, with the same counts (v∞ not counted).
///  4. No vertex appears twice (duplicates are merged before they become vertices).
///  5. *The vertex link*: `face_of(v)` is a triangle that has vertex v (v∞ included), and `none`
///     for a point that is not a vertex (a merged duplicate, or not inserted yet). Every
///     operation below keeps it: an insertion sets it for the new point and the ring around
///     it, a flip for the two vertices that lose a triangle (2 stores), `rename_vertex`,
///     `renumber`, `assign` and `assemble` for what they change. It costs 4 bytes a point.
///  6. *The antipodal edges* (face_kind.hpp): every edge between antipodal vertices has exactly
///     one record in `antipodal_edges()`, which says along which half great circle it runs;
///     `rename_vertex` and `renumber` keep the records' indices. Empty for planar input.
///
/// **Queries** (triangulation_query.cpp): `edges()`, each undirected edge once as a half-edge;
/// the *star* of a vertex, `incident_faces(v)` and `neighbors(v)`, counter-clockwise around v
/// from `face_of(v)` (one step across the edge v → neighbour per triangle, no search);
/// `locate(p, hint)`, exact on all of T² (triangulation_query.cpp: the walk below with the exact
/// orient for front points in a planar triangulation, otherwise a visibility walk with the exact
/// `side_of_edge` of face_kind.hpp); `nearest_vertex(p, hint)`, a greedy walk over neighbours
/// with the exact `compare_distance`, exact in T² on the T² Delaunay (triangulation_query.cpp
/// proves when, and scans when the walk would not be).
///
/// **The remembering stochastic walk** (Devillers, Pion and Teillaud, "Walking in a
/// triangulation", 2002). From a triangle, test the edges other than the one we came through,
/// starting at a random one; cross the first edge that has p strictly on its far side; stop at
/// a triangle no edge of which separates p (p is in the closed triangle) or at an infinite
/// triangle (p is strictly outside that hull edge). *Termination on a Delaunay triangulation.*
/// Lift each point s to ŝ = (s, |s|² + ε_s) with the symbolic perturbation of delaunay.hpp;
/// the triangulation is the projection of the lower convex hull of the lifted points, and no
/// four lifted points are coplanar. Let h_t be the affine function whose graph is the plane of
/// the lifted triangle t. The lower hull is the graph of max_t h_t (a convex function), and on
/// t' it is h_t'. Crossing from t to t' through the edge e with p strictly on the t' side: h_t
/// and h_t' agree on the line of e, and h_t' ≥ h_t on the t' side with equality only if the
/// planes coincide, i.e. if the four lifted vertices were coplanar — excluded. Hence h_t(p)
/// strictly increases at every step, no triangle is visited twice and the walk ends after at
/// most (number of triangles) steps. The randomness is not needed for termination here (it is
/// for non-Delaunay triangulations, where a deterministic visibility walk can cycle); it keeps
/// the expected length short on adversarial orders.

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "t2/kernel/point.hpp"
#include "t2/kernel/sign.hpp"
#include "t2/triangulation/face_kind.hpp"

namespace t2 {

/// A triangulation of points of T² stored in flat index arrays (see the file comment).
class Triangulation {
 public:
  using Index = std::uint32_t;                     ///< vertex, triangle and half-edge indices
  static constexpr Index infinite = 0xFFFFFFFFu;  ///< the vertex index of v∞
  static constexpr Index none = 0xFFFFFFFFu;      ///< "no triangle"

  /// Where the walk found a point.
  struct Location {
    /// What the point hits.
    enum Kind {
      face,   ///< strictly inside a finite triangle, or strictly beyond the hull edge of an infinite one
      edge,   ///< in the relative interior of an edge
      vertex  ///< equal to a vertex
    } kind = face;  ///< what the point hits
    Index t = none;  ///< the triangle (for `face`, possibly infinite)
    int i = 0;       ///< `edge`: the slot opposite the edge; `vertex`: the slot of the vertex
  };

  /// An empty triangulation (dimension −1).
  Triangulation() = default;
  /// A triangulation of `points` with no triangle yet (dimension −1); the algorithms fill it.
  explicit Triangulation(std::vector<Point> points) : points_(std::move(points)) {}

  /// The input points; vertex indices refer to them.
  const std::vector<Point>& points() const { return points_; }
  /// −1 no point, 0 all points equal, 1 all points collinear (no triangle), 2 triangulated.
  int dimension() const { return dimension_; }
  /// Number of triangles, infinite ones included.
  std::size_t size() const { return v_.size() / 3; }
  /// Vertex i (0, 1, 2) of triangle t: a point index or `infinite`.
  Index vertex(Index t, int i) const { return v_[3 * t + i]; }
  /// The half-edge across the edge opposite vertex i of t: 3t' + j (see the file comment).
  Index twin(Index t, int i) const { return n_[3 * t + i]; }
  /// The triangle across the edge opposite vertex i of t.
  Index neighbor(Index t, int i) const { return n_[3 * t + i] / 3; }
  /// True when v∞ is a vertex of t.
  bool is_infinite(Index t) const {
    return v_[3 * t] == infinite || v_[3 * t + 1] == infinite || v_[3 * t + 2] == infinite;
  }
  /// The half-edge across half-edge h = 3t + i (the same as twin(t, i)).
  Index twin(Index h) const { return n_[h]; }
  /// The origin of half-edge h = 3t + i: vertex(t, i + 1) (the edge opposite slot i runs from
  /// vertex i + 1 to vertex i + 2, counter-clockwise around t).
  Index org(Index h) const { return v_[h - h % 3 + next(static_cast<int>(h % 3))]; }
  /// The destination of half-edge h: vertex(t, i + 2) = org(twin(h)).
  Index dest(Index h) const { return v_[h - h % 3 + prev(static_cast<int>(h % 3))]; }
  /// A triangle that has vertex v (`infinite` for v∞), or `none` when v is not a vertex
  /// (invariant 5; O(1)).
  Index face_of(Index v) const {
    const Index k = v + 1;  // v∞ = 0xFFFFFFFF wraps to slot 0
    return k < link_.size() ? link_[k] : none;
  }
  /// The slot of vertex v in t, or −1.
  int slot(Index t, Index v) const {
    for (int i = 0; i < 3; ++i)
      if (v_[3 * t + i] == v) return i;
    return -1;
  }

  /// The finite triangles as index triples, counter-clockwise, each rotated so that its
  /// smallest index comes first.
  std::vector<std::array<Index, 3>> finite_triangles() const;
  /// The hull edges (a, b), counter-clockwise around the hull (the interior to their left).
  std::vector<std::pair<Index, Index>> hull_edges() const;
  /// The merged duplicates as pairs (dropped index, kept index), sorted; the kept point is the
  /// one of smallest index among equal points.
  const std::vector<std::pair<Index, Index>>& duplicates() const { return duplicates_; }
  /// Bytes held by the arrays (capacities, not sizes): the memory figure of the benchmark.
  std::size_t memory_bytes() const {
    return points_.capacity() * sizeof(Point) + (v_.capacity() + n_.capacity() + link_.capacity()) * sizeof(Index) +
           duplicates_.capacity() * sizeof(duplicates_[0]) + antipodal_.capacity() * sizeof(AntipodalEdge);
  }
  /// Each undirected edge once, as the half-edge h = 3t + i with h < twin(h) (edges at v∞
  /// included: 3T/2 of them for T triangles); its endpoints are org(h) and dest(h).
  std::vector<Index> edges() const;

  class Star;
  /// The triangles around vertex v (or v∞), counter-clockwise, starting at face_of(v); empty
  /// when v is not a vertex. Triangle k is (v, n_k, n_k+1) for the neighbours of `neighbors(v)`.
  Star incident_faces(Index v) const;
  /// The vertices adjacent to v, counter-clockwise around it (v∞ among them for a hull vertex),
  /// the k-th being the vertex after v in the k-th triangle of incident_faces(v).
  Star neighbors(Index v) const;

  /// Locates any point p of T² (front, back or on Ω), exactly, from triangle `hint` (any index:
  /// taken modulo size()), in any triangulation of dimension 2 (planar, the T² Delaunay,
  /// Algorithm 9's, lunes and flat faces included). The answer: `vertex` (p is vertex(t, i)),
  /// `edge` (p is inside the edge opposite slot i of t, a face that is not flat; where flat
  /// faces lie on one another their edges overlap, and the answer is one of those that hold
  /// p), `face` with t
  /// finite (p strictly inside the proper face or lune t), or `face` with t infinite (p is
  /// outside the closed hull, strictly beyond the hull edge of t: orient > 0 with the edge
  /// (vertex(t, i + 1), vertex(t, i + 2)), i the slot of v∞; one such t when p sees several).
  /// Throws std::logic_error in dimension < 2.
  Location locate(const Point& p, Index hint = 0) const;
  /// The vertex nearest to p in T² (exact `compare_distance`; one of the nearest when several
  /// tie), for a *Delaunay* triangulation (planar or T², `delaunay`): a greedy walk over
  /// neighbours from the face that holds p, where triangulation_query.cpp proves it stops at a
  /// nearest vertex (p proper and a site on p's side); a scan of the vertices where the walk
  /// can stop short (p proper and no site on its side, or p on Ω). On another triangulation the
  /// walk returns a vertex no neighbour of which is nearer. Throws `Undefined` for p on Ω when
  /// its nearest sites include a front and a back one (compare_distance is undefined there and
  /// no site on Ω is nearer), std::logic_error in dimension < 2.
  Index nearest_vertex(const Point& p, Index hint = 0) const;
  /// The antipodal edges and how each runs (invariant 6, face_kind.hpp).
  const std::vector<AntipodalEdge>& antipodal_edges() const { return antipodal_; }
  /// Records the antipodal edge e (the constructions, when they make it).
  void add_antipodal_edge(const AntipodalEdge& e) { antipodal_.push_back(e); }
  /// Replaces the records (Algorithm 9, when a point splits an antipodal edge).
  void set_antipodal_edges(std::vector<AntipodalEdge> edges) { antipodal_ = std::move(edges); }

  /// Checks invariants 1–6 of the file comment exactly; returns an empty string or what is wrong.
  std::string validate() const;
  /// True when validate() finds nothing wrong.
  bool valid() const { return validate().empty(); }

  //> triangulation-operations
  /// Starts dimension 2 with the counter-clockwise triangle (a, b, c) and its three
  /// infinite triangles; `reserve` is the expected number of points (storage for
  /// 2·reserve triangles).
  void make_triangle(Index a, Index b, Index c, std::size_t reserve = 0);
  /// Inserts point p strictly inside triangle t (finite), or strictly outside the hull
  /// edge of the infinite triangle t. Afterwards p is vertex 0 of three triangles, whose
  /// first one is returned as t itself and the other two as the last two triangles.
  void insert_in_face(Index t, Index p);
  /// Inserts point p in the relative interior of the edge opposite vertex i of t (that
  /// edge may be a hull edge). Afterwards p is vertex 0 of four triangles: t, twin's
  /// triangle and the last two.
  void insert_on_edge(Index t, int i, Index p);
  /// Flips the edge opposite vertex i of t, shared with t' = neighbor(t, i) whose
  /// opposite vertex is d: with t = (p, q, r), the quadrilateral p, q, d, r becomes t =
  /// (p, q, d) and t' = (p, d, r). The caller guarantees that the quadrilateral is
  /// strictly convex.
  void flip(Index t, int i);
  //< triangulation-operations

  /// Locates p by the remembering stochastic walk from triangle `start` (see the file comment),
  /// with the orientation predicate `orient(p, q, r)` of the kernel and a random state `rng`.
  /// Requires dimension() == 2 and a finite p.
  template <class Orient>
  Location locate(const Point& p, Index start, Orient&& orient, std::uint32_t& rng) const;

  /// Replaces the triangles by `triangles` (vertex triples, `infinite` allowed) and links their
  /// twins by matching each directed edge u → v with the edge v → u of another triangle; sets
  /// dimension 2. Throws `std::logic_error` when an edge has no unique opposite (the triples do
  /// not form a closed oriented surface). Used by the constructions that assemble a
  /// triangulation from pieces (delaunay_t2.hpp).
  void assemble(const std::vector<std::array<Index, 3>>& triangles);
  /// Replaces the triangles by the flat arrays `vertices` (3 per triangle) and `twins` (the
  /// half-edge across each slot, linked by the caller as in the file comment); sets dimension 2.
  /// Used by the constructions built on another structure (divide.hpp, from the quad-edge;
  /// delaunay_t2.hpp, copying the planar triangulations of the two sides).
  void assign(std::vector<Index> vertices, std::vector<Index> twins) {
    v_ = std::move(vertices);
    n_ = std::move(twins);
    dimension_ = 2;
    relink();
  }
  /// Makes index `to` take the place of vertex `from` in every triangle around it (t holds
  /// `from`) and in the antipodal-edge records; used when a duplicate of smaller index arrives.
  void rename_vertex(Index t, Index from, Index to);
  /// Gives vertex k the index order[k] everywhere (triangles, duplicates) and replaces the
  /// points by a copy of `input`, where input[order[k]] is the old point k: the algorithms build
  /// on a copy of the points in insertion order, for locality, and hand back input indices.
  /// `order` and the old points are freed before the copy is made (the peak of a construction).
  void renumber(std::vector<Index> order, std::span<const Point> input);
  /// The same without a copy: the old point k moves to order[k] in place (the construction that
  /// took the caller's vector of points, delaunay.hpp).
  void renumber(std::vector<Index> order);
  /// Records that `dropped` equals `kept` (finished by `finish`).
  void add_duplicate(Index dropped, Index kept) { duplicates_.emplace_back(dropped, kept); }
  /// Sets the dimension (used by the algorithms for degenerate input).
  void set_dimension(int d) { dimension_ = d; }
  /// Resolves duplicate chains (a kept index later dropped in favour of a smaller one) and sorts
  /// the duplicate list; the algorithms call it once at the end.
  void finish();
  /// Point p of the input (no check).
  const Point& point(Index p) const { return points_[p]; }

 private:
  static int next(int i) { return i == 2 ? 0 : i + 1; }
  static int prev(int i) { return i == 0 ? 2 : i - 1; }
  void link(Index e, Index f) {
    n_[e] = f;
    n_[f] = e;
  }
  void set(Index t, Index a, Index b, Index c) {
    v_[3 * t] = a;
    v_[3 * t + 1] = b;
    v_[3 * t + 2] = c;
  }
  /// Rebuilds the vertex link (invariant 5) by a scan of the triangles.
  void relink();
  /// Sets the link of vertex v (or v∞) to triangle t.
  void set_link(Index v, Index t) { link_[v + 1] = t; }
  Index add_triangle() {
    v_.resize(v_.size() + 3);
    n_.resize(n_.size() + 3);
    return static_cast<Index>(v_.size() / 3 - 1);
  }
  /// Rebuilds the k triangles tri[0..k) as the fan (p, ring[m], ring[m+1]) around p; ext[m] is the
  /// half-edge outside the edge ring[m] → ring[m+1].
  void make_fan(Index p, const Index* ring, const Index* ext, const Index* tri, int k);
  /// Gives vertex k the index order[k] in the triangles and the duplicates.
  void renumber_indices(const std::vector<Index>& order);
  /// Moves the link of vertex k to order[k], for `count` points afterwards (a new array of
  /// 4 bytes a point while the old one is alive).
  void renumber_link(const std::vector<Index>& order, std::size_t count);

  std::vector<Point> points_;
  std::vector<Index> v_;  // 3 vertex indices per triangle
  std::vector<Index> n_;  // 3 twin half-edges per triangle
  std::vector<Index> link_;  // link_[v + 1]: a triangle of vertex v; link_[0]: of v∞ (invariant 5)
  std::vector<std::pair<Index, Index>> duplicates_;
  std::vector<AntipodalEdge> antipodal_;  // invariant 6
  int dimension_ = -1;
};

//> star
/// The star of a vertex v: its triangles (`incident_faces`) or its neighbours (`neighbors`),
/// counter-clockwise. From triangle t = (v, a, b) the next one is across the edge v–b, the
/// half-edge opposite the slot after v's: one load per step, and one `slot` search.
class Triangulation::Star {
 public:
  /// A forward iterator over the star (a circulator cut open at face_of(v)).
  class iterator {
   public:
    using value_type = Index;                           ///< a triangle or a vertex
    using difference_type = std::ptrdiff_t;             ///< unused
    using iterator_category = std::forward_iterator_tag;  ///< one pass or many
    iterator() = default;
    /// The iterator at triangle t of v's star.
    iterator(const Triangulation* tr, Index v, Index t, bool faces)
        : tr_(tr), v_(v), t_(t), first_(t), s_(t == none ? 0 : tr->slot(t, v)), faces_(faces) {}
    /// The current triangle, or the vertex after v in it.
    Index operator*() const { return faces_ ? t_ : tr_->v_[3 * t_ + next(s_)]; }
    /// The next triangle counter-clockwise around v; the end after a full turn.
    iterator& operator++() {
      t_ = tr_->n_[3 * t_ + next(s_)] / 3;
      if (t_ == first_) t_ = none;
      else s_ = tr_->slot(t_, v_);
      return *this;
    }
    /// Post-increment.
    iterator operator++(int) {
      iterator old = *this;
      ++*this;
      return old;
    }
    /// Equal at the same triangle (all ends are equal).
    bool operator==(const iterator& o) const { return t_ == o.t_; }

   private:
    const Triangulation* tr_ = nullptr;
    Index v_ = none, t_ = none, first_ = none;
    int s_ = 0;
    bool faces_ = true;
  };
  /// The star of v in tr: its triangles (`faces`) or its neighbours.
  Star(const Triangulation& tr, Index v, bool faces) : tr_(&tr), v_(v), faces_(faces) {}
  /// From face_of(v).
  iterator begin() const { return {tr_, v_, tr_->face_of(v_), faces_}; }
  /// After a full turn.
  iterator end() const { return {}; }

 private:
  const Triangulation* tr_;
  Index v_;
  bool faces_;
};
//< star

inline Triangulation::Star Triangulation::incident_faces(Index v) const { return Star(*this, v, true); }
inline Triangulation::Star Triangulation::neighbors(Index v) const { return Star(*this, v, false); }

template <class Orient>
Triangulation::Location Triangulation::locate(const Point& p, Index t, Orient&& orient, std::uint32_t& rng) const {
  //> walk
  int from = -1;  // the slot of the edge we came through: p is strictly inside it
  for (;;) {
    const Index* v = &v_[3 * t];
    const int inf = v[0] == infinite ? 0 : v[1] == infinite ? 1 : v[2] == infinite ? 2 : -1;
    if (inf >= 0) {  // only at the start, or when we stepped out of the hull
      if (from >= 0 || orient(points_[v[next(inf)]], points_[v[prev(inf)]], p) > 0)
        return {Location::face, t, inf};
      // p may lie on the line of that edge: test all three edges there
      t = n_[3 * t + inf] / 3;
      from = -1;
      continue;
    }
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    const int r = static_cast<int>(rng % 3);
    Sign o[3] = {POSITIVE, POSITIVE, POSITIVE};
    bool moved = false;
    for (int k = 0; k < 3 && !moved; ++k) {
      const int i = (r + k) % 3;
      if (i == from) continue;
      o[i] = orient(points_[v[next(i)]], points_[v[prev(i)]], p);
      if (o[i] < 0) {
        from = static_cast<int>(n_[3 * t + i] % 3);
        t = n_[3 * t + i] / 3;
        moved = true;
      }
    }
    if (moved) continue;
    const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    if (zeros == 0) return {Location::face, t, 0};
    if (zeros == 1) return {Location::edge, t, o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2};
    // the vertex off both lines
    return {Location::vertex, t, o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2};
  }
  //< walk
}

}  // namespace t2
