#!/usr/bin/env bash
# The whole test suite (what CI runs): the default build and an ASan+UBSan build.
# Long randomized runs are behind a label: ctest --preset long, after `cmake --preset default`
# and its build (that tree builds every test).
# Each test is built and run in one tree (T2_TESTS, tests/CMakeLists.txt): the ASan tree runs the
# unit tests, the default tree those that need the optimized build, and the few listed in both.
# No test runs a benchmark program, so the default tree here builds none (build.sh builds them:
# its preset turns T2_BUILD_BENCHMARKS on again); the ASan tree builds the benchmark worker, which
# its tests run.
# The ASan tree is a unity build (CMakePresets.json): the files of one target are compiled eight to
# a translation unit, so two files of a target must not give one name two meanings at file scope,
# anonymous namespaces included (name the namespace, as lib/src/intersect/sweep.cpp does). The
# default tree compiles one file a unit, so a missing #include still fails there.
set -euo pipefail
cd "$(dirname "$0")"
scripts/deps.sh
scripts/ninja-trees.sh
cmake --preset default -DT2_TESTS=optimized -DT2_BUILD_BENCHMARKS=OFF
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
