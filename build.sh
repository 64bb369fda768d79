#!/usr/bin/env bash
# The main job: install what is missing, build library, tools, chapters and exercises,
# regenerate every figure, build the API reference and the book.
set -euo pipefail
cd "$(dirname "$0")"
scripts/deps.sh
scripts/ninja-trees.sh
cmake --preset default
cmake --build --preset default
build/default/bin/t2 figures          # redraw every figure (chapters and gallery) that changed
cmake --build --preset default --target docs
build/default/bin/t2 book --quiet   # the HTML book: build/default/book/index.html
echo "built: build/default/bin/t2 (try: build/default/bin/t2 --help)"
