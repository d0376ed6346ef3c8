#!/usr/bin/env bash
# A certified pattern against the time CGAL needs to check it: runs `papercraft run MESH
# --tolerance T --threads N` for every mesh with each thread count, and checks the one-thread
# run's approximation.obj against the input with CGAL's bounded_error_symmetric_Hausdorff_distance
# (build/bench/cgal_hausdorff_check, error bound a share of the bounding-box diagonal). Prints a
# markdown table: per mesh the faces, the command's wall seconds per thread count and its CPU
# seconds with the first, CGAL's check seconds (wall and CPU, the distance call alone) and the
# ratios run / check, the certified bound, and each node's seconds of the first run
# (report.json); then the sums, and on how many meshes the run takes at most the check's time.
# On a shared machine the CPU ratio is the one to trust. With --baseline OLD_BIN, OLD_BIN runs
# each mesh too (first thread count, right after the new binary so both see the same machine
# load) and the table adds its seconds and CPU new / old.
#
#   bench/speed.sh                                     # every libcgal-demo mesh, 2%, 1 and 2 threads
#   bench/speed.sh --meshes DIR --max-faces 30000 --markdown bench/speed-table.md
#   bench/speed.sh --baseline /tmp/papercraft-old eight.off elephant.off
#
# Options:
#   --meshes DIR          folder of meshes when none are given (default: bench/cgal_meshes.sh)
#   --tolerance T         tolerance of every run (default 2%)
#   --threads "N..."      thread counts (default "1 2"); the first one's outputs are checked
#   --max-faces N         skip meshes with more faces (OFF header; 0 = none, the default)
#   --timeout S           per-run limit in seconds (default 300)
#   --check-timeout S     per-check limit in seconds (default 900)
#   --error-bound S       CGAL's error bound as a share of the diagonal (default 1e-6)
#   --bin PATH            papercraft binary (default build/runner/papercraft)
#   --baseline PATH       a second binary timed the same way, one thread
#   --checker PATH        the CGAL checker (default build/bench/cgal_hausdorff_check)
#   --no-check            leave CGAL out (no check columns)
#   --work DIR            where runs write (default build/speed); checks are cached in
#                         DIR/checks.tsv by the files' checksums, so a rerun with identical
#                         outputs does not check again
#   --markdown FILE       also write the table to FILE
#   --report              run nothing: print the table of the runs in --work (rows.tsv) so far,
#                         as when a long measurement was stopped (give the same --threads and
#                         --baseline)
#
# Setup: the check needs CGAL. When build/bench/cgal_hausdorff_check is missing, the script
# installs libcgal-dev with apt-get (as root or with sudo) if it is missing, configures the
# build again so that CMake finds CGAL, and builds that target alone. CGAL is never a
# requirement of papercraft itself. Exit status 0 (slow meshes are findings); 2 for a bad
# command line; 1 when the checker cannot be set up.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
meshes_dir=""
tolerance=2%
threads_list="1 2"
max_faces=0
timeout_s=300
check_timeout=900
error_bound=1e-6
bin=$root/build/runner/papercraft
baseline=""
checker=$root/build/bench/cgal_hausdorff_check
check=1
work=$root/build/speed
markdown=""
report_only=0
declare -a meshes=()

. "$root/bench/lib.sh"
while [[ $# -gt 0 ]]; do
  case $1 in
    --meshes) meshes_dir=$2; shift 2 ;;
    --tolerance) tolerance=$2; shift 2 ;;
    --threads) threads_list=$2; shift 2 ;;
    --max-faces) max_faces=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --check-timeout) check_timeout=$2; shift 2 ;;
    --error-bound) error_bound=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --baseline) baseline=$2; shift 2 ;;
    --checker) checker=$2; shift 2 ;;
    --no-check) check=0; shift ;;
    --work) work=$2; shift 2 ;;
    --markdown) markdown=$2; shift 2 ;;
    --report) report_only=1; shift ;;
    -h|--help) usage ;;
    -*) echo "speed.sh: unknown option $1" >&2; usage ;;
    *) meshes+=("$1"); shift ;;
  esac
done
[[ -x $bin ]] || { echo "speed.sh: $bin is not an executable" >&2; exit 2; }
[[ -z $baseline || -x $baseline ]] || { echo "speed.sh: $baseline is not an executable" >&2; exit 2; }
if [[ $report_only -eq 1 ]]; then
  meshes=()
