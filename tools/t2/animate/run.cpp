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
#include "t2/trace/recording.hpp"

namespace t2cli::animate {
namespace {

// Every step is drawn twice (both models) into the page: beyond this many points the page
// grows past what a browser steps through comfortably, and the picture is unreadable anyway.
constexpr std::size_t kMaxPoints = 200;

}  // namespace

std::string write_animation(const std::string& algo, const t2::Scene& scene, const std::filesystem::path& out) {
  std::vector<t2::Point> P;
  for (const auto& p : scene.points) P.push_back(p.point);
  if (P.size() > kMaxPoints)
    throw t2::BadInput(fmt::format("{}: {} points: t2 animate draws every step, so at most {} points", scene.name,
                                   P.size(), kMaxPoints));
  const algorithms::Algorithm* a = algorithms::find(algo);
  if (a == nullptr || !a->record) throw std::invalid_argument(fmt::format("'{}': not an algorithm of t2 animate", algo));
  t2::trace::Recording rec;
  const std::string range = P.empty() ? "no point" : fmt::format("{} points, p0 to p{}", P.size(), P.size() - 1);
  rec.add(algorithms::make_step("input", fmt::format("The input: {}. Next: {}.", range, a->title), ""));
  a->record(P, scene.name, rec);
  t2::write_file_atomically(out, page(fmt::format("{} of {} ({} points)", a->title, scene.name, P.size()), P, rec.steps()));
  return fmt::format("{}: {} steps ({} at the lecture level)", out.string(), rec.size(),
                     rec.at(t2::trace::Depth::lecture).size());
}

}  // namespace t2cli::animate
