#!/usr/bin/env bash
# One command: install what is missing, build in Release, and turn the bundled example
# (examples/pawn.obj, made by `papercraft generate pawn`) into a paper pattern in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target papercraft
build/runner/papercraft run examples/pawn.obj --tolerance 2% --height 150 --out out "$@"
echo "pattern: out/pawn/pattern.pdf; viewer: out/pawn/assembly.html (and pattern-NN.svg, report.json, ...)"