elif [[ ${#meshes[@]} -eq 0 ]]; then
  [[ -n $meshes_dir ]] || meshes_dir=$("$root/bench/cgal_meshes.sh")
  mapfile -t meshes < <(ls "$meshes_dir"/*.off)
fi

setup_checker() {
  [[ -x $checker ]] && return 0
  local sudo=()
  if ! dpkg -s libcgal-dev >/dev/null 2>&1; then
    if [[ $(id -u) -ne 0 ]]; then
      command -v sudo >/dev/null || { echo "speed.sh: need root or sudo to install libcgal-dev" >&2; return 1; }
      sudo=(sudo)
    fi
    echo "speed.sh: installing libcgal-dev" >&2
    "${sudo[@]}" apt-get install -y -qq --no-install-recommends libcgal-dev >&2
  fi
  cmake -S "$root" -B "$root/build" >/dev/null
  cmake --build "$root/build" --target cgal_hausdorff_check >&2
  [[ -x $checker ]]
}
if [[ $check -eq 1 && $report_only -eq 0 ]]; then
  setup_checker || { echo "speed.sh: no CGAL checker (run with --no-check to time the runs alone)" >&2; exit 1; }
fi

mkdir -p "$work"
checks=$work/checks.tsv
touch "$checks"
rows=$work/rows.tsv
if [[ $report_only -eq 0 ]]; then
  cp "$bin" "$work/new-papercraft"
  [[ -n $baseline ]] && cp "$baseline" "$work/old-papercraft"
  : >"$rows"
fi

# run_one BIN MESH THREADS DIR: prints "status wall_seconds cpu_seconds" (the whole command's,
# start-up included; CPU is user + system) and leaves the outputs in DIR/<name>/.
run_one() {
  local bin=$1 mesh=$2 threads=$3 dir=$4 rc
  rm -rf "$dir"
  set +e
  /usr/bin/time -f "%e %U %S" -o "$dir.time" timeout "$timeout_s" "$bin" run "$mesh" \
    --tolerance "$tolerance" --threads "$threads" --out "$dir" -q >/dev/null 2>"$dir.stderr"
  rc=$?
  set -e
  if [[ $rc -eq 124 ]]; then echo "timeout - -"; elif [[ $rc -ne 0 ]]; then echo "failed($rc) - -"; else
    awk 'END { print "ok", $1, $2 + $3 }' "$dir.time"
  fi
}

# check_one MESH APPROXIMATION: prints "wall_seconds cpu_seconds hausdorff bound" of CGAL's
# check, cached by the files' checksums.
check_one() {
  local key line
  key=$(cat "$1" "$2" | sha1sum | cut -c1-40)-$error_bound
  line=$(awk -v k="$key" '$1 == k { print $2, $3, $4, $5 }' "$checks" | tail -n 1)
  if [[ -z $line ]]; then
    line=$(timeout "$check_timeout" "$checker" "$1" "$2" --error-bound "$error_bound" 2>/dev/null |
      awk '{ print $6, $8, $2, $4 }' || true)
    [[ -n $line ]] || line="timeout - - -"
    printf '%s %s\n' "$key" "$line" >>"$checks"
  fi
  echo "$line"
}

for mesh in "${meshes[@]}"; do
  faces=$(faces_of "$mesh")
  if [[ $max_faces -gt 0 && $faces -gt $max_faces ]]; then continue; fi
  name=$(basename "${mesh%.*}")
  runs=()
  first_dir=""
  old_run="- - -"
  for threads in $threads_list; do
    dir=$work/out-$threads
    runs+=($(run_one "$work/new-papercraft" "$mesh" "$threads" "$dir"))
    if [[ -z $first_dir ]]; then
      first_dir=$dir
      [[ -n $baseline ]] && old_run=$(run_one "$work/old-papercraft" "$mesh" "$threads" "$work/old")
    fi
  done
  check_line="- - - -"
  if [[ $check -eq 1 && ${runs[0]} == ok && -f $first_dir/$name/approximation.obj ]]; then
    check_line=$(check_one "$mesh" "$first_dir/$name/approximation.obj")
  fi
  report=$first_dir/$name/report.json
  [[ -f $report && ${runs[0]} == ok ]] || report=-
  python3 - "$name" "$faces" "$report" $old_run $check_line "${runs[@]}" >>"$rows" <<'PY'
import json, sys
name, faces, report = sys.argv[1:4]
old, check, runs = sys.argv[4:7], sys.argv[7:11], sys.argv[11:]
nodes = {}
bound = "-"
if report != "-":
    r = json.load(open(report))
    nodes = {k: v["seconds"] for k, v in r["timing"]["nodes"].items()}
    bound = f'{r["result"]["hausdorff_bound_percent"]:.3f}'
print(json.dumps({"name": name, "faces": int(faces), "runs": runs, "old": old, "check": check,
                  "bound": bound, "nodes": nodes}))
PY
  rm -rf "$work"/out-* "$work/old"
done

python3 - "$rows" "$threads_list" "$tolerance" "$error_bound" "$check" "${baseline:+1}" <<'PY' |
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
threads = sys.argv[2].split()
tolerance, error_bound = sys.argv[3], sys.argv[4]
check, baseline = sys.argv[5] == "1", sys.argv[6] == "1"
stages = ["load", "proxy", "segment", "select", "ruled", "hausdorff", "cut", "unfold", "merge",
          "layout", "export"]
def num(x):
    try:
        return float(x)
    except ValueError:
        return None
def fmt(x):
    return "-" if x is None else f"{x:.2f}"
def ratio(a, b):
    return "-" if a is None or not b else f"{a / b:.2f}"
head = ["mesh", "faces"] + [f"run s {t} thr" for t in threads] + ["run CPU s 1 thr"]
if baseline: head += ["baseline s", "baseline CPU s", "CPU new / baseline"]
if check:
    head += ["check s", "check CPU s"] + [f"run / check {t} thr" for t in threads]
    head += ["CPU run / check"]
head += ["bound %"] + [f"{s} s" for s in stages]
print(f"Tolerance {tolerance}; CGAL's error bound {error_bound} of the diagonal; run seconds are "
      f"the whole command's; node seconds of the {threads[0]}-thread run (report.json).\n")
print("| " + " | ".join(head) + " |")
print("|---|" + "---:|" * (len(head) - 1))
sums, within, within_cpu, complete = {}, {t: 0 for t in threads}, 0, 0
def add(key, value):
    if value is not None: sums[key] = sums.get(key, 0.0) + value
for r in rows:
    runs = [(r["runs"][3 * i], num(r["runs"][3 * i + 1]), num(r["runs"][3 * i + 2]))
            for i in range(len(threads))]
    ok = all(s == "ok" for s, _, _ in runs)
    cells = [r["name"], str(r["faces"])]
    cells += [fmt(w) if s == "ok" else s for s, w, _ in runs] + [fmt(runs[0][2])]
    old_wall, old_cpu = num(r["old"][1]), num(r["old"][2])
    if baseline: cells += [fmt(old_wall) if old_wall else r["old"][0], fmt(old_cpu), ratio(runs[0][2], old_cpu)]
    check_wall, check_cpu = num(r["check"][0]), num(r["check"][1])
    if check:
        cells += [fmt(check_wall) if check_wall is not None else r["check"][0], fmt(check_cpu)]
        cells += [ratio(w, check_wall) for _, w, _ in runs] + [ratio(runs[0][2], check_cpu)]
    cells += [r["bound"]] + [fmt(r["nodes"].get(s)) for s in stages]
    print("| " + " | ".join(cells) + " |")
    if not ok or (check and check_wall is None) or (baseline and old_cpu is None):
        continue
    complete += 1
    for t, (_, w, c) in zip(threads, runs):
        add(f"run {t}", w)
        if check and w <= check_wall: within[t] += 1
    add("cpu", runs[0][2])
    if check:
        add("check", check_wall); add("check cpu", check_cpu)
        if runs[0][2] <= check_cpu: within_cpu += 1
    if baseline: add("old", old_wall); add("old cpu", old_cpu)
    for s in stages: add(s, r["nodes"].get(s))
print()
failed = [r["name"] for r in rows if any(r["runs"][3 * i] != "ok" for i in range(len(threads)))]
print(f"{complete} of {len(rows)} meshes complete" +
      (f"; failed or past the limits: {' '.join(failed)}" if failed else "") + ".")
for t in threads:
    line = f"- {t} thread(s): runs {sums.get(f'run {t}', 0):.1f} s"
    if check and sums.get("check"):
        line += (f", CGAL checks {sums['check']:.1f} s, ratio {sums[f'run {t}'] / sums['check']:.2f}; "
                 f"run <= check on {within[t]} of {complete}")
    print(line)
if check and sums.get("check cpu"):
    print(f"- CPU, one thread: runs {sums.get('cpu', 0):.1f} s, CGAL checks {sums['check cpu']:.1f} s, "
          f"ratio {sums.get('cpu', 0) / sums['check cpu']:.2f}; run <= check on {within_cpu} of {complete}")
if baseline and sums.get("old cpu"):
    print(f"- baseline, one thread: {sums['old']:.1f} s, CPU {sums['old cpu']:.1f} s; CPU new / baseline "
          f"{sums['cpu'] / sums['old cpu']:.3f}")
total = sum(sums.get(s, 0.0) for s in stages)
if total > 0:
    print(f"- node seconds ({threads[0]} thread): " + ", ".join(
        f"{s} {sums.get(s, 0.0):.1f} ({100 * sums.get(s, 0.0) / total:.0f}%)" for s in stages))
PY
  if [[ -n $markdown ]]; then tee "$markdown"; else cat; fi
