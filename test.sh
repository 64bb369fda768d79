#!/usr/bin/env bash
# The whole test suite (what CI runs): the default build and an ASan+UBSan build.
# Long randomized runs are behind a label: ctest --preset long.
set -euo pipefail
cd "$(dirname "$0")"
scripts/deps.sh
scripts/ninja-trees.sh
cmake --preset default
cmake --build --preset default
ctest --preset default
cmake --preset asan
cmake --build --preset asan
ctest --preset asan
# A short libFuzzer run (clang) of the scene parser from the committed corpus: the fuzzer and the
# kernel layer it links, nothing else.
cmake -S fuzz -B build/fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/fuzz --target fuzz_scene
ctest --test-dir build/fuzz -LE long --output-on-failure
