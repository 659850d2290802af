#!/usr/bin/env bash
# The variation kernel against flam3-render, whole process, one thread, same genome, same samples
# (quality × width × height): each genome of tests/data/flame/bench/ is imported with
# `gridifs import-flame`, then flam3-render (nthreads=1) and `gridifs render --threads 1` run in
# alternation REPEAT times (default 3); the table gives median wall and CPU (user + system) seconds
# and peak memory (maximum resident set, MB), and the medians of the per-round ratios flam3 /
# gridifs (r_wall, r_cpu: the default device, which probes the GPU first, run right after flam3;
# r_gcpu: CPU with --device cpu, run right after that, whose wall/CPU is the column "dev cpu").
# With BASELINE=/path/to/older/gridifs that binary runs in the same rounds, last (before/after
# from one run: compare rb_cpu with r_gcpu, both GridIFS after GridIFS). Then the canonical 3D grid
# scene (tests/bench/canonical_scene.h) against flam3's 3-function Sierpinski at the same samples,
# as scripts/bench-whole-process measures it, when the build has bench_gpu (which writes the
# scene), and the default project (whose maps leave X) against the same genome. Every row draws
# SAMPLES samples (default 10^8, where a render's fixed costs no longer dominate; each genome's
# quality is scaled to give it); SAMPLES=genome keeps the genomes' own quality. Not run by ctest:
# timings need a quiet machine.
# usage: tests/bench/bench_flam3_ratio.sh [BUILD_DIR]   (default: build)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
source "$ROOT/tests/bench/bench_common.sh"
BUILD="$(cd "${1:-$ROOT/build}" && pwd)"
G="${GRIDIFS:-$BUILD/app/gridifs}"
REPEAT="${REPEAT:-3}"
BASELINE="${BASELINE:-}"
SAMPLES="${SAMPLES:-100000000}"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/gridifs-flam3ratio.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

measure() {  # "wall cpu peak" of "$@": seconds, seconds (user + system), MB (maximum resident set)
  /usr/bin/time -f "%e %U %S %M" -o "$WORK/time" "$@" >/dev/null 2>&1 || echo "failed: $*" >&2
  tail -1 "$WORK/time" | awk '{printf "%s %.2f %.0f", $1, $2 + $3, $4 / 1024}'
}
median() { python3 -c "import statistics,sys; print('%.2f' % statistics.median(float(a) for a in sys.argv[1:]))" "$@"; }
ratio() { python3 -c "print($1 / $2)"; }

# name  flam3-genome  gridifs-project  samples: one table row. Columns: medians of flam3's wall and
# CPU seconds, gridifs's (default device, then --device cpu, then BASELINE), and the medians of the
# per-round ratios flam3 / gridifs, wall and CPU.
run_case() {
  local name="$1" flame="$2" project="$3" samples="$4"
  local fw=() fc=() fm=() gw=() gc=() gm=() cw=() cc=() bw=() bc=() rw=() rc=() rcw=() rbw=() rbc=()
  for ((i = 0; i < REPEAT; ++i)); do
    local f g c b
    # Always in this order: on these VMs a process that follows another program or a pause spends
    # up to 0.1 s more system time (faulting in memory the host took back) than one that follows
    # a render like itself, so the default device's run (r_cpu) is GridIFS right after flam3, a
    # single render's cost, and --device cpu's (r_gcpu) GridIFS after GridIFS, a batch's.
    read -r -a f <<<"$(measure env nthreads=1 seed=1 out="$WORK/flam3.png" sh -c "flam3-render < '$flame'")"
    read -r -a g <<<"$(measure "$G" render "$project" -o "$WORK/g.png" --samples "$samples" --threads 1 -q)"
    read -r -a c <<<"$(measure "$G" render "$project" -o "$WORK/c.png" --samples "$samples" --threads 1 -q --device cpu)"
    if [[ -n "$BASELINE" ]]; then
      read -r -a b <<<"$(measure "$BASELINE" render "$project" -o "$WORK/b.png" --samples "$samples" --threads 1 -q)"
    fi
    fw+=("${f[0]}") fc+=("${f[1]}") fm+=("${f[2]}") gw+=("${g[0]}") gc+=("${g[1]}") gm+=("${g[2]}") cw+=("${c[0]}") cc+=("${c[1]}")
    rw+=("$(ratio "${f[0]}" "${g[0]}")") rc+=("$(ratio "${f[1]}" "${g[1]}")") rcw+=("$(ratio "${f[1]}" "${c[1]}")")
    if [[ -n "$BASELINE" ]]; then
      bw+=("${b[0]}") bc+=("${b[1]}") rbw+=("$(ratio "${f[0]}" "${b[0]}")") rbc+=("$(ratio "${f[1]}" "${b[1]}")")
    fi
  done
  printf "%-18s %11s %5s/%-5s %5s/%-5s %4.0f/%-4.0f %5s/%-5s %6sx %6sx %6sx" "$name" "$samples" "$(median "${fw[@]}")" \
    "$(median "${fc[@]}")" "$(median "${gw[@]}")" "$(median "${gc[@]}")" "$(median "${fm[@]}")" \
    "$(median "${gm[@]}")" "$(median "${cw[@]}")" "$(median "${cc[@]}")" "$(median "${rw[@]}")" "$(median "${rc[@]}")" "$(median "${rcw[@]}")"
  [[ -n "$BASELINE" ]] && printf "   %5s/%-5s %6sx %6sx" "$(median "${bw[@]}")" "$(median "${bc[@]}")" \
    "$(median "${rbw[@]}")" "$(median "${rbc[@]}")"
  printf "\n"
}

