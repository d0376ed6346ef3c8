#!/usr/bin/env bash
# Whole-pipeline benchmark on real meshes: runs `papercraft run MESH --tolerance T --threads N
# --out DIR -q` for every mesh and tolerance, each under a timeout and /usr/bin/time -v, and
# prints a markdown table: mesh, faces, tolerance, status, 3D strips, flat strips, pages,
# certified bound (% of the largest side), pipeline seconds (run.json), wall seconds, peak RSS
# (MiB); under it, a count per tolerance and the error message of every failed run.
#
#   bench/pipeline_meshes.sh                                # every *.off of bench/cgal_meshes.sh
#   bench/pipeline_meshes.sh --markdown out.md a.off b.obj  # a given list
#   bench/pipeline_meshes.sh --tolerances "2%" --timeout 60 --max-faces-at 1%=200000
#   bench/pipeline_meshes.sh --speedup build/cgal-data/data/meshes/bunny00.off --copies 4
#
# Options:
#   --tolerances "T..."   tolerances to run (default "1% 2% 5%")
#   --timeout S           per-run wall-clock limit in seconds (default 120)
#   --threads N           --threads of each run (default 1)
#   --config FILE         pipeline config of each run (-c FILE; default: the built-in one)
#   --meshes DIR          folder of meshes when none are given (default: bench/cgal_meshes.sh)
#   --glob PATTERN        file names taken from --meshes (default "*.off")
#   --max-faces N         skip meshes with more faces (from the file header; OFF only)
#   --max-faces-at T=N    skip meshes with more than N faces at tolerance T (repeatable)
#   --budget S            stop starting runs after S seconds in all; the rest are "skipped"
#   --markdown FILE       also write the table (and the failure list) to FILE
#   --work DIR            where runs write (default build/pipeline-bench); each run's outputs
#                         are deleted after reading, except report.json, run.json, logs
#   --bin PATH            the papercraft binary (default build/runner/papercraft); it is copied
#                         into --work first, so a rebuild during the runs does not mix versions
#   --report ROWS...      only print the table of earlier runs (their --work/rows.tsv files;
#                         a later file's run replaces an earlier row for the same mesh and
#                         tolerance, a skipped row does not, so a rerun of a subset merges in)
# Speed-up mode (instead of the table):
#   --speedup MESH        run a batch of --copies N (default 4) copies of MESH at --tolerance
#                         (default 2%) with --threads 1 and then --threads 2 (or --speedup-threads
#                         "1 2 ..."), --repeat R times each (default 1, the fastest counts), and
#                         print the wall times and the ratio against --threads 1.
#
# Meshes run in ascending order of face count. Exit status 0 even when runs fail (failures are
# findings, listed under the table); 2 for a bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tolerances="1% 2% 5%"
timeout_s=120
threads=1
config_args=()
meshes_dir=""
glob="*.off"
max_faces=""
declare -a max_faces_at=()
budget=""
markdown=""
work=$root/build/pipeline-bench
bin=$root/build/runner/papercraft
speedup=""
copies=4
speedup_tolerance=2%
speedup_threads="1 2"
repeat=1
declare -a inputs=()
report_only=0

. "$root/bench/lib.sh"

while [[ $# -gt 0 ]]; do
  case $1 in
    --tolerances) tolerances=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --config) config_args=(-c "$2"); shift 2 ;;
    --meshes) meshes_dir=$2; shift 2 ;;
    --glob) glob=$2; shift 2 ;;
    --max-faces) max_faces=$2; shift 2 ;;
    --max-faces-at) max_faces_at+=("$2"); shift 2 ;;
    --budget) budget=$2; shift 2 ;;
    --markdown) markdown=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --speedup) speedup=$2; shift 2 ;;
    --copies) copies=$2; shift 2 ;;
    --tolerance) speedup_tolerance=$2; shift 2 ;;
    --speedup-threads) speedup_threads=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --report) report_only=1; shift ;;
    -h|--help) usage ;;
    --) shift; inputs+=("$@"); break ;;
    -*) echo "pipeline_meshes.sh: unknown option $1" >&2; usage ;;
    *) inputs+=("$1"); shift ;;
  esac
done

[[ -x $bin ]] || { echo "pipeline_meshes.sh: $bin not found (ninja -C build papercraft)" >&2; exit 2; }
if [[ ! -x /usr/bin/time ]]; then
  echo "pipeline_meshes.sh: installing GNU time" >&2
  sudo=(); [[ $(id -u) -ne 0 ]] && sudo=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq time >&2 ||
    { "${sudo[@]}" apt-get update -qq >&2 && DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq time >&2; }
