#!/usr/bin/env bash
# What the patterns cost a person to build: every libcgal-demo mesh (or the given meshes) at each
# tolerance, laid out at one height, and per model the assembly effort (report.json "effort",
# docs/pieces.md) with each of its terms, the 3D strips, whether the result is certified, the
# merge node's seconds and the run's; then the sums per tolerance. Compare two builds (--bin)
# or two configs (--config, e.g. a merge.none pipeline) by running it twice.
#
#   bench/effort.sh                                  # all meshes, 2% and 5%, 200 mm
#   bench/effort.sh --tolerances "2%" eight.off cactus.off
#   bench/effort.sh --config nomerge.yaml --work build/effort-nomerge --max-faces 30000
#
# Options: --tolerances "T ..." (2% 5%), --height MM (200), --threads N (2), --max-faces N (0:
#          all), --timeout S (600), --work DIR (build/effort), --bin PATH, --config FILE
# A model that fails or runs past the timeout is listed as failed and left out of the sums.
# Exit status 0 (findings are data); 2 for a bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tolerances="2% 5%"
height=200
threads=2
max_faces=0
timeout_s=600
work=$root/build/effort
bin=$root/build/runner/papercraft
config=
declare -a meshes=()

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
    --config) config=$2; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "effort.sh: unknown option $1" >&2; usage ;;
    *) meshes+=("$1"); shift ;;
  esac
done
if [[ ${#meshes[@]} -eq 0 ]]; then
  mapfile -t meshes < <(ls "$("$root/bench/cgal_meshes.sh")"/*.off)
fi
mkdir -p "$work"
cp "$bin" "$work/papercraft"
config_args=()
[[ -n $config ]] && config_args=(-c "$config")


rows=$work/rows.tsv
: >"$rows"
for tolerance in $tolerances; do
  out=$work/${tolerance//%/pct}
  for mesh in "${meshes[@]}"; do
    if [[ $max_faces -gt 0 && $mesh == *.off && $(faces_of "$mesh") -gt $max_faces ]]; then continue; fi
    name=$(basename "${mesh%.*}")
    if ! timeout "$timeout_s" "$work/papercraft" run "$mesh" --tolerance "$tolerance" \
        --height "$height" --threads "$threads" --out "$out" -q "${config_args[@]}" \
        >/dev/null 2>&1 || [[ ! -f $out/$name/report.json ]]; then
      printf '%s\t%s\tfailed\n' "$name" "$tolerance" >>"$rows"
      continue
    fi
    python3 - "$out/$name/report.json" "$name" "$tolerance" >>"$rows" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
e = r["effort"]
nodes = r["timing"]["nodes"]
merge = sum(v["seconds"] for k, v in nodes.items() if k.startswith("merge"))
print("\t".join(str(x) for x in [sys.argv[2], sys.argv[3], f'{e["total"]:.2f}', e["things_to_cut"],
      e["printed_pieces"], e["joining_strips"], e["seam_chains"], e["self_seams"],
      f'{e["glue_length_mm"] / 1000:.3f}', e["sawtooth_corners"], e["small_pieces"],
      e["narrow_pieces"], r["result"]["strips_3d"], r["layout"]["pages"],
      int(r["result"]["certified"]), f"{merge:.2f}", f'{r["timing"]["total_seconds"]:.2f}']))
PY
  done
done
python3 - "$rows" <<'PY'
import sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip()]
head = ["mesh", "tolerance", "effort", "things to cut", "pieces", "joining strips", "seams",
        "self seams", "glue m", "sawtooth", "small", "narrow", "3D strips", "pages", "certified",
        "merge s", "run s"]
print("| " + " | ".join(head) + " |")
print("|---|---|" + "---:|" * (len(head) - 2))
for r in rows:
    print("| " + " | ".join(r + [""] * (len(head) - len(r))) + " |")
print()
for tolerance in dict.fromkeys(r[1] for r in rows):
    done = [r for r in rows if r[1] == tolerance and r[2] != "failed"]
    failed = [r[0] for r in rows if r[1] == tolerance and r[2] == "failed"]
    if not done:
        continue
    sums = [sum(float(r[i]) for r in done) for i in range(2, len(head))]
    slowest = max(done, key=lambda r: float(r[15]))
    print(f"{tolerance}: {len(done)} models, effort {sums[0]:.1f}; things to cut {sums[1]:.0f} "
          f"({sums[2]:.0f} pieces, {sums[3]:.0f} joining strips); seams {sums[4]:.0f} "
          f"({sums[5]:.0f} of a piece with itself); glue {sums[6]:.2f} m; sawtooth corners "
          f"{sums[7]:.0f}; small {sums[8]:.0f}; narrow {sums[9]:.0f}; 3D strips {sums[10]:.0f}; "
          f"pages {sums[11]:.0f}; certified {sums[12]:.0f}/{len(done)}; merge {sums[13]:.1f} s "
          f"(slowest {slowest[0]} {slowest[15]} s) of {sums[14]:.1f} s"
          + (f"; failed: {' '.join(failed)}" if failed else ""))
PY
