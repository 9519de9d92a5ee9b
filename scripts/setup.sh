#!/usr/bin/env bash
# Installs every system package iblkit needs from Debian's archive. Idempotent: when everything
# is already installed it only checks (well under a second) and exits 0.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git ca-certificates
  libembree-dev libtbb-dev
  libglfw3-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri libgles-dev libopengl-dev libepoxy-dev
  glslang-tools glslang-dev
  libglm-dev libtinygltf-dev libdraco-dev libmeshoptimizer-dev nlohmann-json3-dev libstb-dev libwebp-dev
  libopenexr-dev libimath-dev zlib1g-dev
  libgtest-dev libbenchmark-dev libcli11-dev libimgui-dev
  clang libclang-rt-dev  # make fuzz: clang and its libFuzzer runtime (libclang_rt.fuzzer)
  xvfb xauth xdotool  # the window tests: a virtual X server, and real input events (tests/view)
  x11-xserver-utils  # xrdb: a high-DPI X screen (Xft.dpi) for the window tests
  chromium chromium-driver  # the report page's browser test (tests/programs/report_page_browser_test.py)
  time  # GNU time: scripts/ab-time.sh, the A/B timings of docs/benchmarks.md
  slurm-wlm munge  # the one-node Slurm cluster of tests/programs/cluster_slurm_trace_test.sh (docs/cluster.md)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# Node.js and npm fetch the CC0 assets (npm pack). Many machines ship their own Node; Debian's
# npm package conflicts with it, so install Debian's only when no npm is on the PATH.
if ! command -v npm >/dev/null 2>&1; then
  missing+=(nodejs npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all system packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=sudo
  else
    echo "setup: not root and no sudo; run as root: apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
else
  SUDO=
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
