#!/usr/bin/env bash
# Unpacks CGAL's sample meshes (Debian's libcgal-demo ships them as
# /usr/share/doc/libcgal-dev/data.tar.gz, holding data/meshes/*.off) into a cache folder and
# prints the meshes folder. Installs libcgal-demo with apt-get when it is missing (needs root
# or sudo). Idempotent: a second run only prints the folder.
#
#   bench/cgal_meshes.sh                  # -> build/cgal-data/data/meshes
#   bench/cgal_meshes.sh /tmp/cgal        # -> /tmp/cgal/data/meshes
#   MESHES=$(bench/cgal_meshes.sh) && ls "$MESHES"
#
# Messages go to stderr; stdout holds only the folder, so the script can be used in $(...).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${1:-$root/build/cgal-data}
archive=/usr/share/doc/libcgal-dev/data.tar.gz
meshes=$cache/data/meshes
stamp=$cache/.unpacked

if [[ -f $stamp && -d $meshes ]]; then
  echo "$meshes"
  exit 0
fi

if [[ ! -f $archive ]]; then
  if ! dpkg -s libcgal-demo >/dev/null 2>&1; then
    echo "cgal_meshes.sh: installing libcgal-demo" >&2
    sudo=()
    if [[ $(id -u) -ne 0 ]]; then
      command -v sudo >/dev/null || { echo "cgal_meshes.sh: need root or sudo to install libcgal-demo" >&2; exit 1; }
      sudo=(sudo)
    fi
    export DEBIAN_FRONTEND=noninteractive
    "${sudo[@]}" apt-get update -qq >&2
    "${sudo[@]}" apt-get install -y -qq --no-install-recommends libcgal-demo >&2
  fi
  if [[ ! -f $archive ]]; then
    # The path moved between releases: take whatever data.tar.gz the package lists.
    archive=$(dpkg -L libcgal-demo libcgal-dev 2>/dev/null | grep '/data\.tar\.gz$' | head -n 1 || true)
    [[ -n $archive && -f $archive ]] || { echo "cgal_meshes.sh: no data.tar.gz in libcgal-demo" >&2; exit 1; }
  fi
fi

mkdir -p "$cache"
echo "cgal_meshes.sh: unpacking $archive into $cache" >&2
tar -xzf "$archive" -C "$cache" data/meshes
[[ -d $meshes ]] || { echo "cgal_meshes.sh: $archive has no data/meshes" >&2; exit 1; }
touch "$stamp"
echo "$meshes"
