#!/usr/bin/env bash
# The rigid-boundary comparison in one command: prepare a cuboid sample per seed
# (in.cuboid_prepare), shear each with four servo-controlled side walls and with fix
# membrane3d (in.cuboid_shear), then tabulate and plot (compare_boundaries.py).
#   examples/triaxial/run_comparison.sh [--quick] [--np N] [--seeds "S1 S2 ..."] [--frictionless T]
#                                       [--width W]
# Default: 3 seeds, 36 mm cuboids of about 4 000 spheres, about 5 minutes per seed on
# 2 cores; --quick: 16 mm cuboids of about 400 spheres, 2 seeds, about a minute each;
# --frictionless 2: the membrane spheres wear the frictionless type 2 (contacts.inc);
# --width W: cuboids W metres wide (and 2 W high), written to out/comparison_W/.
# Writes out/comparison/: per seed the prepared sample, each shear's .txt and log,
# the membrane's VTK frames (ParaView: membrane_SEED_membrane.pvd), comparison.md
# and comparison.png.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
export PYTHONPATH="$root/python${PYTHONPATH:+:$PYTHONPATH}"   # the package python/liggghts_membrane
. "$root/tools/run_options.sh"
np=2
seeds="86028121 104395301 122949823"
W=0.036
size=()
vtkevery=2500
frictionless=0
suffix=
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) W=0.016; size=(-var hfill 0.06 -var nsettle 8000 -var ncompress 12000)
             seeds="86028121 104395301"; vtkevery=1000 ;;
    --np) np=${2-}; ranks_or_exit "$np"; shift ;;
    --seeds) seeds=$2; shift ;;
    --frictionless) frictionless=$2; shift ;;
    --width) W=$2; suffix=_$2; shift
             size=(-var hfill "$(awk -v w="$W" 'BEGIN { print w * 0.16 / 0.036 }')") ;;
    *) echo "usage: $0 [--quick] [--np N] [--seeds \"S1 S2 ...\"] [--frictionless T] [--width W]"; exit 2 ;;
  esac
  shift
done
out=$root/out/comparison$suffix
mkdir -p "$out"
cd "$here"
run() { # log, then the arguments of liggghts-membrane
  local log=$1; shift
  # (the screen to /dev/null: with -screen none LIGGGHTS' fix insert/pack crashes)
  mpirun --allow-run-as-root --oversubscribe -np "$np" "$root/build/app/liggghts-membrane" \
    -log "$log" "$@" > /dev/null
  grep '^CUBOID' "$log" | sed 's/^/    /'
}
for s in $seeds; do
  echo "[$(date +%T)] seed $s: preparing the sample"
  run "$out/prepare_$s.log" -in in.cuboid_prepare -var seed "$s" -var out "$out/cuboid_$s" \
    -var W "$W" "${size[@]}"
  # the frames of an earlier run of this seed (another size, --quick) would stay in
  # the collection (fix membrane3d keeps the frames before its first step: a restart's)
  rm -f "$out/membrane_${s}_membrane.pvd" "$out/membrane_${s}_membrane_"*.vtp
  for b in walls membrane; do
    echo "[$(date +%T)] seed $s: shear with the $b"
    run "$out/${b}_$s.log" -in in.cuboid_shear -var sample "$out/cuboid_$s" -var W "$W" \
      -var boundary "$b" -var out "$out/${b}_$s" -var vtkevery "$vtkevery" \
      -var frictionless "$frictionless"
  done
done
/usr/bin/python3 compare_boundaries.py "$out" $seeds
