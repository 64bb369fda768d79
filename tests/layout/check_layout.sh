#!/bin/bash
# The house's layout rules, checked (check_layout.sh REPO):
#  - the root of lib/include/t2 holds only umbrella headers (#pragma once, comments, #include
#    "t2/..." lines), at most six of them;
#  - no source, header, chapter or script file of the repository is over 500 lines;
#  - CLI11 is included by one file of the tool, tools/t2/arguments.cpp (arguments.hpp says why).
set -u
cd "$1" || exit 2
status=0
roots=(lib/include/t2/*.hpp)
if (( ${#roots[@]} > 6 )); then
  echo "lib/include/t2 holds ${#roots[@]} headers at its root (at most six umbrellas)"; status=1
fi
for h in "${roots[@]}"; do
  bad=$(grep -nvE '^(#pragma once|#include "t2/[a-z0-9_/]+\.hpp"|//.*|)$' "$h" | head -1)
  if [[ -n $bad ]]; then echo "$h:${bad%%:*}: not an umbrella header (only includes of t2 headers)"; status=1; fi
done
while IFS= read -r -d '' f; do
  [[ -L $f ]] && continue
  n=$(wc -l < "$f")
  if (( n > 500 )); then echo "$f: $n lines (at most 500)"; status=1; fi
done < <(find lib tools tests bench chapters exercises scripts book -type f \
           \( -name '*.hpp' -o -name '*.cpp' -o -name '*.md' -o -name '*.sh' -o -name '*.lua' -o -name '*.html' \) -print0)
while IFS= read -r f; do
  [[ $f == tools/t2/arguments.cpp ]] && continue
  echo "$f: includes CLI11 (declare options through tools/t2/arguments.hpp: CLI11 costs 4.5 s of GCC's time in every file that includes it)"
  status=1
done < <(grep -rlE '^#include <CLI/' lib tools tests bench chapters exercises 2>/dev/null)
exit $status
