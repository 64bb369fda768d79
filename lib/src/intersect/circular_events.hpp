#pragma once
// The records of the circular sweep (intersect/circular.cpp): its event points, the pieces of
// the segments, the events and what a piece knows of a crossing waiting in the heap on it.
// Private to lib/src/intersect.
#include <cstdint>
#include <vector>

#include "t2/kernel/join_meet.hpp"
#include "t2/kernel/point.hpp"

// Named: a unity build (test.sh) shares one translation unit between circular.cpp and the
// other sweeps, whose helpers have the same names.
namespace t2::circular_sweep {

inline constexpr std::uint32_t kNone = std::uint32_t(-1);

/// An event point: an input point (p) or a meet (m, when p is null), the point itself, not its
/// antipode.
struct At {
  const Point* p = nullptr;
  JoinMeet<double> m{};
};

/// Where an event is in the turn (circular.cpp's file comment).
enum Rank : std::uint8_t { kStart, kUpper, kHalf, kLower, kEnd };

/// What a piece knows of a crossing waiting in the heap that lies inside it: the crossing's
/// `id`, and `other`, a piece through that crossing on another line (kNone: none).
struct Pending {
  std::uint32_t id = kNone, other = kNone;
};

/// A piece of a segment, from its first point to its last in the turn, on the segment's line
/// la ∨ lb, oriented with o on its left.
struct Piece {
  const Point *la = nullptr, *lb = nullptr;
  At start, end;
  Rank start_rank = kStart, end_rank = kEnd;
  std::uint32_t segment = 0;
  Pending pending{};     ///< a crossing ahead inside it, or none
  bool through = false;  ///< put back at the current event: it passes through it
};

/// A crossing of pieces i < j (its number `id`, one for each push), or (crossing false) the
/// endpoint group g.
struct Event {
  At at;
  Rank rank = kStart;
  bool crossing = false;
  std::uint32_t i = 0, j = 0, id = kNone;
};

/// Endpoint events at one point: the pieces starting there and the one-point segments there.
struct Group {
  Event event;
  std::vector<std::uint32_t> starts, points;
  bool input = false;  ///< the point is an input endpoint (not only a cut point)
};

}  // namespace t2::circular_sweep
