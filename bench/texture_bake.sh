#!/usr/bin/env bash
# Bake speed and PDF size on textured models of about 20k faces (issue: bake under 2 s on one
# thread, PDF under 20 MB at A4, 300 dpi).
#
#   bench/texture_bake.sh [BUILD_DIR] [MESH.off ...]
#
# Each mesh (default: libcgal-demo's camel and bear_bis) gets a UV per face corner and a
# 2048x2048 PNG (bench/textured_model.py), is run at 2% with one thread, and prints faces,
# pages, the seconds of the bake (report.json "texture".bake_seconds: sampling the surface
# for every printed pixel, bleed included; wall and CPU, the CPU seconds being what one thread
# takes when it has a core to itself), the pixels baked and the size of pattern.pdf.
# Pages are rendered to WORK/<name>/page-*.png (pdftoppm, 60 dpi) to look at.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
shift || true
papercraft=$build/runner/papercraft
meshes_dir=$build/cgal-data/data/meshes
[ -d "$meshes_dir" ] || meshes_dir=/usr/share/doc/libcgal-demo/examples/data/meshes
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=("$meshes_dir/camel.off" "$meshes_dir/bear_bis.off")
work=${WORK:-$(mktemp -d /tmp/texture-bake.XXXXXX)}
printf '| mesh | faces | pages | bake s wall (1 thread) | bake s CPU | pixels baked | pattern.pdf MB |\n|---|---:|---:|---:|---:|---:|---:|\n'
for mesh in "${meshes[@]}"; do
  name=$(basename "${mesh%.*}")
  python3 "$here/textured_model.py" "$mesh" "$work/models"
  "$papercraft" run "$work/models/$name.obj" -t 2% -j 1 -o "$work/out" >/dev/null 2>&1 || true
  report=$work/out/$name/report.json
  if [ ! -f "$report" ]; then echo "| $name | failed | | | | | |"; continue; fi
  python3 - "$report" "$work/out/$name/pattern.pdf" "$name" <<'PY'
import json, os, sys
r = json.load(open(sys.argv[1]))
t = r["texture"]
print("| %s | %d | %d | %.2f | %.2f | %.1f M | %.1f |" % (
    sys.argv[3], r["input"]["faces"], r["result"]["pages"], t["bake_seconds"],
    t["bake_cpu_seconds"],
    t["baked_pixels"] / 1e6, os.path.getsize(sys.argv[2]) / 1e6))
PY
  pdftoppm -r 60 -png "$work/out/$name/pattern.pdf" "$work/out/$name/page" 2>/dev/null || true
done
echo "work: $work"
