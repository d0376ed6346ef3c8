#!/usr/bin/env bash
# Resolution independence: the same surface at 75k, 302k and 1.2M faces (libcgal-demo's
# bunny00, each triangle split into four at its edge midpoints once and twice by
# bench/split_mesh.py), each run with 1 and 2 threads. Prints faces, wall seconds of the whole
# command, its CPU seconds (user + system: the fairer figure on a busy machine) and its peak RSS
# (/usr/bin/time -v), strips (3D / flat, from report.json), the proxy's faces and the certified
# bound in % of the largest side.
#
#   bench/scaling.sh                         # 2%, work folder build/scaling
#   bench/scaling.sh --tolerance 1% --work /tmp/scaling --config configs/segment-none.yaml
#   bench/scaling.sh --threads 1             # one thread count only
#
# The split meshes are made once in the work folder (about 75 MB); nothing is committed.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tolerance=2%
work=$root/build/scaling
config=()
threads=(1 2)
binary=${PAPERCRAFT:-$root/build/runner/papercraft}
while [[ $# -gt 0 ]]; do
  case $1 in
    --tolerance) tolerance=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --config) config=(--config "$2"); shift 2 ;;
    --threads) threads=("$2"); shift 2 ;;
    *) echo "scaling.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ -x $binary ]] || { echo "scaling.sh: no $binary (build first)" >&2; exit 1; }
meshes=$("$root/bench/cgal_meshes.sh")
mkdir -p "$work"
cp -f "$meshes/bunny00.off" "$work/bunny00.off"
[[ -f $work/bunny01.off ]] || python3 "$root/bench/split_mesh.py" "$work/bunny00.off" "$work/bunny01.off"
[[ -f $work/bunny02.off ]] || python3 "$root/bench/split_mesh.py" "$work/bunny01.off" "$work/bunny02.off"

printf '%-9s %9s %7s %8s %7s %8s %7s %6s %8s %8s\n' mesh faces threads seconds cpu_s peak_MB strips flat proxy bound%
for name in bunny00 bunny01 bunny02; do
  for j in "${threads[@]}"; do
    out=$work/out-j$j
    log=$work/time-$name-j$j.txt
    /usr/bin/time -v "$binary" run "${config[@]}" -t "$tolerance" -j "$j" -q --out "$out" \
      "$work/$name.off" >/dev/null 2>"$log" || { echo "scaling.sh: $name failed, see $log" >&2; exit 1; }
    python3 - "$out/$name/report.json" "$name" "$j" "$log" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
rss_kb, seconds, cpu = 0, 0.0, 0.0
for line in open(sys.argv[4]):
    if "User time" in line or "System time" in line:
        cpu += float(line.rsplit(":", 1)[1])
    if "Maximum resident set size" in line:
        rss_kb = int(line.rsplit(":", 1)[1])
    if "Elapsed (wall clock)" in line:
        for part in line.rsplit(": ", 1)[1].split(":"):
            seconds = 60 * seconds + float(part)
r, p = report["result"], report.get("proxy", {})
print(f'{sys.argv[2]:<9} {report["input"]["faces"]:>9} {sys.argv[3]:>7} '
      f'{seconds:>8.1f} {cpu:>7.1f} {rss_kb / 1024:>8.0f} '
      f'{r["strips_3d"]:>7} {r["flat_strips"]:>6} {p.get("faces", 0) if p.get("used") else "-":>8} '
      f'{r["hausdorff_bound_percent"]:>8.3f}')
PY
  done
done
