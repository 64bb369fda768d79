// Hostile (issue 10): inline assembly recreating GCC's LTO sections, whose .incbin reads a file
// at build time: a linker plugin outside the sandbox would compile it with the host's files.
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
asm(".section .gnu.lto_.t2_hostile,\"e\",@progbits\n.incbin \"/usr/include/stdio.h\"\n.previous\n");
static void attack() {}
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
