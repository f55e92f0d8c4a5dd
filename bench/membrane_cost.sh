#!/usr/bin/env bash
# Step time of the 8 404-disk biaxial shear with: no lateral boundary (platens
# only), fix membrane2d every 1, every auto (the default: the same chains as
# every 1) and every 10, and rigid servo side walls, on 1
# and 2 ranks. Prints the times and the ratios to 'none', measured in one run.
# 'none' lets the sample spread sideways, so its contacts (the pair work) differ
# from a confined sample; 'membrane kept' (fix membrane2d with the chain found
# once and kept: forces every step, no re-detection) has the same physics as the
# membrane runs, so the ratios to it isolate the cost of re-detecting the chain.
#   bench/membrane_cost.sh [RESTART] [NSTEPS]
# RESTART: a prepared full-size sample (./run.sh writes out/biaxial/prepared.restart).
set -euo pipefail
cd "$(dirname "$0")"
restart=$(readlink -f "${1:-../out/biaxial/prepared.restart}")
nsteps=${2:-3000}
exe=$(readlink -f ../build/app/liggghts-membrane)
[ -f "$restart" ] || { echo "no prepared sample $restart: run ./run.sh first"; exit 1; }
csv=membrane_cost.csv
. ./step_time.sh
echo "ranks,lateral,every,ms_per_step" > $csv
for np in 1 2; do
  for variant in "none 0 1" "kept 1 1000000000" "membrane 1 1" "membrane 1 auto" "membrane 1 10" "rigid 2 1"; do
    set -- $variant
    ms=$(ms_per_step $np in.membrane_cost restart "$restart" lateral "$2" every "$3" nsteps "$nsteps")
    echo "$np,$1,$3,$ms" >> $csv
  done
done
/usr/bin/python3 - "$csv" <<'PY'
import collections, csv, sys
by_ranks = collections.defaultdict(list)  # the variants of each rank count, in run order
for r in csv.DictReader(open(sys.argv[1])):
    by_ranks[r["ranks"]].append(r)
for np_, sel in sorted(by_ranks.items()):
    base = float(next(r["ms_per_step"] for r in sel if r["lateral"] == "none"))
    kept = float(next(r["ms_per_step"] for r in sel if r["lateral"] == "kept"))
    print("ranks %s:" % np_)
    for r in sel:
        t = float(r["ms_per_step"])
        name = {"none": "none (platens only)", "kept": "membrane, chain kept",
                "rigid": "rigid servo walls"}.get(r["lateral"], "membrane every %s" % r["every"])
        print("  %-22s %7.3f ms/step  %+6.1f %% vs none  %+6.1f %% vs chain kept"
              % (name, t, 100 * (t / base - 1), 100 * (t / kept - 1)))
PY
