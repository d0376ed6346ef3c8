#!/usr/bin/env bash
# Runs scripts/parallel/papercraft-parallel.sh (GNU parallel, one model per job) over 9
# generated meshes with --sshloginfile naming this machine, kills one job with SIGKILL while it
# runs (a lost machine), and checks that the next call of the script runs that job only
# (--resume-failed), leaves the other shards' files alone and merges 9 ok rows.
#
#   tests/scripts/parallel_recipe_check.sh [--keep]
#
# In the test suite (ctest: ParallelRecipe.KilledJobResumed; scripts/install-deps.sh installs
# parallel). Run alone, it installs GNU parallel with apt-get when missing (needs root then).
# PAPERCRAFT: the binary (default build/runner/papercraft). Exit 0 when the check holds; 77
# (skipped) when parallel is missing and cannot be installed.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
papercraft=$(realpath "${PAPERCRAFT:-$root/build/runner/papercraft}")
keep=0
[[ ${1:-} == --keep ]] && keep=1
[[ -x $papercraft ]] || { echo "$0: no binary at $papercraft (build first)" >&2; exit 2; }
if ! command -v parallel >/dev/null; then
  [[ $(id -u) -eq 0 ]] || { echo "$0: GNU parallel missing and not root to install it" >&2; exit 77; }
  echo "parallel_recipe_check: installing parallel" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >&2
  apt-get install -y -qq --no-install-recommends parallel >/dev/null
fi

work=$(mktemp -d /tmp/papercraft-parallel.XXXXXX)
victim_pid=""
cleanup() {
  local status=$?
  [[ -n $victim_pid ]] && kill "$victim_pid" 2>/dev/null || true
  if [[ $status -ne 0 || $keep -eq 1 ]]; then
    echo "parallel_recipe_check: files kept in $work" >&2
  else
    rm -rf "$work"
  fi
}
trap cleanup EXIT

mkdir -p "$work/meshes"
shapes=(open_cylinder cone_frustum sphere torus pawn cylinder_two_holes box capped_cylinder)
for shape in "${shapes[@]}"; do "$papercraft" generate "$shape" "$work/meshes/$shape.obj" >/dev/null; done
# The one to kill: long enough to be caught running.
"$papercraft" generate sphere "$work/meshes/slow.obj" --param subdivisions=6 >/dev/null
printf 'inputs: [meshes/*.obj]\noutput: out\ntolerance: 1%%\nthreads: 1\n' >"$work/job.yaml"
echo "2/:" >"$work/hosts"  # this machine, two jobs at a time

list=$("$papercraft" batch "$work/job.yaml" --list)
count=$(wc -l <<<"$list")
victim=$(grep -n "^slow	" <<<"$list" | cut -d: -f1)
export PAPERCRAFT=$papercraft JOBLOG=$work/joblog
run_recipe() {
  "$root/scripts/parallel/papercraft-parallel.sh" "$work/job.yaml" --sshloginfile "$work/hosts"
}

start=$(date +%s.%N)
set +e
run_recipe >"$work/first.log" 2>&1 &
recipe=$!
set -e
shard_file=$work/out/batch.shard-$victim-of-$count.json
for i in $(seq 600); do [[ -f $shard_file ]] && break; sleep 0.1; done
[[ -f $shard_file ]] || { echo "parallel_recipe_check: job $victim never started" >&2; exit 1; }
# The papercraft process itself, not a shell parallel may have started it from.
for pid in $(pgrep -f -- "batch $work/job.yaml --shard $victim/$count" || true); do
  [[ $(cat "/proc/$pid/comm" 2>/dev/null) == papercraft ]] && victim_pid=$pid
done
[[ -n $victim_pid ]] || { echo "parallel_recipe_check: job $victim ended before it could be killed" >&2; exit 1; }
kill -KILL "$victim_pid"
victim_pid=""
first_status=0
wait "$recipe" || first_status=$?
echo "parallel_recipe_check: first call exited $first_status with job $victim killed" >&2

declare -A before=()
for f in "$work"/out/batch.shard-*.json; do before[$f]=$(stat -c %Y.%y "$f"); done
second_status=0
run_recipe >"$work/second.log" 2>&1 || second_status=$?
end=$(date +%s.%N)

python3 - "$work" "$count" "$victim" "$first_status" "$second_status" "$start" "$end" <<'PY'
import csv, json, os, sys
work, count, victim = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
first_status, second_status, start, end = int(sys.argv[4]), int(sys.argv[5]), float(sys.argv[6]), float(sys.argv[7])
rows = list(csv.DictReader(open(os.path.join(work, "joblog")), delimiter="\t"))
problems = []
runs = {}
for r in rows:
    runs.setdefault(int(r["Seq"]), []).append(r)
if len(rows) != count + 1: problems.append(f"joblog has {len(rows)} runs, expected {count} + 1")
if len(runs.get(victim, [])) != 2: problems.append(f"job {victim} ran {len(runs.get(victim, []))} times")
if runs.get(victim) and runs[victim][0]["Signal"] != "9": problems.append(f"job {victim}'s first run: {runs[victim][0]}")
for seq, rs in runs.items():
    if seq != victim and len(rs) != 1: problems.append(f"job {seq} ran {len(rs)} times")
if first_status == 0: problems.append("the first call's summary did not report the killed model")
if second_status != 0: problems.append(f"the second call exited {second_status}")
summary = json.load(open(os.path.join(work, "out", "batch.json")))
names = [r["name"] for r in summary["results"]]
if len(names) != count or len(set(names)) != count: problems.append(f"rows: {names}")
if summary["ok"] != count: problems.append(f"{summary['ok']} ok of {count}")
print(f"parallel: {count} one-model jobs, job {victim} killed and resumed; both calls {end - start:.1f} s; "
      f"batch.json: {summary['ok']} ok, wall {summary['wall_seconds']:.1f} s")
if problems:
    print("parallel_recipe_check: FAILED: " + "; ".join(problems), file=sys.stderr)
    sys.exit(1)
PY
for f in "${!before[@]}"; do
  [[ $f == *"-$victim-of-"* ]] && continue
  [[ $(stat -c %Y.%y "$f") == "${before[$f]}" ]] || { echo "parallel_recipe_check: FAILED: $f rewritten by the second call" >&2; exit 1; }
done
echo "parallel_recipe_check: ok"
