#!/usr/bin/env bash
# Installs the Debian 12 packages papercraft needs to build and test, if any is missing.
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config
          libtbb-dev libopenmesh-dev libeigen3-dev libspdlog-dev libyaml-cpp-dev libcli11-dev
          nlohmann-json3-dev libcairo2-dev libgtest-dev libgmock-dev libbenchmark-dev
          libjpeg-dev zlib1g-dev libtinygltf-dev lib3mf-dev
          python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest
          poppler-utils libxml2-utils libcgal-demo parallel
          clang-14 libfuzzer-14-dev
          nodejs npm chromium)
# A Node.js 18 or later from elsewhere (NodeSource's nodejs carries its own npm) will do.
node_major=$(node -p 'process.versions.node.split(".")[0]' 2>/dev/null || echo 0)
have_node=false
if [ "$node_major" -ge 18 ] && command -v npm >/dev/null; then have_node=true; fi
missing=()
for p in "${packages[@]}"; do
  if $have_node && { [ "$p" = nodejs ] || [ "$p" = npm ]; }; then continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
