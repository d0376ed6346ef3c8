#!/usr/bin/env bash
# Queues a papercraft batch on Slurm: a job array of N shards, then the merge once the array
# has ended, whatever became of it. Prints the two job ids (array first).
#
#   scripts/slurm/submit.sh JOB.yaml N [sbatch options for the array, e.g. -c 4 -t 2:00:00]
#
# The job file, its inputs and output folder must be on a file system every node sees, at the
# same path; PAPERCRAFT (default: papercraft on PATH) likewise.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[[ $# -ge 2 ]] || { echo "usage: $0 JOB.yaml N [sbatch options]" >&2; exit 2; }
job=$(realpath "$1")
count=$2
shift 2
[[ $count =~ ^[1-9][0-9]*$ ]] || { echo "$0: N must be a positive number, got '$count'" >&2; exit 2; }
array=$(sbatch --parsable --array="1-$count" "$@" "$here/papercraft-array.sbatch" "$job")
array=${array%%;*}  # "id;cluster" on federated setups
merge=$(sbatch --parsable --dependency="afterany:$array" "$here/papercraft-summary.sbatch" "$job")
echo "$array ${merge%%;*}"
