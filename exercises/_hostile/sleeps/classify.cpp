// Hostile: waits without using CPU (only the wall-clock timeout can stop it).
#include <unistd.h>
#include "classify.hpp"
namespace ex01 {
static bool wait_forever() { for (;;) sleep(1000); }
Where where(const t2::Point&) { return wait_forever() ? Where::front : Where::back; }
bool same_point(const t2::Point&, const t2::Point&) { return wait_forever(); }
bool antipodal(const t2::Point&, const t2::Point&) { return wait_forever(); }
}  // namespace ex01
