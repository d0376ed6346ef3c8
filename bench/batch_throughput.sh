#!/usr/bin/env bash
# Batch throughput on real meshes: the COUNT largest libcgal-demo meshes under MAX_FACES faces
# (bench/cgal_meshes.sh unpacks them) as one batch, run with 1 and with 2 threads, then (with
# --slurm) as a Slurm job array on a throwaway single-node Slurm (bench/slurm_array_check.sh,
# root only) against the same batch run directly with as many threads as the node has CPUs.
#
#   bench/batch_throughput.sh                          # 40 meshes under 10k faces at 2%
#   bench/batch_throughput.sh --slurm --shards 4       # and the array, 4 tasks of 1 CPU each
#   bench/batch_throughput.sh --count 10 --tolerance 5%
#
# Prints a table (models, ok, failed, wall s, models/min, summed work s) and the ratios. Every
# run writes a fresh output folder under --work (default: a temporary folder, deleted).
# PAPERCRAFT: the binary (default build/runner/papercraft). The machine this was written on has
# 2 shared cores: read ratios, and compare runs made one after the other.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
papercraft=$(realpath "${PAPERCRAFT:-$root/build/runner/papercraft}")
count=40
max_faces=10000
tolerance=2%
slurm=0
shards=4
work=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --count) count=$2; shift 2 ;;
    --max-faces) max_faces=$2; shift 2 ;;
    --tolerance) tolerance=$2; shift 2 ;;
    --slurm) slurm=1; shift ;;
    --shards) shards=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    *) echo "usage: $0 [--count N] [--max-faces N] [--tolerance T] [--slurm] [--shards N] [--work DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $papercraft ]] || { echo "$0: no binary at $papercraft (build first)" >&2; exit 2; }
meshes=$("$root/bench/cgal_meshes.sh")
if [[ -z $work ]]; then
  work=$(mktemp -d /tmp/papercraft-throughput.XXXXXX)
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work/in"

# The COUNT largest meshes under MAX_FACES faces (face count from the OFF header).
python3 - "$meshes" "$count" "$max_faces" "$work/in" <<'PY'
import os, sys
folder, count, max_faces, target = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
sizes = []
for name in sorted(os.listdir(folder)):
    if not name.endswith(".off"):
        continue
    tokens = []
    with open(os.path.join(folder, name), "rb") as f:
        for line in f:
            tokens += line.split(b"#")[0].split()
            if len(tokens) >= 4:
                break
    if tokens and tokens[0].endswith(b"OFF"):
        tokens = tokens[1:]
    try:
        faces = int(tokens[1])
    except (IndexError, ValueError):
        continue
    if 0 < faces < max_faces:
        sizes.append((faces, name))
chosen = sorted(sizes)[-count:]
for faces, name in chosen:
    os.symlink(os.path.join(folder, name), os.path.join(target, name))
print(f"{len(chosen)} meshes, {chosen[0][0]}..{chosen[-1][0]} faces, {sum(f for f, _ in chosen)} in all",
      file=sys.stderr)
PY

write_job() {  # write_job NAME: a job with its own output folder
  printf 'inputs: [in/*.off]\noutput: out-%s\ntolerance: %s\n' "$1" "$tolerance" >"$work/$1.yaml"
}
results=$work/results.tsv
: >"$results"
direct() {  # direct NAME THREADS
  write_job "$1"
  echo "batch_throughput: $1 (load $(cut -d' ' -f1-3 /proc/loadavg))" >&2
  local status=0
  "$papercraft" batch "$work/$1.yaml" --threads "$2" -q >"$work/$1.log" 2>&1 || status=$?
  [[ $status -le 1 ]] || { echo "batch_throughput: $1 exited $status" >&2; tail "$work/$1.log" >&2; exit 1; }
  printf '%s\t%s\n' "$1" "$work/out-$1/batch.json" >>"$results"
}
direct "threads-1" 1
direct "threads-2" 2
if [[ $slurm -eq 1 ]]; then
  write_job "slurm"
  cpus=$(nproc)
  echo "batch_throughput: slurm array of $shards tasks, 1 CPU each (load $(cut -d' ' -f1-3 /proc/loadavg))" >&2
  "$root/bench/slurm_array_check.sh" --job "$work/slurm.yaml" --shards "$shards" -- -c 1 \
    >"$work/slurm.log" 2>&1 || { tail -20 "$work/slurm.log" >&2; exit 1; }
  grep '^slurm array:' "$work/slurm.log" >&2
  printf '%s\t%s\t%s\n' "slurm" "$work/out-slurm/batch.json" \
    "$(grep -oP 'submission to merged summary \K[0-9.]+' "$work/slurm.log")" >>"$results"
  direct "threads-$cpus-again" "$cpus"  # the same batch directly, right after the array
fi

python3 - "$results" <<'PY'
import json, sys
rows = {}
print(f"{'run':<22}{'models':>7}{'ok':>5}{'failed':>8}{'wall s':>9}{'models/min':>12}{'work s':>9}")
for line in open(sys.argv[1]):
    fields = line.rstrip("\n").split("\t")
    name, path = fields[0], fields[1]
    s = json.load(open(path))
    wall = float(fields[2]) if len(fields) > 2 else s["wall_seconds"]
    done = s["ok"] - s["skipped"] + s["failed"]
    work = sum(r.get("work_seconds", 0) for r in s["results"])
    rows[name] = (wall, 60.0 * done / wall if wall > 0 else 0.0)
    label = name + (" (submit->merged)" if len(fields) > 2 else "")
    print(f"{label:<22}{s['models']:>7}{s['ok']:>5}{s['failed']:>8}{wall:>9.1f}{rows[name][1]:>12.2f}{work:>9.1f}")
if "threads-1" in rows and "threads-2" in rows:
    print(f"2 threads / 1 thread: {rows['threads-2'][1] / rows['threads-1'][1]:.2f}x models/min")
if "slurm" in rows:
    again = [k for k in rows if k.endswith("-again")][0]
    print(f"slurm array wall / direct batch wall ({again}): {rows['slurm'][0]:.1f} s / {rows[again][0]:.1f} s"
          f" = {rows['slurm'][0] / rows[again][0]:.2f}")
PY
