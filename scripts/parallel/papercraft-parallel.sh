#!/usr/bin/env bash
# A batch with GNU parallel, one model per job, then the merge (docs/batches.md, "GNU parallel").
# Job I of N runs `papercraft batch JOB --shard I/N` with N the number of inputs: exactly the
# I-th input, summarised in <output>/batch.shard-I-of-N.json. The joblog makes a second call
# run only the jobs that failed or were killed (--resume-failed); the models they finished are
# skipped by papercraft's own resume.
#
#   scripts/parallel/papercraft-parallel.sh JOB.yaml [parallel options]
#   scripts/parallel/papercraft-parallel.sh JOB.yaml -j 8 --sshloginfile hosts.txt
#
# Options go to parallel (-j, --sshloginfile, --timeout, ...). With --sshloginfile every host
# needs PAPERCRAFT (default: papercraft on PATH) and the job's files at the same paths.
# JOBLOG (default: <job file>.joblog) belongs to one list of inputs: delete it when the
# list changes. Exits with `papercraft summary`'s code: 0 when every model is ok.
set -euo pipefail
[[ $# -ge 1 ]] || { echo "usage: $0 JOB.yaml [parallel options]" >&2; exit 2; }
job=$(realpath "$1")
shift
papercraft=${PAPERCRAFT:-papercraft}
count=$("$papercraft" batch "$job" --shard 1/1 --list | wc -l)
[[ $count -gt 0 ]] || { echo "$0: $job has no inputs" >&2; exit 2; }
joblog=${JOBLOG:-$job.joblog}
status=0
seq 1 "$count" | parallel --joblog "$joblog" --resume-failed "$@" \
  "$papercraft" batch "$job" --shard "{}/$count" --threads 1 -q || status=$?
echo "parallel: $status job(s) failed; the summary says which" >&2
exec "$papercraft" summary "$job"