fi
command -v python3 >/dev/null || { echo "pipeline_meshes.sh: needs python3" >&2; exit 2; }
mkdir -p "$work"
work=$(cd "$work" && pwd)
if [[ $report_only -eq 0 ]]; then
  # Snapshot the binary: a rebuild while the runs go on must not mix two versions in one table.
  cp "$bin" "$work/papercraft.bin"
  echo "pipeline_meshes.sh: $bin ($(stat -c %y "$bin" | cut -d. -f1), sha1 $(sha1sum "$bin" | cut -c1-12)) copied to $work/papercraft.bin" >&2
  bin=$work/papercraft.bin
fi

# One run under timeout and /usr/bin/time: papercraft ARGS... ; sets run_rc.
# timeout is the child of time, so time's wait4 sees papercraft's peak RSS too.
timed_run() {
  local time_file=$1 log=$2; shift 2
  set +e
  /usr/bin/time -v -o "$time_file" timeout -k 5 "$timeout_s" "$bin" "$@" >"$log" 2>&1
  run_rc=$?
  set -e
}

# ---------------------------------------------------------------- speed-up mode
if [[ -n $speedup ]]; then
  [[ -f $speedup ]] || { echo "pipeline_meshes.sh: $speedup not found" >&2; exit 2; }
  dir=$work/speedup
  rm -rf "$dir"; mkdir -p "$dir/in"
  name=$(basename "$speedup"); stem=${name%.*}; ext=${name##*.}
  copies_list=()
  for ((i = 1; i <= copies; ++i)); do
    ln -s "$(cd "$(dirname "$speedup")" && pwd)/$name" "$dir/in/${stem}_$i.$ext"
    copies_list+=("$dir/in/${stem}_$i.$ext")
  done
  echo "batch of $copies copies of $name at $speedup_tolerance, timeout ${timeout_s}s, $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
  results=$dir/results.tsv; : >"$results"
  for ((r = 1; r <= repeat; ++r)); do
    for t in $speedup_threads; do
      out=$dir/t$t-r$r
      timed_run "$out.time" "$out.log" run "${copies_list[@]}" --tolerance "$speedup_tolerance" \
        "${config_args[@]}" --threads "$t" --out "$out" -q
      printf '%s\t%s\t%s\t%s\t%s\n' "$t" "$r" "$run_rc" "$out.time" "$out/run.json" >>"$results"
      rm -rf "$out"/"${stem}"_*/
    done
  done
  python3 - "$results" "$copies" "$name" "$speedup_tolerance" "$markdown" <<'PY'
import json, re, sys
results, copies, name, tol, markdown = sys.argv[1:6]
def wall(path):
    text = open(path).read()
    m = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", text)
    h, mi, s = m.groups()
    return int(h or 0) * 3600 + int(mi) * 60 + float(s)
def rss(path):
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(path).read())
    return int(m.group(1)) / 1024.0
best = {}
rows = []
for line in open(results):
    t, r, rc, tf, bj = line.rstrip("\n").split("\t")
    w = wall(tf)
    try:
        batch = json.load(open(bj)); failed = batch["failed"]
        model_s = sum(row.get("wall_seconds") or 0 for row in batch["results"])
    except Exception:
        failed, model_s = "?", float("nan")
    rows.append((int(t), int(r), int(rc), w, rss(tf), failed, model_s))
    if int(rc) == 0 and (int(t) not in best or w < best[int(t)]):
        best[int(t)] = w
lines = [f"Batch of {copies} copies of {name} at {tol}", "",
         "| threads | repeat | exit | wall s | peak RSS MiB | failed | sum of model s | speed-up vs 1 thread |",
         "|---:|---:|---:|---:|---:|---:|---:|---:|"]
for t, r, rc, w, m, failed, model_s in rows:
    ratio = f"{best[1] / w:.2f}" if 1 in best and rc == 0 else "-"
    lines.append(f"| {t} | {r} | {rc} | {w:.2f} | {m:.0f} | {failed} | {model_s:.2f} | {ratio} |")
if 1 in best:
    lines.append("")
    for t in sorted(best):
        if t != 1:
            lines.append(f"fastest wall time: 1 thread {best[1]:.2f} s, {t} threads {best[t]:.2f} s; "
                         f"speed-up {best[1] / best[t]:.2f}")
text = "\n".join(lines) + "\n"
print(text, end="")
if markdown:
    open(markdown, "w").write(text)
PY
  exit 0
fi

