// Linked to t2::kernel only (no Cairo, no drawing): the kernel's headers and sources stand alone.
// Run by CTest as kernel.links_without_cairo; it checks a few exact answers on the way.
#include <t2/kernel/constructions.hpp>
#include <t2/kernel/predicates.hpp>
#include <t2/kernel/scene.hpp>

#include <cstdio>

int main() {
  const t2::Point a(1, 0, 0), b(1, 1, 0), c(1, 0, 1);
  const bool ok = t2::orient(a, b, c) == t2::POSITIVE && t2::in_circle(a, b, c, t2::Point(1, 0.25, 0.25)) == t2::POSITIVE &&
                  t2::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == t2::POSITIVE &&
                  t2::side(t2::join(a, b), c) == t2::POSITIVE && t2::parse_scene("1 2\n3 4\n", "inline").points.size() == 2;
  std::puts(ok ? "kernel ok" : "kernel WRONG");
  return ok ? 0 : 1;
}
