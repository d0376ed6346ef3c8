#!/usr/bin/env bash
# cmake/check_includes.cmake on small trees: the project's own tree follows the rule, and each
# kind of include the rule forbids is refused with the file and the reason named.
#
#   tests/scripts/include_rule_check.sh     (ctest: IncludeRule.RefusesEveryForbiddenKind)
#
# CMAKE: the cmake to run (default: cmake on PATH). Exit 0 when the check holds.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cmake=${CMAKE:-cmake}
work=$(mktemp -d /tmp/papercraft-include-rule.XXXXXX)
trap 'rm -rf "$work"' EXIT
failures=0

# check TREE: runs the rule over TREE, output in $work/log; returns its exit status.
check() {
  "$cmake" -DROOT="$1" -DSTAMP="$work/stamp" -P "$root/cmake/check_includes.cmake" \
    >"$work/log" 2>&1
}

if ! check "$root"; then
  echo "FAIL: the project's own tree breaks the include rule:" >&2
  cat "$work/log" >&2
  failures=$((failures + 1))
fi

# check_one FILE INCLUDE: the rule over a tree holding only FILE, which includes INCLUDE.
check_one() {
  local tree="$work/tree"
  rm -rf "$tree"
  mkdir -p "$tree/$(dirname "$1")"
  printf '#include "%s"\n' "$2" >"$tree/$1"
  check "$tree"
}

# refused FILE INCLUDE REASON: FILE including INCLUDE fails, naming both and REASON.
refused() {
  if check_one "$1" "$2"; then
    echo "FAIL: $1 including $2 passed the check" >&2
    failures=$((failures + 1))
  elif ! tr -s ' \n' ' ' <"$work/log" | grep -qF "$1: #include \"$2\" ($3"; then
    echo "FAIL: $1 including $2 was refused without naming it and '$3':" >&2
    cat "$work/log" >&2
    failures=$((failures + 1))
  fi
}

# allowed FILE INCLUDE: FILE including INCLUDE passes.
allowed() {
  if ! check_one "$1" "$2"; then
    echo "FAIL: $1 including $2 was refused:" >&2
    cat "$work/log" >&2
    failures=$((failures + 1))
  fi
}

refused nodes/merge/congruent_join.cpp nodes/layout/pages.h "a stage uses core/ and engine/"
refused nodes/merge/congruent_node.cpp nodes/unfold/sequential_node.h "a stage uses core/"
refused nodes/merge/congruent_join.cpp graph/messages.h "a stage's algorithms know nothing"
refused engine/refine/refine.cpp nodes/cut/harmonic_node.h "engine/ includes core/"
refused engine/refine/refine.cpp graph/node.h "engine/ includes core/"
refused core/mesh.h engine/refine/refine.h "core/ includes core/ only"
refused graph/node.h nodes/layout/pages.h "graph/ includes core/"
refused graph/node.h engine/hausdorff/bounded.h "graph/ uses the engine through"
refused runner/run_models.cpp nodes/layout/pages.h "runner/ uses the stages"
allowed nodes/merge/rejoin_3d_node.cpp engine/refine/rejoin.h
allowed nodes/merge/congruent_node.cpp graph/messages.h
allowed nodes/merge/congruent_join.cpp nodes/merge/congruent.h
allowed graph/node.h engine/refine/refine.h
allowed runner/main.cpp engine/refine/refine.h

if ((failures > 0)); then
  echo "include_rule_check: $failures failure(s)" >&2
  exit 1
fi
echo "include_rule_check: ok"
