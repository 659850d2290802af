#!/usr/bin/env bash
# Installs the Debian 12 packages GridIFS needs (quietly, only what is missing) and builds it.
# Sourced by scripts/run, which installs and builds only what the modeller needs, and by
# scripts/test, which adds the test-only packages and builds the rest into the same folder.
set -euo pipefail
# To build and run the modeller and the command line.
GRIDIFS_RUN_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libglfw3-dev libglm-dev libopenmesh-dev libopenimageio-dev libimgui-dev libmuparser-dev
  nlohmann-json3-dev libcli11-dev libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libtbb-dev libpugixml-dev libopenvdb-dev libboost-iostreams-dev libnanoflann-dev zlib1g-dev
  fonts-dejavu-core
  # Sound that animations follow (libsndfile reads it, FFTW splits it into bands, SDL plays it),
  # OSC and MIDI input. RtMidi's JACK headers are named as JACK 2's: left to choose, apt takes
  # JACK 1's, and the tests' jackd2 then removes them and RtMidi with them, mid-build.
  libsndfile1-dev libfftw3-dev liblo-dev libjack-jackd2-dev librtmidi-dev libsdl2-dev
  # flam3's palettes, which flame projects and imported .flame files name by number.
  flam3-palette
)
# Only the tests, benchmarks and CI need these. The build of the tests needs the first set (its
# headers and libraries); the tiers need the rest only when they run, so scripts/test installs
# them while it builds.
GRIDIFS_TEST_BUILD_PACKAGES=(
  libgtest-dev libbenchmark-dev
  # The Python module: pybind11 against the system Python 3.11 that Debian's Blender runs.
  pybind11-dev python3-dev
)
GRIDIFS_TEST_PACKAGES=(
  # The gui tier: a real X server with Mesa's llvmpipe, real input, screenshots.
  xvfb xauth xdotool x11-utils imagemagick mesa-utils
  # flam3-render to compare against, oiiotool for scripts/figures, ffmpeg for --video (optional
  # at run time: without it --video says so).
  flam3-utils openimageio-tools ffmpeg python3
  # scripts/fuzz: clang and libFuzzer; scripts/test checks the sources' format.
  clang libclang-rt-14-dev clang-format
  # scripts/slurm-local: a one-node Slurm for the render-job tests; ss picks its free ports.
  slurm-wlm munge iproute2 procps
  # MIDI through a real transport: JACK's server with its dummy driver (no sound hardware).
  jackd2
  # The python tier, the examples' plots, and the blender tier's Blender.
  python3-numpy python3-pytest python3-matplotlib blender
)
# gridifs_install_deps run|test-build|test: the modeller's packages; and those the tests' build
# needs; or every package. The package lists are updated once (GRIDIFS_APT_UPDATED) when any is missing.
gridifs_install_deps() {
  local wanted=("${GRIDIFS_RUN_PACKAGES[@]}")
  case "${1:-test}" in
    run) ;;
    test-build) wanted+=("${GRIDIFS_TEST_BUILD_PACKAGES[@]}") ;;
    *) wanted+=("${GRIDIFS_TEST_BUILD_PACKAGES[@]}" "${GRIDIFS_TEST_PACKAGES[@]}") ;;
  esac
  local missing=()
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "Installing Debian packages: ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    if [ "${GRIDIFS_APT_UPDATED:-0}" != 1 ]; then
      $sudo apt-get update -qq
      GRIDIFS_APT_UPDATED=1
    fi
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
}
# gridifs_configure DIR [CMAKE ARGS...]: one configuration for scripts/run and scripts/test
# (Release, Ninja, warnings are errors in both), so that the second of them reuses the first one's
# objects instead of building everything again with other flags.
gridifs_configure() {
  local dir="$1"; shift
  # A folder configured for another generator (older checkouts used Makefiles) cannot switch.
  if [ -f "$dir/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$dir/CMakeCache.txt"; then
    echo "Reconfiguring $dir for Ninja (it was made with another generator)."
    rm -rf "$dir/CMakeCache.txt" "$dir/CMakeFiles"
  fi
  cmake -G Ninja -S "$GRIDIFS_ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DGRIDIFS_WERROR=ON "$@" >/dev/null
}
# gridifs_build DIR [TARGET...]: builds the named targets, or everything.
gridifs_build() {
  local dir="$1"; shift
  local targets=()
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build "$dir" -j"$(nproc)" "${targets[@]}"
}
