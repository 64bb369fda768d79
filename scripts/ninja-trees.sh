#!/usr/bin/env bash
# The build trees are Ninja trees (CMakePresets.json, test.sh). A tree configured earlier with
# another generator cannot be reconfigured with Ninja: remove it, so that the next configure
# starts it anew.
set -euo pipefail
cd "$(dirname "$0")/.."
for d in build/default build/asan build/fuzz; do
  if [ -f "$d/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$d/CMakeCache.txt"; then
    echo "removing $d: configured with another generator than Ninja"
    rm -rf "$d"
  fi
done
