# Shell functions the bench scripts share; source it after setting `root`:
#   . "$root/bench/lib.sh"

# Prints the script's header comment (from line 2 to `set -euo`) on stderr and exits 2.
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

# The face count in an OFF header, or 0 when unknown.
faces_of() {
  awk 'NR == 1 && $1 ~ /OFF$/ && NF > 1 { print $3; exit }
       NR == 1 && $1 ~ /OFF$/ { next }
       /^[ \t]*#/ || NF == 0 { next }
       { print $2; exit }' "$1" 2>/dev/null | grep -E '^[0-9]+$' || echo 0
}
