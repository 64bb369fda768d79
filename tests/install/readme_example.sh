#!/usr/bin/env bash
# Builds and runs the README's "library in ten lines" example exactly as printed there, twice:
# with add_subdirectory(t2) and with find_package(t2) after `cmake --install`.
# Usage: readme_example.sh REPO_DIR
set -euo pipefail
repo=$(cd "$1" && pwd)
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
  cmake -S "$dir" -B "$dir/build" -DCMAKE_BUILD_TYPE=Release "${@:2}" > "$dir/configure.log"
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

# 2. find_package after cmake --install
cmake -S "$repo" -B "$tmp/lib" -DCMAKE_BUILD_TYPE=Release -DT2_BUILD_ALL=OFF > "$tmp/lib.log"
cmake --build "$tmp/lib" -j2 >> "$tmp/lib.log"
cmake --install "$tmp/lib" --prefix "$tmp/prefix" >> "$tmp/lib.log"
mkdir "$tmp/pkg" && cp "$tmp/app.cpp" "$tmp/pkg/"
sed 's|^add_subdirectory(t2).*|find_package(t2 REQUIRED)|' "$tmp/CMakeLists.txt" > "$tmp/pkg/CMakeLists.txt"
run_app "$tmp/pkg" -DCMAKE_PREFIX_PATH="$tmp/prefix"
echo "find_package: ok"
