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
# NP LATERAL EVERY NSTEPS: "ms_per_step,pair_ms_per_step,neigh_ms_per_step,contacts,detections"
# (in the timed steps)
ms_cost() {
  local log
  log=$(mpirun --allow-run-as-root --oversubscribe -np "$1" "$exe" -in in.membrane3d_cost -log none \
    -var restart "$restart" -var platen "$platen" -var lateral "$2" -var every "$3" -var nsteps "$4" \
    -var vshear "$vshear" -var meshdir "$(readlink -f "$meshdir")")
  printf "%s,%s,%s,%s,%s" "$(grep "^Loop time" <<<"$log" | tail -1 | awk '{printf "%.4f", 1000 * $4 / $9}')" \
    "$(grep "^Pair  time" <<<"$log" | tail -1 | awk -v n="$4" '{printf "%.4f", 1000 * $5 / n}')" \
    "$(grep "^Neigh time" <<<"$log" | tail -1 | awk -v n="$4" '{printf "%.4f", 1000 * $5 / n}')" \
    "$(grep "^BENCH contacts" <<<"$log" | awk '{printf "%.3f", $5}')" \
    "$(grep "^BENCH detections" <<<"$log" | awk '{print $3}')"
}
echo "ranks,lateral,every,ms_per_step,pair_ms_per_step,neigh_ms_per_step,contacts_per_sphere,detections,steps" > $csv
for np in 1 2; do
  echo "$np,cylinder,0,$(ms_cost $np 0 1 "$nsteps"),$nsteps" >> $csv
  # every $never: the placement alone (the one detection at the run's start is not timed)
  for every in $never 200 50 10 auto; do echo "$np,membrane,$every,$(ms_cost $np 1 $every "$nsteps"),$nsteps" >> $csv; done
  echo "$np,membrane,1,$(ms_cost $np 1 1 $((nsteps / 10))),$((nsteps / 10))" >> $csv
done
/usr/bin/python3 - "$csv" "$never" <<'PY'
import collections, csv, sys
NEVER = sys.argv[2]
rows = collections.defaultdict(dict)
for r in csv.DictReader(open(sys.argv[1])):
    rows[r["ranks"]][(r["lateral"], r["every"])] = r
for np_, t in sorted(rows.items()):
    def ms(key, column="ms_per_step"):
        return float(t[key][column])
    cylinder, placed = ("cylinder", "0"), ("membrane", NEVER)
    base = ms(cylinder)
    def sample(key):  # the sample's own cost: its pair forces and neighbour lists
        return ms(key, "pair_ms_per_step") + ms(key, "neigh_ms_per_step")
    # the membrane's denser sample (more contacts) seen with a membrane placed only:
    # without it, what each membrane costs itself (its detections slow the pair forces
    # that follow them too: they are its cost)
    denser = sample(placed) - sample(cylinder)
    print("ranks %s:" % np_)
    print("  %-22s %8.3f ms/step" % ("rigid cylinder", base))
    for every in (NEVER, "200", "50", "10", "auto", "1"):
        key = ("membrane", every)
        share = float(t[key]["detections"] or 0) / float(t[key]["steps"])
        name = "membrane, placed only" if every == NEVER else "membrane every " + every
        print("  %-22s %8.3f ms/step  %+7.1f %% vs cylinder (its own %+7.1f %%)  "
              "detections on %5.1f %% of the steps"
              % (name, ms(key), 100 * (ms(key) / base - 1), 100 * (ms(key) - base - denser) / base,
                 100 * share))
    # every 1 detects each step, every 200 almost never: the difference is a detection
    print("  one detection          %8.1f ms" % (ms(("membrane", "1")) - ms(("membrane", "200"))))
    print("  pair forces            %8.3f ms/step in the cylinder, %.3f under the membrane (%+.1f %%); "
          "contacts per sphere %.2f and %.2f"
          % (ms(cylinder, "pair_ms_per_step"), ms(placed, "pair_ms_per_step"),
             100 * (ms(placed, "pair_ms_per_step") / ms(cylinder, "pair_ms_per_step") - 1),
             float(t[cylinder]["contacts_per_sphere"]), float(t[placed]["contacts_per_sphere"])))
PY
