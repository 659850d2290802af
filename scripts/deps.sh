#!/usr/bin/env bash
# Installs the Debian 12 packages GridIFS builds, tests and runs with (quietly, only
# what is missing). Sourced by scripts/run and scripts/test.
set -euo pipefail
GRIDIFS_PACKAGES=(
  build-essential cmake pkg-config
  libglfw3-dev libglm-dev libopenmesh-dev libopenimageio-dev openimageio-tools libimgui-dev
  libmuparser-dev nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev libepoxy-dev
  xvfb xauth xdotool x11-utils imagemagick mesa-utils libgl1-mesa-dri fonts-dejavu-core
  flam3-utils flam3-palette clang libclang-rt-14-dev libtbb-dev libpugixml-dev
  libegl-dev libegl-mesa0 libopenvdb-dev libboost-iostreams-dev libnanoflann-dev ffmpeg zlib1g-dev
  # scripts/figures (its thumbnails through oiiotool, above).
  python3
  # scripts/slurm-local: a one-node Slurm for the render-job tests; ss picks its free ports.
  slurm-wlm munge iproute2
)
gridifs_install_deps() {
  local missing=()
  for p in "${GRIDIFS_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "Installing Debian packages: ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
}
# One configuration for scripts/run and scripts/test (warnings are errors in both), so that the
# second of them reuses the first one's build instead of rebuilding everything with other flags.
gridifs_build() {
  local dir="$1"; shift
  cmake -S "$GRIDIFS_ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DGRIDIFS_WERROR=ON "$@" >/dev/null
  cmake --build "$dir" -j"$(nproc)"
}
