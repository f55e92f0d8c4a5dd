#!/usr/bin/env bash
# Step time of the triaxial sample (examples/triaxial, 7 699 spheres in a 50 mm
# cylinder) with the rigid cylinder and with fix membrane3d placed only (no detection
# in the timed steps), every auto, 1, 10, 50 and 200, platens still, on 1 and 2
# ranks. Prints the times and the ratios to the cylinder, measured in one run, the
# cost of one detection (from every 1 and every 200) and the share of the steps
# every auto detects on.
# Also the pair forces' share of the step (the sample's own cost under each boundary).
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
exe=$(readlink -f ../build/app/liggghts-membrane)
[ -f "$restart" ] || { echo "no compressed sample $restart: run examples/triaxial/in.triaxial first"; exit 1; }
platen=${restart%.restart}.platen
csv=membrane3d_cost.csv
never=100000000
meshdir=../examples/triaxial/meshes
. ./step_time.sh
# NP LATERAL EVERY NSTEPS: "ms_per_step,pair_ms_per_step,detections" (in the timed steps)
ms_cost() {
  local log
  log=$(mpirun --allow-run-as-root --oversubscribe -np "$1" "$exe" -in in.membrane3d_cost -log none \
    -var restart "$restart" -var platen "$platen" -var lateral "$2" -var every "$3" -var nsteps "$4" \
    -var vshear "$vshear" -var meshdir "$(readlink -f "$meshdir")")
  printf "%s,%s,%s" "$(grep "^Loop time" <<<"$log" | tail -1 | awk '{printf "%.4f", 1000 * $4 / $9}')" \
    "$(grep "^Pair  time" <<<"$log" | tail -1 | awk -v n="$4" '{printf "%.4f", 1000 * $5 / n}')" \
    "$(grep "^BENCH detections" <<<"$log" | awk '{print $3}')"
}
echo "ranks,lateral,every,ms_per_step,pair_ms_per_step,detections,steps" > $csv
for np in 1 2; do
  echo "$np,cylinder,0,$(ms_cost $np 0 1 "$nsteps"),$nsteps" >> $csv
  # every $never: the placement alone (the one detection at the run's start is not timed)
  for every in $never 200 50 10 auto; do echo "$np,membrane,$every,$(ms_cost $np 1 $every "$nsteps"),$nsteps" >> $csv; done
  echo "$np,membrane,1,$(ms_cost $np 1 1 $((nsteps / 10))),$((nsteps / 10))" >> $csv
done
/usr/bin/python3 - "$csv" "$never" <<'PY'
import collections, csv, sys
NEVER = sys.argv[2]
rows, pairs = collections.defaultdict(dict), collections.defaultdict(dict)
for r in csv.DictReader(open(sys.argv[1])):
    rows[r["ranks"]][(r["lateral"], r["every"])] = (float(r["ms_per_step"]),
                                                   float(r["detections"] or 0) / float(r["steps"]))
    pairs[r["ranks"]][(r["lateral"], r["every"])] = float(r["pair_ms_per_step"])
for np_, t in sorted(rows.items()):
    base, base_pair = t[("cylinder", "0")][0], pairs[np_][("cylinder", "0")]
    print("ranks %s:" % np_)
    print("  %-22s %8.3f ms/step" % ("rigid cylinder", base))
    for every in (NEVER, "200", "50", "10", "auto", "1"):
        ms, share = t[("membrane", every)]
        name = "membrane, placed only" if every == NEVER else "membrane every " + every
        print("  %-22s %8.3f ms/step  %+7.1f %% vs cylinder  detections on %5.1f %% of the steps"
              % (name, ms, 100 * (ms / base - 1), 100 * share))
    # every 1 detects each step, every 200 almost never: the difference is a detection
    print("  one detection          %8.1f ms" % (t[("membrane", "1")][0] - t[("membrane", "200")][0]))
    # the sample's own cost: the pair forces under the cylinder and under a membrane placed only
    placed_pair = pairs[np_][("membrane", NEVER)]
    print("  pair forces            %8.3f ms/step in the cylinder, %.3f under the membrane (%+.1f %%)"
          % (base_pair, placed_pair, 100 * (placed_pair / base_pair - 1)))
PY
