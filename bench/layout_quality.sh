#!/usr/bin/env bash
# The pages a maker prints, over every libcgal-demo mesh (or the given meshes) at one tolerance
# and height: each mesh is laid out twice, with layout.pages (nesting by outlines) and with
# layout.rectangles (MaxRects, the packer before), everything else the same. Prints per mesh
# the pages of each, the mean fill of every page but the last, seams without a tab (nor a
# joining strip), the smallest text, the overlapping texts and the joining strips (report.json
# "layout"), the layout node's seconds, the segments its SVG pages print with zero length, the
# seam sides whose partner piece is printed on the same page (pieces.json); then
# the totals and the five meshes whose page count fell the most.
#
#   bench/layout_quality.sh                               # all meshes, 2%, 200 mm
#   bench/layout_quality.sh --tolerance 5% a.off b.off
#
# Options: --tolerance T (2%), --height MM (200), --threads N (2), --max-faces N (30000),
#          --timeout S (300), --work DIR (build/layout-quality), --bin PATH,
#          --nest-only (one run per mesh: the rectangle pages from report.json's
#          rectangle_pages, the same pieces packed by MaxRects in that run; no rectangle fill
#          or seconds, printed as nan)
# Exit status 0 (findings are data); 2 for a bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tolerance=2%
height=200
threads=2
max_faces=30000
timeout_s=300
work=$root/build/layout-quality
bin=$root/build/runner/papercraft
declare -a meshes=()
declare -a variants=(nest rect)

. "$root/bench/lib.sh"
while [[ $# -gt 0 ]]; do
  case $1 in
    --tolerance) tolerance=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --max-faces) max_faces=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --nest-only) variants=(nest); shift ;;
    -h|--help) usage ;;
    -*) echo "layout_quality.sh: unknown option $1" >&2; usage ;;
    *) meshes+=("$1"); shift ;;
  esac
done
if [[ ${#meshes[@]} -eq 0 ]]; then
  mapfile -t meshes < <(ls "$("$root/bench/cgal_meshes.sh")"/*.off)
fi
mkdir -p "$work"
cp "$bin" "$work/papercraft"
sed 's/impl: layout.pages, /impl: layout.rectangles, /' "$root/configs/default.yaml" >"$work/rectangles.yaml"
grep -q layout.rectangles "$work/rectangles.yaml" || { echo "no layout.pages in default.yaml" >&2; exit 2; }


rows=$work/rows.tsv
: >"$rows"
for mesh in "${meshes[@]}"; do
  if [[ $max_faces -gt 0 && $mesh == *.off && $(faces_of "$mesh") -gt $max_faces ]]; then continue; fi
  name=$(basename "${mesh%.*}")
  ok=1
  for variant in "${variants[@]}"; do
    args=()
    [[ $variant == rect ]] && args=(-c "$work/rectangles.yaml")
    if ! timeout "$timeout_s" "$work/papercraft" run "$mesh" --tolerance "$tolerance" \
        --height "$height" --threads "$threads" --out "$work/$variant" -q "${args[@]}" \
        >/dev/null 2>&1; then ok=0; fi
  done
  [[ $ok -eq 1 ]] || continue
  rect_report=$work/rect/$name/report.json
  [[ ${#variants[@]} -eq 2 ]] || rect_report=-
  python3 - "$work/nest/$name/report.json" "$rect_report" "$name" >>"$rows" <<'PY'
import glob, json, os, re, sys
n = json.load(open(sys.argv[1]))
# Segments that print with zero length (a point repeated, as the SVG writes it) in any path.
zero = 0
for svg in glob.glob(os.path.join(os.path.dirname(sys.argv[1]), "pattern-*.svg")):
    for d in re.findall(r' d="([^"]*)"', open(svg).read()):
        previous = None
        for command, point in re.findall(r'([MLZ])\s*([-\d.e]+,[-\d.e]+)?', d):
            if command == "L" and point == previous: zero += 1
            previous = point if command in "ML" else None
r = json.load(open(sys.argv[2])) if sys.argv[2] != "-" else {
    "layout": {"pages": n["layout"]["rectangle_pages"], "page_fill": [float("nan")] * 2},
    "timing": {"nodes": {"layout": {"seconds": float("nan")}}}}
ln, lr = n["layout"], r["layout"]
# Seam sides whose partner piece is printed on the same page (pieces.json).
glued = same = 0
pieces_json = os.path.join(os.path.dirname(sys.argv[1]), "pieces.json")
if os.path.exists(pieces_json):
    pieces = json.load(open(pieces_json))["pieces"]
    page_of = {p["name"]: p["page"] for p in pieces}
    for p in pieces:
        for seam in p.get("seams", []):
            if seam.get("partner") in page_of:
                glued += 1
                same += page_of[seam["partner"]] == p["page"]
def fill(l):
    f = l["page_fill"]
    return sum(f[:-1]) / (len(f) - 1) if len(f) > 1 else float("nan")
print("\t".join(str(x) for x in [sys.argv[3], ln["pages"], lr["pages"], f"{fill(ln):.3f}", f"{fill(lr):.3f}",
      ln["seams"], ln["seams_without_tab"], ln["smallest_text_mm"], ln["overlapping_text"],
      ln.get("joining_strips", 0),
      f'{n["timing"]["nodes"]["layout"]["seconds"]:.3f}', f'{r["timing"]["nodes"]["layout"]["seconds"]:.3f}',
      zero, same, glued]))
PY
done
python3 - "$rows" <<'PY'
import sys, math
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip()]
print("| mesh | pages nest | pages rect | fill nest | fill rect | seams | no tab | smallest text mm | overlapping text | joining strips | layout s nest | layout s rect | zero-length segments | partner on the page |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
same = sum(int(r[13]) for r in rows); glued = sum(int(r[14]) for r in rows)
for r in rows: r[13] = f"{int(r[13])}/{int(r.pop(14))}"
for r in rows: print("| " + " | ".join(r) + " |")
pn = sum(int(r[1]) for r in rows); pr = sum(int(r[2]) for r in rows)
def mean(i):
    v = [float(r[i]) for r in rows if not math.isnan(float(r[i]))]
    return sum(v) / len(v) if v else float("nan")
print()
print(f"{len(rows)} meshes: pages {pn} nested vs {pr} rectangles ({pn / max(pr, 1):.3f}); "
      f"mean fill but last page {mean(3):.3f} vs {mean(4):.3f}; seams without a tab "
      f"{sum(int(r[6]) for r in rows)} of {sum(int(r[5]) for r in rows)}; smallest text "
      f"{min(float(r[7]) for r in rows):.2f} mm; overlapping texts {sum(int(r[8]) for r in rows)}; "
      f"joining strips {sum(int(r[9]) for r in rows)}; "
      f"layout seconds {sum(float(r[10]) for r in rows):.1f} vs {sum(float(r[11]) for r in rows):.1f}; "
      f"segments printed with zero length {sum(int(r[12]) for r in rows)}; seam sides with "
      f"their partner on the same page {same} of {glued}")
drop = sorted(rows, key=lambda r: int(r[1]) - int(r[2]))[:5]
print("largest page drops: " + ", ".join(f"{r[0]} {r[2]} -> {r[1]}" for r in drop))
PY
