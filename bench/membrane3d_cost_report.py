"""The summary of bench/membrane3d_cost.sh and bench/membrane3d_cuboid_cost.sh from
their CSV: per rank count, each membrane's step time against the rigid boundary's (the
row of lateral BASE, every 0), its own cost, the steps it detects on, the cost of one
detection, and the sample's pair forces and contacts per sphere under each boundary.

    python3 membrane3d_cost_report.py CSV NEVER BASE "NAME"

NEVER: the every of the membrane placed only; BASE: the rigid boundary's lateral
(cylinder, walls); NAME: how to call it (rigid cylinder, servo walls). Optional CSV
columns sigma1_kpa, sigma3_kpa (the stresses after the settle) are printed too. A case
run more than once (rounds: several rows of the same ranks, lateral and every) counts
with the median of each time, its range shown beside it."""
import collections
import csv
import statistics
import sys

path, NEVER, BASE, NAME = sys.argv[1:5]
rows = collections.defaultdict(lambda: collections.defaultdict(list))
for r in csv.DictReader(open(path)):
    rows[r["ranks"]][(r["lateral"], r["every"])].append(r)
for np_, runs in sorted(rows.items()):
    t = {key: rs[0] for key, rs in runs.items()}  # the sample's state: the same each round

    def ms(key, column="ms_per_step"):  # the median over the rounds
        return statistics.median(float(r[column]) for r in runs[key])

    def spread(key):
        times = [float(r["ms_per_step"]) for r in runs[key]]
        return " (%.3f-%.3f)" % (min(times), max(times)) if len(times) > 1 else ""

    def state(key):  # the sample's own state under this boundary
        r = t[key]
        s = "; pair %.3f ms/step, %.2f contacts/sphere" % (ms(key, "pair_ms_per_step"),
                                                           float(r["contacts_per_sphere"]))
        if r.get("sigma1_kpa"):
            s += ", settled at sigma1 %.1f, sigma3 %.1f kPa" % (float(r["sigma1_kpa"]),
                                                                 float(r["sigma3_kpa"]))
        return s

    rigid, placed = (BASE, "0"), ("membrane", NEVER)
    base = ms(rigid)

    def sample(key):  # the sample's own cost: its pair forces and neighbour lists
        return ms(key, "pair_ms_per_step") + ms(key, "neigh_ms_per_step")
    # the membrane's sample seen with a membrane placed only (in the rigid cylinder it
    # has fewer contacts): without it, what each membrane costs itself (its detections
    # slow the pair forces that follow them too: they are its cost)
    denser = sample(placed) - sample(rigid)
    rounds = max(len(rs) for rs in runs.values())
    print("ranks %s:%s" % (np_, " (median of %d rounds, range)" % rounds if rounds > 1 else ""))
    print("  %-22s %8.3f ms/step%s%s" % (NAME, base, spread(rigid), state(rigid)))
    for every in (NEVER, "200", "50", "10", "auto", "1"):
        key = ("membrane", every)
        if key not in t:
            continue
        share = float(t[key]["detections"] or 0) / float(t[key]["steps"])
        name = "membrane, placed only" if every == NEVER else "membrane every " + every
        print("  %-22s %8.3f ms/step%s  %+7.1f %% vs %s (its own %+7.1f %%)  "
              "detections on %5.1f %% of the steps%s"
              % (name, ms(key), spread(key), 100 * (ms(key) / base - 1), BASE,
                 100 * (ms(key) - base - denser) / base, 100 * share, state(key)))
    # every 1 detects each step, every 200 almost never: the difference is a detection
    if ("membrane", "1") in t and ("membrane", "200") in t:
        print("  one detection          %8.1f ms" % (ms(("membrane", "1")) - ms(("membrane", "200"))))
    print("  pair forces            %8.3f ms/step with the %s, %.3f under the membrane (%+.1f %%); "
          "contacts per sphere %.2f and %.2f"
          % (ms(rigid, "pair_ms_per_step"), BASE, ms(placed, "pair_ms_per_step"),
             100 * (ms(placed, "pair_ms_per_step") / ms(rigid, "pair_ms_per_step") - 1),
             float(t[rigid]["contacts_per_sphere"]), float(t[placed]["contacts_per_sphere"])))
