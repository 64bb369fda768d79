// Hostile (issue 29, break 6): a demangler bomb. Each level is a pair of the level below, so the
// mangled name of `bomb` stays short (a substitution refers back to a level) while its demangled
// form doubles per level: about 2^60 characters. A grader that demangles symbols in its own
// process hangs; the answers are the stub's, so the submission must score 0, within a minute.
#include <stdexcept>

#include "classify.hpp"

namespace ex01 {
template <class A, class B>
struct P {};
using L0 = P<int, long>;
using L1 = P<L0, L0>;
using L2 = P<L1, L1>;
using L3 = P<L2, L2>;
using L4 = P<L3, L3>;
using L5 = P<L4, L4>;
using L6 = P<L5, L5>;
using L7 = P<L6, L6>;
using L8 = P<L7, L7>;
using L9 = P<L8, L8>;
using L10 = P<L9, L9>;
using L11 = P<L10, L10>;
using L12 = P<L11, L11>;
using L13 = P<L12, L12>;
using L14 = P<L13, L13>;
using L15 = P<L14, L14>;
using L16 = P<L15, L15>;
using L17 = P<L16, L16>;
using L18 = P<L17, L17>;
using L19 = P<L18, L18>;
using L20 = P<L19, L19>;
using L21 = P<L20, L20>;
using L22 = P<L21, L21>;
using L23 = P<L22, L22>;
using L24 = P<L23, L23>;
using L25 = P<L24, L24>;
using L26 = P<L25, L25>;
using L27 = P<L26, L26>;
using L28 = P<L27, L27>;
using L29 = P<L28, L28>;
using L30 = P<L29, L29>;
using L31 = P<L30, L30>;
using L32 = P<L31, L31>;
using L33 = P<L32, L32>;
using L34 = P<L33, L33>;
using L35 = P<L34, L34>;
using L36 = P<L35, L35>;
using L37 = P<L36, L36>;
using L38 = P<L37, L37>;
using L39 = P<L38, L38>;
using L40 = P<L39, L39>;
using L41 = P<L40, L40>;
using L42 = P<L41, L41>;
using L43 = P<L42, L42>;
using L44 = P<L43, L43>;
using L45 = P<L44, L44>;
using L46 = P<L45, L45>;
using L47 = P<L46, L46>;
using L48 = P<L47, L47>;
using L49 = P<L48, L48>;
using L50 = P<L49, L49>;
using L51 = P<L50, L50>;
using L52 = P<L51, L51>;
using L53 = P<L52, L52>;
using L54 = P<L53, L53>;
using L55 = P<L54, L54>;
using L56 = P<L55, L55>;
using L57 = P<L56, L56>;
using L58 = P<L57, L57>;
using L59 = P<L58, L58>;
using L60 = P<L59, L59>;
void bomb(L60*) {}

Where where(const t2::Point&) { throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
