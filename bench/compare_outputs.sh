#!/usr/bin/env bash
# Compares two papercraft binaries on real meshes: runs `papercraft run MESH --tolerance T
# --threads 1` with each, one after the other (old, new, old, new, ... so both see the same
# machine load), and checks that approximation.obj and strips.json are byte-identical. Prints a
# row per mesh and tolerance that is not identical (or failed with one binary only), then the
# counts and the pipeline seconds (the model's wall seconds in run.json, or batch.json of binaries
# older than run.json; the fastest of --repeat runs) summed per tolerance
# over the meshes both binaries ran, with the ratio new / old.
#
#   bench/compare_outputs.sh OLD_BINARY NEW_BINARY                    # every *.off of libcgal-demo
#   bench/compare_outputs.sh --tolerances 2% OLD NEW a.off b.obj     # a given list
#
# Options:
#   --tolerances "T..."   tolerances (default "2% 5%")
#   --max-faces N         skip meshes with more faces (OFF header; default 30000, 0 = none)
#   --timeout S           per-run limit in seconds (default 120)
#   --repeat R            runs per binary and mesh, the fastest counts for the time (default 1)
#   --files "F..."        the outputs compared (default "approximation.obj strips.json")
#   --work DIR            where runs write (default build/compare-outputs)
#   --meshes DIR          folder of meshes when none are given (default: bench/cgal_meshes.sh)
#
# The binaries are copied into --work first, so a rebuild during the runs does not mix versions.
# Exit status: 0 when every compared output is identical and no mesh failed with only one of the
# binaries, 1 otherwise, 2 for a bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tolerances="2% 5%"
max_faces=30000
timeout_s=120
repeat=1
files="approximation.obj strips.json"
work=$root/build/compare-outputs
meshes_dir=""
declare -a positional=()

. "$root/bench/lib.sh"

while [[ $# -gt 0 ]]; do
  case $1 in
    --tolerances) tolerances=$2; shift 2 ;;
    --max-faces) max_faces=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --files) files=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --meshes) meshes_dir=$2; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "compare_outputs.sh: unknown option $1" >&2; usage ;;
    *) positional+=("$1"); shift ;;
  esac
