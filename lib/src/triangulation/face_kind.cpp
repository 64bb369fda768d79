// The shared face record of the T² triangulations (face_kind.hpp): the kind of a face and the
// exact side of its edges, antipodal edges included.
#include "t2/triangulation/face_kind.hpp"

#include <stdexcept>

#include "t2/kernel/orient.hpp"
#include "t2/triangulation/antipodal_edge.hpp"
#include "t2/triangulation/triangulation.hpp"

namespace t2 {

FaceKind face_kind(const Triangulation& tr, std::uint32_t t) {
  if (tr.is_infinite(t)) return FaceKind::infinite;
  return face_kind(tr.point(tr.vertex(t, 0)), tr.point(tr.vertex(t, 1)), tr.point(tr.vertex(t, 2)));
}

Sign side_of_edge(const Triangulation& tr, std::uint32_t t, int i, const Point& p) {
  const std::uint32_t a = tr.vertex(t, (i + 1) % 3), b = tr.vertex(t, (i + 2) % 3);
  const Sign o = orient(tr.point(a), tr.point(b), p);
  if (o != ZERO || !(tr.point(a) == antipode(tr.point(b)))) return o;
  for (const AntipodalEdge& e : tr.antipodal_edges()) {
    if (e.z == a && e.nz == b) return side_of_antipodal_edge(tr.points(), e, p);
    if (e.z == b && e.nz == a) return static_cast<Sign>(-side_of_antipodal_edge(tr.points(), e, p));
  }
  throw std::logic_error("side_of_edge: an antipodal edge " + std::to_string(a) + "-" + std::to_string(b) +
                         " without its record");
}

}  // namespace t2