# ---------------------------------------------------------------- table mode
if [[ $report_only -eq 1 ]]; then
  row_files=("${inputs[@]}")
  inputs=()
  [[ ${#row_files[@]} -gt 0 ]] || { echo "pipeline_meshes.sh: --report needs rows.tsv files" >&2; exit 2; }
fi
if [[ $report_only -eq 0 && ${#inputs[@]} -eq 0 ]]; then
  [[ -n $meshes_dir ]] || meshes_dir=$("$root/bench/cgal_meshes.sh")
  shopt -s nullglob
  for f in "$meshes_dir"/$glob; do inputs+=("$f"); done
  shopt -u nullglob
  [[ ${#inputs[@]} -gt 0 ]] || { echo "pipeline_meshes.sh: no $glob in $meshes_dir" >&2; exit 2; }
fi

# Face counts from the headers (OFF; other formats: unknown, sorted last), ascending.
ordered=()
[[ $report_only -eq 1 ]] || mapfile -t ordered < <(python3 - "${inputs[@]}" <<'PY'
import sys
def off_faces(path):
    try:
        with open(path, "rb") as f:
            tokens = []
            for raw in f:
                line = raw.split(b"#", 1)[0].split()
                tokens += line
                if len(tokens) >= 3:
                    break
        if not tokens or not tokens[0].endswith(b"OFF"):
            return -1
        nums = tokens[1:]
        return int(nums[1])
    except Exception:
        return -1
rows = [(off_faces(p), p) for p in sys.argv[1:]]
rows.sort(key=lambda r: (r[0] < 0, r[0], r[1]))
for faces, path in rows:
    print(f"{faces}\t{path}")
PY
)

if [[ $report_only -eq 0 ]]; then
rows=$work/rows.tsv; : >"$rows"
row_files=("$rows")
start=$SECONDS
echo "pipeline_meshes.sh: ${#ordered[@]} meshes x tolerances {$tolerances}, --threads $threads, timeout ${timeout_s}s, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
for entry in "${ordered[@]}"; do
  faces=${entry%%$'\t'*}; mesh=${entry#*$'\t'}
  name=$(basename "$mesh"); stem=${name%.*}
  for tol in $tolerances; do
    skip=""
    if [[ -n $max_faces && $faces -gt $max_faces ]]; then skip="skipped (> $max_faces faces)"; fi
    for rule in "${max_faces_at[@]+"${max_faces_at[@]}"}"; do
      if [[ ${rule%%=*} == "$tol" && $faces -gt ${rule#*=} ]]; then skip="skipped (> ${rule#*=} faces at $tol)"; fi
    done
    if [[ -n $budget && $((SECONDS - start)) -ge $budget ]]; then skip="skipped (budget ${budget}s spent)"; fi
    tag=${stem}_${tol//%/pct}
    out=$work/runs/$tag
    if [[ -n $skip ]]; then
      printf '%s\t%s\t%s\t%s\t-\t%s\t%s\n' "$mesh" "$faces" "$tol" "$skip" "$out" "-" >>"$rows"
      continue
    fi
    rm -rf "$out"; mkdir -p "$out"
    timed_run "$out/time.txt" "$out/log.txt" run "$mesh" "${config_args[@]}" \
      --tolerance "$tol" --threads "$threads" \
      --out "$out" -q
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$mesh" "$faces" "$tol" "run" "$run_rc" "$out" "$stem" \
      "$timeout_s" >>"$rows"
    # keep report.json, run.json and the logs; drop the patterns
    find "$out" -mindepth 2 -type f ! -name report.json -delete 2>/dev/null || true
    printf '%s %-28s %-4s rc=%-3s %6.1fs\n' "$(date +%T)" "$name" "$tol" "$run_rc" \
      "$(grep -oP 'Elapsed \(wall clock\) time.*: \K.*' "$out/time.txt" | awk -F: '{s=0; for (i=1;i<=NF;i++) s=s*60+$i; print s}')" >&2
  done
done
fi

python3 - "$markdown" "$threads" "$timeout_s" "${row_files[@]}" <<'PY'
import json, math, os, re, sys
markdown, threads, timeout_s = sys.argv[1:4]
row_files = sys.argv[4:]

def wall_and_rss(path):
    try:
        text = open(path).read()
    except OSError:
        return None, None
    m = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", text)
    wall = int(m.group(1) or 0) * 3600 + int(m.group(2)) * 60 + float(m.group(3)) if m else None
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    rss = int(m.group(1)) / 1024.0 if m else None
    return wall, rss

def last_error_line(log):
    try:
        lines = [l.strip() for l in open(log, errors="replace") if l.strip()]
    except OSError:
        return ""
    for l in reversed(lines):
        if "error" in l.lower() or "what()" in l or "terminate" in l:
            return l
    return lines[-1] if lines else ""

raw = {}
for rows_file in row_files:
    for line in open(rows_file):
        fields = line.rstrip("\n").split("\t")
        key = (fields[0], fields[2])
        # a later run replaces an earlier row of the same (mesh, tolerance); a skip does not
        if key not in raw or fields[3] == "run":
            raw[key] = fields
table = []
for fields in raw.values():
    mesh, faces, tol, kind, rc, out, stem = fields[:7]
    run_timeout = fields[7] if len(fields) > 7 else timeout_s
    name = os.path.basename(mesh)
    row = dict(mesh=name, path=mesh, faces=int(faces) if int(faces) >= 0 else None, tol=tol, status="",
               s3=None, flat=None, pages=None, bound=None, secs=None, wall=None, rss=None, error="")
    if kind != "run":
        row["status"] = kind
        table.append(row)
        continue
    rc = int(rc)
    row["wall"], row["rss"] = wall_and_rss(os.path.join(out, "time.txt"))
    batch = None
    try:
        batch = json.load(open(os.path.join(out, "run.json")))
    except Exception:
        pass
    report = None
    try:
        report = json.load(open(os.path.join(out, stem, "report.json")))
    except Exception:
        pass
    if report:
        if row["faces"] is None:  # not an OFF: the triangles the loader built
            row["faces"] = report.get("input", {}).get("faces")
        res = report.get("result", {})
        row["bound"] = res.get("hausdorff_bound_percent")
    if batch and batch.get("results"):
        r = batch["results"][0]
        row["status"] = r.get("status", "?")
        row["error"] = r.get("error") or ""
        row["s3"], row["flat"], row["pages"] = r.get("strips_3d"), r.get("flat_strips"), r.get("pages")
        row["secs"] = r.get("wall_seconds")
        if row["status"] == "ok" and r.get("certified") is False:
            row["status"] = "ok, not certified"
    if rc in (124, 137):
        row["status"] = f"timeout ({run_timeout} s)"
    elif not batch:
        row["status"] = f"crash (exit {rc})" if rc not in (0, 1, 2) else f"exit {rc}, no run.json"
        row["error"] = last_error_line(os.path.join(out, "log.txt"))
    elif rc not in (0, 1) and row["status"] == "ok":
        row["status"] = f"ok, exit {rc}"
    table.append(row)

def fmt(v, spec="{}"):
    return "" if v is None else spec.format(v)

timeouts = sorted({int(f[7]) if len(f) > 7 else int(timeout_s) for f in raw.values() if f[3] == "run"})
lines = [f"papercraft run --threads {threads}, timeout {'/'.join(map(str, timeouts)) or timeout_s} s per run "
         f"({os.cpu_count()} cores). Seconds: the model's pipeline time (run.json); "
         "wall: the whole process; RSS: peak resident set.", "",
         "| mesh | faces | tol | status | 3D strips | flat strips | pages | bound % | seconds | wall s | peak RSS MiB |",
         "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|"]
for r in table:
    lines.append("| " + " | ".join([
        r["mesh"], fmt(r["faces"]), r["tol"], r["status"], fmt(r["s3"]), fmt(r["flat"]),
        fmt(r["pages"]), fmt(r["bound"], "{:.3f}"), fmt(r["secs"], "{:.3f}"),
        fmt(r["wall"], "{:.2f}"), fmt(r["rss"], "{:.0f}")]) + " |")

# Summary per tolerance and the failures.
lines.append("")
tols = []
for r in table:
    if r["tol"] not in tols:
        tols.append(r["tol"])
for tol in tols:
    rs = [r for r in table if r["tol"] == tol]
    counts = {}
    for r in rs:
        key = r["status"].split(" (")[0]
        counts[key] = counts.get(key, 0) + 1
    ok = [r for r in rs if r["status"].startswith("ok")]
    secs = sorted(r["secs"] for r in ok if r["secs"] is not None)
    med = secs[len(secs) // 2] if secs else float("nan")
    lines.append(f"- {tol}: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())) +
                 (f"; ok runs: median {med:.3f} s, total {sum(secs):.1f} s" if secs else ""))
failures = [r for r in table if not r["status"].startswith("ok") and not r["status"].startswith("skipped")]
if failures:
    lines += ["", "Failures:", ""]
    for r in failures:
        err = r["error"].replace(r["path"], r["mesh"]).replace("|", "\\|")
        # part ids name the whole chain of cuts: give its depth instead
        err = re.sub(r"part ((?:\d+\.){6,}\d+)", lambda m: f"part <{m.group(1).count('.') + 1} levels deep>", err)
        if len(err) > 300:
            err = err[:297] + "..."
        lines.append(f"- {r['mesh']} at {r['tol']}: {r['status']}" + (f": {err}" if err else ""))
text = "\n".join(lines) + "\n"
print(text, end="")
if markdown:
    with open(markdown, "w") as f:
        f.write(text)
PY
