# Shell helpers of the whole-process benchmarks (tests/bench/bench_flam3_ratio.sh,
# scripts/bench-whole-process), sourced by both.

# "MODEL (family F model M) (avx512f)": lscpu's model name with /proc/cpuinfo's family and model,
# since a hypervisor may show every generation of a vendor's server CPUs under one name ("AMD
# EPYC"), and they differ in speed.
cpu_description() {
  local family model
  family=$(sed -n 's/^cpu family[[:space:]]*: //p' /proc/cpuinfo | head -1)
  model=$(sed -n 's/^model[[:space:]]*: //p' /proc/cpuinfo | head -1)
  echo "$(lscpu | sed -n 's/^Model name: *//p' | head -1) (family $family model $model) ($(grep -o -m1 'avx512f' /proc/cpuinfo || echo 'no AVX-512'))"
}

# write_sierpinski_flame FILE QUALITY: flam3's 3-function linear Sierpinski genome at 1024², the
# flame the 3D grid scenes are timed against (QUALITY samples per pixel).
write_sierpinski_flame() {
  cat > "$1" <<FLAME
<flame name="sierpinski" version="3.1.1" size="1024 1024" center="0 0" scale="400" quality="$2"
 supersample="1" filter="0" temporal_samples="1" background="0 0 0" brightness="4" gamma="4" vibrancy="1"
 estimator_radius="0" estimator_minimum="0" estimator_curve="0.4" palette="0">
   <xform weight="0.333333" color="0" linear="1" coefs="0.5 0 0 0.5 -0.5 -0.5"/>
   <xform weight="0.333333" color="0.5" linear="1" coefs="0.5 0 0 0.5 0.5 -0.5"/>
   <xform weight="0.333333" color="1" linear="1" coefs="0.5 0 0 0.5 0 0.5"/>
</flame>
FLAME
}
