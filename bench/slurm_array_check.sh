#!/usr/bin/env bash
# Runs a papercraft batch through scripts/slurm/submit.sh on a throwaway single-node Slurm
# started on this machine, and checks that the merged summary has a row per input, each once.
#
#   bench/slurm_array_check.sh                        # 9 generated meshes, a 3-task array
#   bench/slurm_array_check.sh --job JOB.yaml --shards 4 [--expect-ok] [-- SBATCH OPTIONS]
#
# A given job needs an output folder without summaries (the check counts the merged rows).
# Options after -- go to sbatch for the array (e.g. -c 1: one CPU and one thread per task).
# Needs root: installs slurm-wlm and munge with apt-get when missing (Debian 12), writes a
# minimal slurm.conf and a munge key in a temporary folder, starts munged, slurmctld and slurmd
# from there (on ports of their own; nothing of the system's configuration is used) and stops
# them at exit. Prints the array's wall time from submission to the merged batch.json, and
# batch.json's own wall time. PAPERCRAFT: the binary (default build/runner/papercraft).
# Exit 0 when the check holds.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
papercraft=$(realpath "${PAPERCRAFT:-$root/build/runner/papercraft}")
job=""
shards=3
sbatch_options=()
expect_ok=0
keep=0
while [[ $# -gt 0 ]]; do
  case $1 in
    --job) job=$(realpath "$2"); shift 2 ;;
    --shards) shards=$2; shift 2 ;;
    --expect-ok) expect_ok=1; shift ;;
    --keep) keep=1; shift ;;
    --) shift; sbatch_options=("$@"); break ;;
    *) echo "usage: $0 [--job JOB.yaml] [--shards N] [--expect-ok] [--keep] [-- SBATCH OPTIONS]" >&2; exit 2 ;;
  esac
done
[[ $(id -u) -eq 0 ]] || { echo "$0: needs root (it starts slurmd)" >&2; exit 2; }
[[ -x $papercraft ]] || { echo "$0: no binary at $papercraft (build first)" >&2; exit 2; }

missing=()
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "slurm_array_check: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >&2
  # Debian's maintainer scripts start the daemons where they can; ours run on their own ports.
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

work=$(mktemp -d /tmp/papercraft-slurm.XXXXXX)
pids=()
cleanup() {
  local status=$?
  if [[ -n ${SLURM_CONF:-} ]]; then scancel --quiet --user root >/dev/null 2>&1 || true; fi
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [[ $status -ne 0 || $keep -eq 1 ]]; then
    echo "slurm_array_check: logs kept in $work" >&2
  else
    rm -rf "$work"
  fi
}
trap cleanup EXIT
mkdir -p "$work"/{state,spool,log,munge}
chmod 700 "$work/munge"

# munge: a key of our own and a socket in our folder.
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
munged --force --foreground --key-file="$work/munge/munge.key" \
  --socket="$work/munge/munge.socket" --pid-file="$work/munge/munged.pid" \
  --log-file="$work/log/munged.log" --seed-file="$work/munge/munged.seed" \
  >"$work/log/munged.out" 2>&1 &
pids+=($!)

host=$(hostname -s)
port=$((20000 + RANDOM % 20000))
cat >"$work/slurm.conf" <<CONF
ClusterName=papercraft-check
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/munge.socket
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
MpiDefault=none
KillWait=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=check Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf

for i in $(seq 50); do [[ -S $work/munge/munge.socket ]] && break; sleep 0.1; done
slurmctld -D -i -f "$SLURM_CONF" >"$work/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$work/log/slurmd.out" 2>&1 &
pids+=($!)
for i in $(seq 100); do
  state=$(sinfo -h -o %T 2>/dev/null || true)
  [[ $state == idle* ]] && break
  sleep 0.2
done
[[ ${state:-} == idle* ]] || { echo "slurm_array_check: the node did not come up (state '${state:-}')" >&2; exit 1; }
echo "slurm_array_check: slurmctld and slurmd up on $host:$port ($(nproc) CPUs)" >&2

if [[ -z $job ]]; then
  mkdir -p "$work/meshes"
  shapes=(open_cylinder cone_frustum sphere torus pawn cylinder_two_holes box capped_cylinder dumbbell)
  for shape in "${shapes[@]}"; do "$papercraft" generate "$shape" "$work/meshes/$shape.obj" >/dev/null; done
  printf 'inputs: [meshes/*.obj]\noutput: out\ntolerance: 3%%\nthreads: 1\n' >"$work/job.yaml"
  job=$work/job.yaml
  expect_ok=1
fi
list=$("$papercraft" batch "$job" --shard 1/1 --list)
count=$(wc -l <<<"$list")
out=$(dirname "$(head -n 1 <<<"$list" | cut -f3)")
if [[ -e $out/batch.json || -n $(compgen -G "$out/batch.shard-*") ]]; then
  echo "slurm_array_check: $out holds summaries already; give a job with a fresh output" >&2
  exit 2
fi

cd "$work"
export PAPERCRAFT=$papercraft
start=$(date +%s.%N)
read -r array merge < <("$root/scripts/slurm/submit.sh" "$job" "$shards" "${sbatch_options[@]}")
echo "slurm_array_check: array $array ($shards tasks over $count inputs), merge $merge" >&2
for i in $(seq 3000); do
  [[ -z $(squeue -h -j "$array,$merge" 2>/dev/null) ]] && break
  sleep 0.2
done
end=$(date +%s.%N)
[[ -z $(squeue -h -j "$array,$merge" 2>/dev/null) ]] || { echo "slurm_array_check: jobs still queued after 10 min" >&2; exit 1; }
cat "$work"/papercraft-summary-*.log

python3 - "$out/batch.json" "$count" "$shards" "$expect_ok" "$start" "$end" <<'PY'
import json, sys
path, count, shards, expect_ok, start, end = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4] == "1", float(sys.argv[5]), float(sys.argv[6])
summary = json.load(open(path))
names = [row["name"] for row in summary["results"]]
problems = []
if len(names) != count: problems.append(f"{len(names)} rows, expected {count}")
if len(set(names)) != len(names): problems.append("a model has two rows")
if len(summary.get("merged_from", [])) < 2 * shards: problems.append(f"merged from {summary.get('merged_from')}")
if expect_ok and summary["ok"] != count: problems.append(f"{summary['ok']} ok of {count}")
print(f"slurm array: {shards} tasks, {count} models: {summary['ok']} ok, {summary['failed']} failed; "
      f"submission to merged summary {end - start:.1f} s; batch.json wall {summary['wall_seconds']:.1f} s, "
      f"{summary['models_per_minute']:.2f} models/min")
if problems:
    print("slurm_array_check: FAILED: " + "; ".join(problems), file=sys.stderr)
    sys.exit(1)
print("slurm_array_check: ok")
PY
