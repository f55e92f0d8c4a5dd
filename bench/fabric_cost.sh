#!/usr/bin/env bash
# Cost of one compute fabric call on the prepared 8 404-disk sample, with the
# stability index, histogram and stress off ('basic') and on ('full'), on 1 and
# 2 ranks: 200 steps with thermo output every step, minus the same run without
# the compute, divided by 200; also as a multiple of one plain step.
#   bench/fabric_cost.sh [RESTART]
# Environment: EXE (another build), CSV (another table), NSTEPS (default 200),
# REPEAT (default 1; the fastest of REPEAT runs counts, against a loaded machine).
set -euo pipefail
cd "$(dirname "$0")"
restart=$(readlink -f "${1:-../out/biaxial/prepared.restart}")
exe=${EXE:-$(readlink -f ../build/app/liggghts-membrane)}
[ -f "$restart" ] || { echo "no prepared sample $restart: run ./run.sh first"; exit 1; }
csv=${CSV:-fabric_cost.csv}
. ./step_time.sh
echo "ranks,what,ms_per_step" > $csv
for np in 1 2; do
  for what in 0:none 1:basic 2:full; do
    best=
    for _ in $(seq "${REPEAT:-1}"); do
      ms=$(ms_per_step $np in.fabric_cost restart "$restart" what ${what%%:*} nsteps "${NSTEPS:-200}")
      if [ -z "$best" ] || awk "BEGIN {exit !($ms < $best)}"; then best=$ms; fi
    done
    echo "$np,${what#*:},$best" >> $csv
  done
done
/usr/bin/python3 - "$csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for np_ in sorted({r["ranks"] for r in rows}):
    t = {r["what"]: float(r["ms_per_step"]) for r in rows if r["ranks"] == np_}
    print("ranks %s: plain step %.3f ms" % (np_, t["none"]))
    for w in ("basic", "full"):
        c = t[w] - t["none"]
        print("  compute fabric %-5s %.3f ms per call = %.2f plain steps" % (w, c, c / t["none"]))
PY
