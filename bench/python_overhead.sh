#!/usr/bin/env bash
# What the Python module costs over the command line: each mesh is run with `papercraft run`
# and with papercraft.run(*papercraft.load(mesh)) in Python, alternately (cli, python, cli,
# python, ... so both see the same machine load), at one tolerance and thread count. Prints per
# mesh the fastest wall seconds of each (the Python time counts the load, the run and the
# conversion of the arrays and files; the command line's its whole process), their ratio, and
# whether both made the same strips.json and pieces.json.
#
#   bench/python_overhead.sh                       # bunny00, 2%, one thread, 2 repeats
#   bench/python_overhead.sh --repeat 3 --threads 2 eight.off elephant.off
#
# Options: --tolerance T (2%), --threads N (1), --repeat R (2), --work DIR
#          (build/python-overhead), --bin PATH (build/runner/papercraft), --python-path DIR
#          (build/python: where the papercraft package and its module are)
# Exit status 0; 1 when a mesh gives different files; 2 for a bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tolerance=2%
threads=1
repeat=2
work=$root/build/python-overhead
bin=$root/build/runner/papercraft
python_path=$root/build/python
declare -a meshes=()
. "$root/bench/lib.sh"
while [[ $# -gt 0 ]]; do
  case $1 in
    --tolerance) tolerance=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --python-path) python_path=$2; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "python_overhead.sh: unknown option $1" >&2; usage ;;
    *) meshes+=("$1"); shift ;;
  esac
done
if [[ ${#meshes[@]} -eq 0 ]]; then meshes=("$("$root/bench/cgal_meshes.sh")/bunny00.off"); fi
mkdir -p "$work"
status=0
printf '| mesh | command line s | Python s | Python / command line | same files |\n|---|---:|---:|---:|---|\n'
for mesh in "${meshes[@]}"; do
  name=$(basename "${mesh%.*}")
  best_cli=inf best_py=inf
  for ((i = 0; i < repeat; ++i)); do
    start=$(date +%s.%N)
    "$bin" run "$mesh" --tolerance "$tolerance" --threads "$threads" --out "$work/cli" -q \
      >/dev/null
    cli=$(python3 -c "print($(date +%s.%N) - $start)")
    py=$(PYTHONPATH=$python_path /usr/bin/python3 - "$mesh" "$tolerance" "$threads" "$work/py" <<'PY'
import sys, time
start = time.perf_counter()
import papercraft
V, F = papercraft.load(sys.argv[1])
name = sys.argv[1].rsplit("/", 1)[-1].rsplit(".", 1)[0]
result = papercraft.run(V, F, tolerance=sys.argv[2], threads=int(sys.argv[3]), name=name)
seconds = time.perf_counter() - start
result.write(sys.argv[4])
print(seconds)
PY
)
    best_cli=$(python3 -c "print(min(float('$best_cli'), $cli))")
    best_py=$(python3 -c "print(min(float('$best_py'), $py))")
  done
  same=yes
  for file in strips.json pieces.json; do
    cmp -s "$work/cli/$name/$file" "$work/py/$name/$file" || same="no ($file differs)"
  done
  [[ $same == yes ]] || status=1
  python3 -c "print(f'| $name | {$best_cli:.2f} | {$best_py:.2f} | {$best_py / $best_cli:.3f} | $same |')"
done
exit $status
