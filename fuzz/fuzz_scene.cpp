// libFuzzer target: t2::parse_scene on arbitrary bytes. A valid input must parse, and its text
// (t2::to_string) must parse again; an invalid one must throw t2::ParseError whose message
// starts with "name:line: " (line >= 1). Any other exception, a crash or a sanitizer report is
// a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "t2/kernel/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const t2::Scene s = t2::parse_scene(text, "fuzz");
    // Every accepted point is a point of T2, every segment has non-antipodal endpoints, every
    // line and circle is defined (an exception from join or Circle escapes and is reported).
    for (const auto& g : s.segments)
      if (g.b.point == t2::antipode(g.a.point)) std::abort();
    for (const auto& p : s.polygons)
      if (p.vertices.size() < 3) std::abort();
    // Every line and circle block builds its object without throwing.
    for (const auto& l : s.lines) (void)l.join();
    for (const auto& c : s.circles) (void)c.circle();
    // Its text (styles included) reads back: a ParseError here names "written", not "fuzz",
    // and fails the prefix check below.
    (void)t2::parse_scene(t2::to_string(s), "written");
  } catch (const t2::ParseError& e) {
    const std::string prefix = "fuzz:" + std::to_string(e.line()) + ": ";
    if (e.line() < 1 || std::string_view(e.what()).substr(0, prefix.size()) != prefix) std::abort();
  }
  return 0;
}
