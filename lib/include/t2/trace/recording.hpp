#pragma once
/// @file recording.hpp
/// @brief The steps of one run of an algorithm, recorded completely before anything plays them.
///
/// Recording first and playing afterwards is what lets a player step back, jump to any step and
/// change the level of detail without running the algorithm again: every `Step` holds the whole
/// state it shows.

#include <utility>
#include <vector>

#include "t2/trace/step.hpp"

namespace t2::trace {

/// An append-only list of steps.
class Recording {
 public:
  /// Appends a step.
  void add(Step s) { steps_.push_back(std::move(s)); }
  /// Every step, in order.
  const std::vector<Step>& steps() const { return steps_; }
  /// The steps of depth at most `level`, in order (what a player shows at that level).
  std::vector<Step> at(Depth level) const {
    std::vector<Step> out;
    for (const Step& s : steps_)
      if (s.depth <= level) out.push_back(s);
    return out;
  }
  /// Number of steps.
  std::size_t size() const { return steps_.size(); }
  /// True when nothing was recorded.
  bool empty() const { return steps_.empty(); }
  /// The last step (requires a non-empty recording).
  const Step& back() const { return steps_.back(); }

 private:
  std::vector<Step> steps_;
};

}  // namespace t2::trace
