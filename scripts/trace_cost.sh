#!/bin/sh
# The trace costs nothing when off: the machine code of graham, jarvis and delaunay_with with
# their default trace (NoTrace, DelaunayTraits's empty hooks) is compared with that of copies
# of the same functions from which every trace call was deleted (made here by sed from the
# library's headers). Both are compiled in one file with the project's flags (-O2) and
# disassembled; the script prints the code size of each pair and whether the instructions are
# the same (addresses and symbol names aside). Exit 1 when a pair differs.
# With --time LIBDIR (build/default/lib) it also links a timing program and
# prints the best of 7 alternating runs of each pair on the same random points.
#   scripts/trace_cost.sh [--time build/default/lib]
set -eu
CXX=${CXX:-c++}
LIB=
[ "${1:-}" = --time ] && LIB=$2
root=$(cd "$(dirname "$0")/.." && pwd)
inc=$root/lib/include
tmp=$(mktemp -d); [ -n "${KEEP:-}" ] && echo "$tmp"
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT

# Untraced copies: the trace parameter and every line that calls it removed, the function renamed.
for f in graham jarvis; do
  perl -0pe 's/,\s*Tr&& trace = \{\}\)/)/; s/template <class K = HullTraits, class Tr = NoTrace>\n(std::vector<std::size_t>) '"$f"'\(/template <class K = HullTraits>\n$1 '"$f"'_untraced(/; s/^.*trace\(HullStep.*\n//mg; s/#pragma once//' \
    "$inc/t2/hull/$f.hpp" >"$tmp/${f}_untraced.hpp"
done
awk '/^template <class K = DelaunayTraits>/{on=1} /^\/\/\/ The Delaunay triangulation of front points with the exact/{on=0} on' \
  "$inc/t2/triangulation/delaunay.hpp" |
  sed -e '/kernel\.inserted(/d' -e '/kernel\.flipped(/d' -e 's/Triangulation delaunay_with(/Triangulation delaunay_with_untraced(/' \
  >"$tmp/delaunay_body.hpp"
{ echo '#include "t2/triangulation/delaunay.hpp"'; echo 'namespace t2 {'; cat "$tmp/delaunay_body.hpp"; echo '}'; } >"$tmp/delaunay_untraced.hpp"

cat >"$tmp/cost.cpp" <<'CPP'
#include "t2/hull/graham.hpp"
#include "t2/hull/jarvis.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "graham_untraced.hpp"
#include "jarvis_untraced.hpp"
#include "delaunay_untraced.hpp"
namespace t2 {
using V = std::vector<std::size_t>;
template V graham<HullTraits, NoTrace>(std::span<const Point>, const V&, const Chart&, NoTrace&&);
template V graham_untraced<HullTraits>(std::span<const Point>, const V&, const Chart&);
template V jarvis<HullTraits, NoTrace>(std::span<const Point>, const V&, const Chart&, NoTrace&&);
template V jarvis_untraced<HullTraits>(std::span<const Point>, const V&, const Chart&);
template Triangulation delaunay_with<DelaunayTraits>(std::span<const Point>, DelaunayTraits);
template Triangulation delaunay_with_untraced<DelaunayTraits>(std::span<const Point>, DelaunayTraits);
}
CPP
"$CXX" -std=c++20 -O2 -g -DNDEBUG -I"$inc" -I"$tmp" -c "$tmp/cost.cpp" -o "$tmp/cost.o"

# The instructions of the function whose mangled name starts with $1 (addresses, offsets and
# symbol names normalised away).
body() {
  sym=$(nm "$tmp/cost.o" | awk -v p="$1" '$2 ~ /^[TW]$/ && index($3, p) == 1 {print $3; exit}')
  [ -n "$sym" ] || return 0
  objdump -d --no-show-raw-insn --disassemble="$sym" "$tmp/cost.o" |
    awk '/^[0-9a-f]+ </ {on=1; next} on && NF && !/^Disassembly/' |
    sed -E -e 's/^ *[0-9a-f]+:\s*//' -e 's/<[^>]*>//g' -e 's/\b(0x)?[0-9a-f]{2,}\b/N/g' -e 's/#.*//'
}
status=0
for pair in graham:_ZN2t26grahamI:_ZN2t215graham_untracedI jarvis:_ZN2t26jarvisI:_ZN2t215jarvis_untracedI \
  delaunay_with:_ZN2t213delaunay_withI:_ZN2t222delaunay_with_untracedI; do
  name=${pair%%:*}
  rest=${pair#*:}
  body "${rest%%:*}" >"$tmp/a"
  body "${rest#*:}" >"$tmp/b"
  a=$(wc -l <"$tmp/a")
  b=$(wc -l <"$tmp/b")
  if [ "$a" -gt 0 ] && cmp -s "$tmp/a" "$tmp/b"; then same=identical; else same=DIFFERENT; status=1; fi
  printf '%-14s with the trace off: %5d instructions   with no trace calls: %5d   %s\n' "$name" "$a" "$b" "$same"
done
if [ -n "$LIB" ]; then
  cat >>"$tmp/cost.cpp" <<'CPP'
#include <chrono>
#include <cstdio>
#include <numeric>
template <class F>
double best(F f) {  // milliseconds
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
int main() {
  std::vector<t2::Point> P;
  unsigned long long x = 88172645463325252ull;
  auto next = [&] { x ^= x << 13; x ^= x >> 7; x ^= x << 17; return (x >> 11) * 0x1.0p-53 * 2 - 1; };
  for (int i = 0; i < 200000; ++i) P.emplace_back(1.0, next(), next());
  std::vector<std::size_t> idx(P.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  const t2::Chart c = t2::front_chart();
  const std::span<const t2::Point> S(P);
  double t[6] = {1e30, 1e30, 1e30, 1e30, 1e30, 1e30};
  std::size_t sink = 0;
  for (int r = 0; r < 7; ++r) {
    t[0] = std::min(t[0], best([&] { sink += t2::graham(S, idx, c).size(); }));
    t[1] = std::min(t[1], best([&] { sink += t2::graham_untraced(S, idx, c).size(); }));
    t[2] = std::min(t[2], best([&] { sink += t2::jarvis(S, idx, c).size(); }));
    t[3] = std::min(t[3], best([&] { sink += t2::jarvis_untraced(S, idx, c).size(); }));
    t[4] = std::min(t[4], best([&] { sink += t2::delaunay_with(S).size(); }));
    t[5] = std::min(t[5], best([&] { sink += t2::delaunay_with_untraced(S).size(); }));
  }
  std::printf("200000 uniform points, best of 7 (ms): trace off / no trace calls\n");
  std::printf("graham         %8.2f  %8.2f\njarvis         %8.2f  %8.2f\ndelaunay_with  %8.2f  %8.2f\n", t[0], t[1],
              t[2], t[3], t[4], t[5]);
  return sink == 0;
}
CPP
  "$CXX" -std=c++20 -O2 -DNDEBUG -I"$inc" -I"$tmp" "$tmp/cost.cpp" "$LIB/libt2.a" "$LIB/libt2_kernel.a" -lfmt -lgmpxx -lgmp -o "$tmp/cost"
  "$tmp/cost"
fi
exit $status
