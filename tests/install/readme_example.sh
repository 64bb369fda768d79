#!/usr/bin/env bash
# Builds and runs the README's "library in ten lines" example exactly as printed there, twice:
# with add_subdirectory(t2) and with find_package(t2) after `cmake --install`.
# Usage: readme_example.sh REPO_DIR BUILD_DIR
# The library is compiled once, by the add_subdirectory build (with no build type, as a user who
# follows the README would); find_package uses `cmake --install` of BUILD_DIR, the build tree
# whose tests run this script (so its install rules and exported targets are what is checked).
set -euo pipefail
repo=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The first ```cmake and ```cpp blocks after the heading, and the "// prints:" line.
section() { sed -n '/^## The library in ten lines/,$p' "$repo/README.md"; }
block() { section | awk -v lang="$1" '$0 == "```" lang {on=1; next} on && /^```/ {exit} on {print}'; }
block cmake > "$tmp/CMakeLists.txt"
block cpp > "$tmp/app.cpp"
expected=$(grep -m1 '^// prints: ' "$tmp/app.cpp" | sed 's|^// prints: ||')
[ -n "$expected" ] || { echo "README example has no '// prints:' line"; exit 1; }
grep -q 'add_subdirectory(t2)' "$tmp/CMakeLists.txt" || { echo "README example lost add_subdirectory(t2)"; exit 1; }

run_app() {
  local dir=$1
  cmake -S "$dir" -B "$dir/build" "${@:2}" > "$dir/configure.log"
  cmake --build "$dir/build" -j2 > "$dir/build.log" || { cat "$dir/build.log"; exit 1; }
  local got
  got=$("$dir/build/app")
  if [ "$got" != "$expected" ]; then
    echo "README example printed '$got', the README says '$expected'"
    exit 1
  fi
}

# 1. add_subdirectory
mkdir "$tmp/sub" && cp "$tmp/CMakeLists.txt" "$tmp/app.cpp" "$tmp/sub/"
ln -s "$repo" "$tmp/sub/t2"
run_app "$tmp/sub"
echo "add_subdirectory: ok"

# 2. find_package after cmake --install. The library alone (T2_BUILD_ALL=OFF) still configures as
# a top-level project; the install is the one of the build tree under test.
cmake -S "$repo" -B "$tmp/lib" -DT2_BUILD_ALL=OFF > "$tmp/lib.log" || { cat "$tmp/lib.log"; exit 1; }
cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log" || { cat "$tmp/install.log"; exit 1; }
mkdir "$tmp/pkg" && cp "$tmp/app.cpp" "$tmp/pkg/"
sed 's|^add_subdirectory(t2).*|find_package(t2 REQUIRED)|' "$tmp/CMakeLists.txt" > "$tmp/pkg/CMakeLists.txt"
run_app "$tmp/pkg" -DCMAKE_PREFIX_PATH="$tmp/prefix"
echo "find_package: ok"
