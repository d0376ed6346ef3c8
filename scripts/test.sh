#!/usr/bin/env bash
# One command: install what is missing, build everything in Release, run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
# Every fuzz target for 30 s (builds build-fuzz with clang-14 and libFuzzer first).
fuzz/run.sh 30