echo "one thread, whole process, $SAMPLES samples a row, median of $REPEAT alternating rounds; load $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"
echo "CPU: $(cpu_description)"
printf "%-18s %11s %11s %11s %9s %11s %7s %7s %7s" genome samples "flam3 w/cpu" "gridifs w/c" "MB f/g" "dev cpu w/c" \
  "r_wall" "r_cpu" "r_gcpu"
[[ -n "$BASELINE" ]] && printf "   %11s %7s %7s" "base w/cpu" "rb_wall" "rb_cpu"
printf "\n"
# GENOMES: the genomes to time (default all of tests/data/flame/bench/; "none" for the 3D rows only).
GENOMES="${GENOMES:-$(ls "$ROOT"/tests/data/flame/bench/*.flame)}"
[[ "$GENOMES" == none ]] && GENOMES=""
for flame in $GENOMES; do
  name="$(basename "$flame" .flame)"
  if [[ "$SAMPLES" != genome ]]; then
    # flam3 draws quality × width × height samples: scale the quality to SAMPLES in a copy.
    python3 - "$flame" "$WORK/$name.flame" "$SAMPLES" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
w, h = map(int, re.search(r'size="(\d+) (\d+)"', text).group(1, 2))
open(sys.argv[2], "w").write(re.sub(r'quality="[^"]*"', 'quality="%.6f"' % (int(sys.argv[3]) / (w * h)), text, count=1))
PY
    flame="$WORK/$name.flame"
  fi
  "$G" import-flame "$flame" -o "$WORK/$name.gridifs" >/dev/null
  samples=$(python3 -c "import json; print(json.load(open('$WORK/$name.gridifs'))['render']['samples'])")
  run_case "$name" "$flame" "$WORK/$name.gridifs" "$samples"
done

# The 3D rows: QUALITY (samples per pixel of 1024²) overrides SAMPLES; flam3's Sierpinski genome
# draws the same samples.
[[ "$SAMPLES" == genome ]] && QUALITY="${QUALITY:-20}"
QUALITY="${QUALITY:-$(python3 -c "print(round($SAMPLES / (1024 * 1024)))")}"
samples=$((QUALITY * 1024 * 1024))
write_sierpinski_flame "$WORK/sierpinski.flame" "$QUALITY"
at_1024() {  # copies project $1 to $2 with a 1024×1024 image
  python3 - "$1" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); d["render"]["width"] = 1024; d["render"]["height"] = 1024
json.dump(d, open(sys.argv[2], "w"))
PY
}
if [[ -x "$BUILD/tests/bench_gpu" ]]; then
  # The canonical scene at 1024² (its own mode).
  "$BUILD/tests/bench_gpu" --write-scene "$WORK/canonical.gridifs"
  at_1024 "$WORK/canonical.gridifs" "$WORK/canonical_1024.gridifs"
  run_case "canonical-3d-grid" "$WORK/sierpinski.flame" "$WORK/canonical_1024.gridifs" "$samples"
else
  echo "(no $BUILD/tests/bench_gpu: build it for the canonical 3D grid scene row)"
fi
# A scene whose maps leave X: the default project's four twisted functions reach 1.18 from the
# centre, so the chaos game clamps points back into X (z-buffer, 1024²).
at_1024 "$ROOT/assets/default.gridifs" "$WORK/default_1024.gridifs"
run_case "default-leaves-X" "$WORK/sierpinski.flame" "$WORK/default_1024.gridifs" "$samples"
