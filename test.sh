#!/usr/bin/env bash
# The whole test suite (what CI runs): the default build and an ASan+UBSan build.
# Long randomized runs are behind a label: ctest --preset long.
set -euo pipefail
cd "$(dirname "$0")"
scripts/deps.sh
cmake --preset default
cmake --build --preset default
ctest --preset default
cmake --preset asan
cmake --build --preset asan
ctest --preset asan
