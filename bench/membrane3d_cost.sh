#!/usr/bin/env bash
# Step time of the triaxial sample (examples/triaxial, 7 699 spheres in a 50 mm
# cylinder) with the rigid cylinder and with fix membrane3d placed only (no detection
# in the timed steps), every auto, 1, 10, 50 and 200, platens still, on 1 and 2
# ranks. Prints the times and the ratios to the cylinder, measured in one run, the
# cost of one detection (from every 1 and every 200) and the share of the steps
# every auto detects on.
# Also the sample's own cost under each boundary (the pair forces and neighbour lists,
# and its contacts per sphere), and each membrane's own cost: its step beyond the
# cylinder's, less what the sample costs more under a membrane placed only.
# Each run waits until no other liggghts-membrane or mpirun runs (membrane3d_cost_lib.sh).
#   bench/membrane3d_cost.sh [RESTART] [NSTEPS] [VSHEAR]
# VSHEAR: the upper platen's speed down in the timed steps [m/s] (default 0: still).
# RESTART: the compressed sample of examples/triaxial/in.triaxial
# (${out}.compressed.restart, with ${out}.compressed.platen beside it).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
restart=$(readlink -f "${1:-$here/../out/triaxial/triaxial.compressed.restart}")  # before cd: a path given from anywhere
cd "$here"
nsteps=${2:-1000}
vshear=${3:-0}
. ./membrane3d_cost_lib.sh
[ -f "$restart" ] || { echo "no compressed sample $restart: run examples/triaxial/in.triaxial first"; exit 1; }
platen=${restart%.restart}.platen
csv=membrane3d_cost.csv
never=100000000
meshdir=../examples/triaxial/meshes
# NP LATERAL EVERY NSTEPS: "ms_per_step,pair_ms_per_step,neigh_ms_per_step,contacts,detections"
# (in the timed steps; membrane3d_cost_lib.sh)
ms_cost() {
  bench_run "$1" in.membrane3d_cost -var restart "$restart" -var platen "$platen" -var lateral "$2" \
    -var every "$3" -var nsteps "$4" -var vshear "$vshear" -var meshdir "$(readlink -f "$meshdir")"
  bench_figures "$4"
}
echo "ranks,lateral,every,ms_per_step,pair_ms_per_step,neigh_ms_per_step,contacts_per_sphere,detections,steps" > $csv
for np in 1 2; do
  echo "$np,cylinder,0,$(ms_cost $np 0 1 "$nsteps"),$nsteps" >> $csv
  # every $never: the placement alone (the one detection at the run's start is not timed)
  for every in $never 200 50 10 auto; do echo "$np,membrane,$every,$(ms_cost $np 1 $every "$nsteps"),$nsteps" >> $csv; done
  echo "$np,membrane,1,$(ms_cost $np 1 1 $((nsteps / 10))),$((nsteps / 10))" >> $csv
done
/usr/bin/python3 membrane3d_cost_report.py "$csv" "$never" cylinder "rigid cylinder"