done
[[ ${#positional[@]} -ge 2 ]] || usage
for b in "${positional[0]}" "${positional[1]}"; do
  [[ -x $b ]] || { echo "compare_outputs.sh: $b is not an executable" >&2; exit 2; }
done

mkdir -p "$work"
cp "${positional[0]}" "$work/old-papercraft"
cp "${positional[1]}" "$work/new-papercraft"
declare -a meshes=("${positional[@]:2}")
if [[ ${#meshes[@]} -eq 0 ]]; then
  [[ -n $meshes_dir ]] || meshes_dir=$("$root/bench/cgal_meshes.sh")
  mapfile -t meshes < <(ls "$meshes_dir"/*.off)
fi


# run BIN MESH TOL DIR: writes DIR/{status,seconds,error}; outputs in DIR/out/<name>/
run_one() {
  local bin=$1 mesh=$2 tol=$3 dir=$4 best="" rc
  for ((r = 0; r < repeat; r++)); do
    rm -rf "$dir/out"
    set +e
    timeout "$timeout_s" "$bin" run "$mesh" --tolerance "$tol" --threads 1 --out "$dir/out" -q \
      >/dev/null 2>"$dir/stderr"
    rc=$?
    set -e
    if [[ $rc -ne 0 ]]; then
      if [[ $rc -eq 124 ]]; then echo timeout >"$dir/status"; else echo "failed($rc)" >"$dir/status"; fi
      grep -v '^\s*$' "$dir/stderr" | tail -n 1 >"$dir/error" || true
      return
    fi
    local s
    # run.json and wall_seconds since batches keep their own summaries; batch.json and seconds before
    s=$(python3 -c 'import json,os,sys
d = sys.argv[1]
f = os.path.join(d, "run.json") if os.path.exists(os.path.join(d, "run.json")) else os.path.join(d, "batch.json")
r = json.load(open(f))["results"][0]
print(r["wall_seconds"] if "wall_seconds" in r else r["seconds"])' "$dir/out")
    if [[ -z $best ]] || python3 -c "import sys; sys.exit(0 if $s < $best else 1)"; then best=$s; fi
  done
  echo ok >"$dir/status"
  echo "$best" >"$dir/seconds"
}

declare -A same=() differ=() both_failed=() one_failed=() old_sum=() new_sum=()
problems=0
for tol in $tolerances; do
  same[$tol]=0; differ[$tol]=0; both_failed[$tol]=0; one_failed[$tol]=0
  old_sum[$tol]=0; new_sum[$tol]=0
done

printf '| mesh | tolerance | old | new | outputs |\n|---|---|---|---|---|\n'
for mesh in "${meshes[@]}"; do
  faces=$(faces_of "$mesh")
  if [[ $max_faces -gt 0 && $faces -gt $max_faces ]]; then continue; fi
  name=$(basename "${mesh%.*}")
  for tol in $tolerances; do
    old=$work/old/$name-${tol%\%}
    new=$work/new/$name-${tol%\%}
    rm -rf "$old" "$new"
    mkdir -p "$old" "$new"
    run_one "$work/old-papercraft" "$mesh" "$tol" "$old"
    run_one "$work/new-papercraft" "$mesh" "$tol" "$new"
    so=$(cat "$old/status")
    sn=$(cat "$new/status")
    if [[ $so != ok && $sn != ok ]]; then
      both_failed[$tol]=$((both_failed[$tol] + 1))
      if ! cmp -s "$old/error" "$new/error"; then
        printf '| %s | %s | %s | %s | errors differ: `%s` / `%s` |\n' "$name" "$tol" "$so" "$sn" \
          "$(cat "$old/error")" "$(cat "$new/error")"
      fi
      continue
    fi
    if [[ $so != ok || $sn != ok ]]; then
      one_failed[$tol]=$((one_failed[$tol] + 1))
      problems=$((problems + 1))
      printf '| %s | %s | %s | %s | `%s` |\n' "$name" "$tol" "$so" "$sn" \
        "$(cat "$old/error" "$new/error" 2>/dev/null | head -c 200)"
      continue
    fi
    diffs=""
    for f in $files; do
      # A file neither run wrote (a second page of a one-page pattern) is no difference.
      [[ -e $old/out/$name/$f || -e $new/out/$name/$f ]] || continue
      if ! cmp -s "$old/out/$name/$f" "$new/out/$name/$f"; then diffs="$diffs $f"; fi
    done
    old_sum[$tol]=$(python3 -c "print(${old_sum[$tol]} + $(cat "$old/seconds"))")
    new_sum[$tol]=$(python3 -c "print(${new_sum[$tol]} + $(cat "$new/seconds"))")
    if [[ -n $diffs ]]; then
      differ[$tol]=$((differ[$tol] + 1))
      problems=$((problems + 1))
      printf '| %s | %s | ok | ok | differ:%s |\n' "$name" "$tol" "$diffs"
    else
      same[$tol]=$((same[$tol] + 1))
    fi
    rm -rf "$old/out" "$new/out"
  done
done

echo
printf '| tolerance | identical | different | failed with one binary | failed with both | old s | new s | new / old |\n'
printf '|---|---:|---:|---:|---:|---:|---:|---:|\n'
for tol in $tolerances; do
  ratio=$(python3 -c "o, n = ${old_sum[$tol]}, ${new_sum[$tol]}; print(f'{n / o:.3f}' if o > 0 else '-')")
  printf '| %s | %d | %d | %d | %d | %.2f | %.2f | %s |\n' "$tol" "${same[$tol]}" "${differ[$tol]}" \
    "${one_failed[$tol]}" "${both_failed[$tol]}" "${old_sum[$tol]}" "${new_sum[$tol]}" "$ratio"
done
[[ $problems -eq 0 ]]
