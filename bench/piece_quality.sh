#!/usr/bin/env bash
# Runs papercraft on every libcgal-demo mesh (or the given meshes) at each tolerance and prints
# what build/bench/piece_quality finds on paper: pieces narrower than 3 mm over more than 25%
# of their area, pieces under 1 cm^2, seam edges without exactly one partner, labels whose
# two sides differ, the "unmatched" notes of report.json; then strips, flat strips and pages
# summed per tolerance, and whether every run is certified.
#
#   bench/piece_quality.sh                                   # all meshes, 2% and 5%, 200 mm
#   bench/piece_quality.sh --tolerances 2% --height 150 a.off b.obj
#
# Options:
#   --tolerances "T..."   (default "2% 5%")
#   --height MM           --height of each run (default 200)
#   --threads N           (default 2)
#   --max-faces N         skip OFF meshes with more faces (default 30000; 0: none)
#   --timeout S           per run (default 300)
#   --work DIR            (default build/piece-quality)
#   --bin PATH            (default build/runner/papercraft; copied first)
#   --config FILE         pipeline config of each run
#   -- ARGS               extra arguments for every run
# Exit status 0 (findings are data); 2 for a bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tolerances="2% 5%"
height=200
threads=2
max_faces=30000
timeout_s=300
work=$root/build/piece-quality
bin=$root/build/runner/papercraft
checker=$root/build/bench/piece_quality
declare -a extra=() meshes=()

. "$root/bench/lib.sh"
while [[ $# -gt 0 ]]; do
  case $1 in
    --tolerances) tolerances=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --max-faces) max_faces=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --config) extra+=(-c "$2"); shift 2 ;;
    --) shift; extra+=("$@"); break ;;
    -h|--help) usage ;;
    -*) echo "piece_quality.sh: unknown option $1" >&2; usage ;;
    *) meshes+=("$1"); shift ;;
  esac
done
[[ -x $checker ]] || { echo "piece_quality.sh: build $checker first" >&2; exit 2; }
if [[ ${#meshes[@]} -eq 0 ]]; then
  mapfile -t meshes < <(ls "$("$root/bench/cgal_meshes.sh")"/*.off)
fi
mkdir -p "$work"
cp "$bin" "$work/papercraft"


for tol in $tolerances; do
  out=$work/out-${tol%\%}
  rm -rf "$out"
  mkdir -p "$out"
  declare -a done_dirs=()
  failed=0 uncertified=0 strips=0 flat=0 pages=0
  for mesh in "${meshes[@]}"; do
    if [[ $max_faces -gt 0 && $mesh == *.off && $(faces_of "$mesh") -gt $max_faces ]]; then continue; fi
    name=$(basename "${mesh%.*}")
    if ! timeout "$timeout_s" "$work/papercraft" run "$mesh" --tolerance "$tol" --height "$height" \
      --threads "$threads" --out "$out" -q "${extra[@]}" >/dev/null 2>"$out/$name.stderr"; then
      failed=$((failed + 1))
      continue
    fi
    done_dirs+=("$out/$name")
    read -r s f p c < <(python3 -c 'import json,sys
r = json.load(open(sys.argv[1]))["result"]
print(r["strips_3d"], r["flat_strips"], r["pages"], int(r["certified"]))' "$out/$name/report.json")
    strips=$((strips + s)); flat=$((flat + f)); pages=$((pages + p))
    [[ $c -eq 1 ]] || uncertified=$((uncertified + 1))
  done
  echo "## $tol, ${height} mm: ${#done_dirs[@]} ran, $failed failed, $uncertified uncertified;" \
       "3D strips $strips, flat strips $flat, pages $pages"
  echo
  "$checker" "${done_dirs[@]}" 2>"$out/problems.txt" | grep -v '^| [^*|]* | [0-9]* | 0 | 0 | [0-9]* | [0-9]* | 0 | 0 | 0 | [0-9]* | 0 | 0 | 0 |$'
  echo
  unset done_dirs
done
