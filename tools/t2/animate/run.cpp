// What `t2 animate` does (run.hpp): the algorithm's registered recorder run (algorithms/*.cpp),
// the steps written as the page of page.hpp.
#include "animate/run.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/answer.hpp"
#include "algorithms/registry.hpp"
#include "animate/page.hpp"
#include "t2/kernel/error.hpp"
#include "t2/kernel/io.hpp"
#include "t2/kernel/segment.hpp"
#include "t2/trace/recording.hpp"

namespace t2cli::animate {
namespace {

// Every step is drawn twice (both models) into the page: beyond this many points the page
// grows past what a browser steps through comfortably, and the picture is unreadable anyway.
constexpr std::size_t kMaxPoints = 200;

}  // namespace

std::string write_animation(const std::string& algo, const t2::Scene& scene, const std::filesystem::path& out) {
  const algorithms::Algorithm* a = algorithms::find(algo);
  if (a == nullptr || !a->animates())
    throw std::invalid_argument(fmt::format("'{}': not an algorithm of t2 animate", algo));
  // A problem of segments: the page's points are the endpoints, 2i and 2i + 1 of segment i, and
  // every frame draws the segments.
  const bool of_segments = bool(a->record_segments);
  std::vector<t2::Point> P;
  std::vector<t2::Segment> S;
  std::vector<t2::trace::Edge> drawn;
  if (of_segments) {
    for (const auto& s : scene.segments) {  // defined: the parser checked that
      drawn.push_back({P.size(), P.size() + 1});
      P.push_back(s.a.point);
      P.push_back(s.b.point);
      S.push_back(s.segment());
    }
  } else {
    for (const auto& p : scene.points) P.push_back(p.point);
  }
  if (P.size() > kMaxPoints)
    throw t2::BadInput(fmt::format("{}: {} points: t2 animate draws every step, so at most {} points{}", scene.name,
                                   P.size(), kMaxPoints, of_segments ? " (100 segments)" : ""));
  t2::trace::Recording rec;
  const std::string range =
      of_segments ? (S.empty() ? "no segment" : fmt::format("{} segments, s0 to s{}", S.size(), S.size() - 1))
                  : (P.empty() ? "no point" : fmt::format("{} points, p0 to p{}", P.size(), P.size() - 1));
  rec.add(algorithms::make_step("input", fmt::format("The input: {}. Next: {}.", range, a->title), ""));
  if (of_segments)
    a->record_segments(S, scene.name, rec);
  else
    a->record(P, scene.name, rec);
  const std::string what = of_segments ? fmt::format("{} segments", S.size()) : fmt::format("{} points", P.size());
  t2::write_file_atomically(out, page(fmt::format("{} of {} ({})", a->title, scene.name, what), P, rec.steps(), drawn));
  return fmt::format("{}: {} steps ({} at the lecture level)", out.string(), rec.size(),
                     rec.at(t2::trace::Depth::lecture).size());
}

}  // namespace t2cli::animate
