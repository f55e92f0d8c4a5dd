#!/usr/bin/env bash
# Step time of fix membrane3d against a like-for-like rigid boundary: the cuboid sample
# of examples/triaxial/in.cuboid_prepare (36 mm, one seed, 3 981 spheres at p) with the
# four servo-controlled side walls at p of in.cuboid_shear (-var boundary walls) and
# with fix membrane3d at p (-var boundary membrane; settled every 50, as the example)
# placed only (one detection before the timed steps, none in them), every 200, 50, 10,
# auto, 1; platens still; 1 and 2 ranks (in.membrane3d_cuboid_cost). The same sample
# and stress state under both: unlike the rigid cylinder of bench/membrane3d_cost.sh
# (compressed by its platens alone, its lateral stress below p), the walls hold p.
# Prints the times and the ratios to the walls, each membrane's own cost, the cost of
# one detection, the share of the steps each membrane detects on, and the pair forces
# and contacts per sphere under each boundary (membrane3d_cost_report.py); writes
# membrane3d_cuboid_cost.csv.
#   bench/membrane3d_cuboid_cost.sh [RESTART] [NSTEPS] [VSHEAR] [NHOLD] [ROUNDS]
# RESTART: a sample of in.cuboid_prepare (FILE.restart, FILE.walls beside it; default
#   out/membrane3d_cuboid_cost/cuboid_86028121.restart, prepared here on 1 rank when
#   missing, 1.6 min, not timed).
# NSTEPS: timed steps (default 1000; every 1: a tenth of them).
# VSHEAR: the upper platen's speed down in the timed steps [m/s] (default 0: still).
# NHOLD: steps of settling with the boundary before the timed steps, the platen held at
#   p by its servo (default 3000; in.cuboid_shear holds 5000 before its shear).
# ROUNDS: each case is run this many times, the cases in turn (default 3); the summary
#   takes the median of each time (the machine is noisy: one run of 1 000 steps of a
#   case varied by up to 85 % from one round to the next).
# Each timed run waits for an idle machine and is run again when other processes took
# more than 5 % of the CPU time during it (membrane3d_cost_lib.sh; the CSV's others
# column: their share; BENCH_NO_WAIT=1: neither). BENCH_RANKS="1": 1 rank only.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
seed=86028121
restart=$(readlink -f "${1:-$root/out/membrane3d_cuboid_cost/cuboid_$seed.restart}")  # before cd
nsteps=${2:-1000}
vshear=${3:-0}
nhold=${4:-3000}
rounds=${5:-3}
. "$here/membrane3d_cost_lib.sh"
exdir=$root/examples/triaxial
sample=${restart%.restart}
if [ ! -f "$restart" ]; then
  [ -z "${1:-}" ] || { echo "no cuboid sample $restart (with ${sample}.walls beside it)"; exit 1; }
  echo "[$(date +%T)] preparing the sample (in.cuboid_prepare, seed $seed, 1 rank) into $sample.*"
  mkdir -p "$(dirname "$restart")"
  # (the screen to /dev/null: with -screen none LIGGGHTS' fix insert/pack crashes)
  (cd "$exdir" && mpirun --allow-run-as-root --oversubscribe -np 1 "$bench_exe" -in in.cuboid_prepare \
     -var seed "$seed" -var out "$sample" -log "$sample.prepare.log" > /dev/null)
  grep '^CUBOID' "$sample.prepare.log"
fi
[ -f "$sample.walls" ] || { echo "no ${sample}.walls beside $restart"; exit 1; }
csv=$here/membrane3d_cuboid_cost.csv
never=100000000
# NP BOUNDARY EVERY NSTEPS: "ms_per_step,pair_ms_per_step,neigh_ms_per_step,contacts,detections,
# sigma1_kpa,sigma3_kpa,others" (the timed steps; the stresses after the settle; the
# other processes' share of the CPU time during the run)
ms_cost() {
  # from the example's folder: its .inc files include each other by name
  cd "$exdir"
  bench_run "$1" "$here/in.membrane3d_cuboid_cost" -var sample "$sample" -var boundary "$2" \
    -var timedevery "$3" -var nsteps "$4" -var nhold "$nhold" -var vshear "$vshear"
  printf "%s,%s,%s" "$(bench_figures "$4")" \
    "$(grep "^BENCH held" <<<"$bench_log" | awk '{printf "%.2f,%.2f", $5 / 1000, $7 / 1000}')" "$bench_others"
}
start=$(date +%s)
echo "ranks,lateral,every,ms_per_step,pair_ms_per_step,neigh_ms_per_step,contacts_per_sphere,detections,sigma1_kpa,sigma3_kpa,others,steps,round" > "$csv"
for round in $(seq 1 "$rounds"); do
  for np in ${BENCH_RANKS:-1 2}; do
    echo "[$(date +%T)] round $round, $np rank(s)"
    echo "$np,walls,0,$(ms_cost $np walls 1 "$nsteps"),$nsteps,$round" >> "$csv"
    # every $never: the placement alone (the one detection before the timed steps is not timed)
    for every in $never 200 50 10 auto; do
      echo "$np,membrane,$every,$(ms_cost $np membrane $every "$nsteps"),$nsteps,$round" >> "$csv"
    done
    echo "$np,membrane,1,$(ms_cost $np membrane 1 $((nsteps / 10))),$((nsteps / 10)),$round" >> "$csv"
  done
done
echo "[$(date +%T)] $(($(date +%s) - start)) s"
/usr/bin/python3 "$here/membrane3d_cost_report.py" "$csv" "$never" walls "servo walls"
