#!/usr/bin/env bash
# Cost of one compute fabric call on a prepared sample (default: the 8 404-disk
# sample of ./run.sh), with the stability index, histogram and stress off
# ('basic', the defaults) and on ('full'), on 1 and 2 ranks: runs of NSTEPS steps
# with thermo output every step, without the compute and with each variant, in
# turn, REPEAT times in one process (in.fabric_cost); the fastest run of each
# counts. Per call = (variant - none) per step, also in plain steps.
#   bench/fabric_cost.sh [RESTART]
# Environment: EXE (another build), CSV (another table), NSTEPS (default 200),
# REPEAT (default 3).
set -euo pipefail
cd "$(dirname "$0")"
restart=$(readlink -f "${1:-../out/biaxial/prepared.restart}")
exe=${EXE:-$(readlink -f ../build/app/liggghts-membrane)}
[ -f "$restart" ] || { echo "no prepared sample $restart: run ./run.sh first"; exit 1; }
csv=${CSV:-fabric_cost.csv}
echo "ranks,what,ms_per_step" > "$csv"
for np in 1 2; do
  mpirun --allow-run-as-root --oversubscribe -np "$np" "$exe" -in in.fabric_cost -log none \
      -var restart "$restart" -var meshdir "$(readlink -f ../examples/biaxial/meshes)" \
      -var nsteps "${NSTEPS:-200}" -var repeat "${REPEAT:-3}" |
    awk -v np="$np" '/^Loop time/ { ms = 1000 * $4 / $9; w = k++ % 3
                                     if (!(w in best) || ms < best[w]) best[w] = ms }
                     END { split("none basic full", name)
                           for (w = 0; w < 3; w++) printf "%s,%s,%.4f\n", np, name[w + 1], best[w] }' >> "$csv"
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
