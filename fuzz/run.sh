#!/usr/bin/env bash
# Builds the fuzz targets with clang-14 and libFuzzer (ASan and UBSan on) in build-fuzz, if
# needed, and runs each for SECONDS, one after the other.
#
#   fuzz/run.sh SECONDS [TARGET...]     # default: every target
#   MERGE=1 fuzz/run.sh SECONDS ...     # then replace fuzz/corpus/<target> by the fewest
#                                       # inputs that reach every edge it and the run reached
#
# A target's run grows build-fuzz/corpus/<target> from fuzz/corpus/<target> and replays
# fuzz/regressions/<target>; inputs that crash, hang (over 10 s), leak or pass the memory
# limit (2 GB) are written to build-fuzz/artifacts/<target>/ and make the script exit 1.
# Each run's last line of statistics (executions per second, coverage in edges) is printed
# and its whole log kept in build-fuzz/logs/<target>.log.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:?usage: fuzz/run.sh SECONDS [TARGET...]}
shift
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(load_obj load_off load_ply load_stl load_gltf load_glb load_3mf load_arrays mtl config batch_job)
build=build-fuzz
if [ ! -f "$build/build.ninja" ]; then
  cmake --preset fuzz >/dev/null
fi
cmake --build "$build" -j"${JOBS:-$(nproc)}" --target "${targets[@]/#/fuzz_}"
# Leaks inside system libraries we cannot free (see the file).
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
status=0
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target"
  artifacts="$build/artifacts/$target"
  mkdir -p "$corpus" "$artifacts" "$build/logs" "fuzz/regressions/$target"
  log="$build/logs/$target.log"
  start=$(date +%s)
  if ! "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
      -dict="fuzz/dict/$target.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
      "$corpus" "fuzz/corpus/$target" "fuzz/regressions/$target" >"$log" 2>&1; then
    echo "$target: FINDING (see $log and $artifacts/)" >&2
    status=1
  fi
  stats=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  echo "$target: $(( $(date +%s) - start )) s; $stats"
  if [ "${MERGE:-0}" = 1 ]; then
    # The fewest inputs that reach every edge reached so far (edges only, not hit counts).
    merged="$build/merged/$target"
    rm -rf "$merged" && mkdir -p "$merged"
    "$build/fuzz/fuzz_$target" -merge=1 -use_counters=0 -rss_limit_mb=2048 -timeout=10 \
      "$merged" "fuzz/corpus/$target" "$corpus" >>"$log" 2>&1
    rm -rf "fuzz/corpus/$target" && mv "$merged" "fuzz/corpus/$target"
  fi
done
exit $status
