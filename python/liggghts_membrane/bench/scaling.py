#!/usr/bin/env python3
"""How the biaxial test's cost grows with the sample and the rank count: one command,

    /usr/bin/python3 bench/scaling.py            (about 30 min on 2 cores)

writes bench/scaling.csv (one row per sample size and rank count), bench/scaling.md
(the tables and the parallel-efficiency model) and bench/scaling.png; the runs are kept
in out/bench/scaling/ and reused while their inputs are the same.

1. Preparation from scratch (scripts/generate_sample.py + examples/biaxial/in.prepare)
   at --prepare-scales (default 0.25, 0.5, 1): wall time, steps, seconds per disk.
2. The samples of the timing points: the prepared scale-1 sample tiled S x S times
   (in.scaling_sample: write_data, tiled here, read_data, --nsettle steps with four
   servo walls at 100 kPa so that the seams close). ./run.sh --scale S prepares from
   scratch instead; tiling only makes the 538 000-disk point affordable here.
3. At each scale and rank count, in.membrane_cost (fix viscous 500, platens moving at
   the examples' strain rate, 0.0025 /s, after --nwarm steps with them still; the
   membrane first settles for --nmembrane steps, as the walls of the tiled sample
   give way to it) with three lateral boundaries: none
   (platens only), rigid servo walls, fix membrane2d every auto; the fastest of
   --repeat timed runs of --nsteps steps counts, over --rounds processes of the rigid
   and the membrane shear in turn. The membrane run then times compute
   fabric (stability, histogram, stress) in runs of --fabric-steps steps with thermo
   output every step, against as many steps without it, in turn.
   Measured: wall ms per step and us per particle-step, the membrane fix's own share
   of the step (its timer, printed at the end of each run), compute fabric per call
   in plain steps, peak resident memory per rank, what each rank receives from the
   membrane's collectives (its report) and from compute fabric's (from the ghost
   count LIGGGHTS prints).

`--from-csv` makes the report again from scaling.csv and scaling.json alone.
"""
import argparse
import math
import os
import re
import shutil
import sys
import time

from liggghts_membrane import params, readers, sample
from liggghts_membrane.bench import common

PREFIX = os.path.join(common.HERE, "scaling")
RUNS = os.path.join(common.ROOT, "out", "bench", "scaling")
COST_SCRIPT = os.path.join(common.HERE, "in.membrane_cost")
TILE_SCRIPT = os.path.join(common.HERE, "in.scaling_sample")
SEED = 12345
NOUT = 500           # the examples' output interval (shear_setup.inc nout): fabric's share
FORWARD_DOUBLES = 9  # x, v, omega per ghost in LIGGGHTS' forward communication (vel yes)
REVERSE_DOUBLES = 1  # compute fabric's contact count per ghost (8 with per-atom angles)
CSV_KEYS = ["scale", "disks", "ranks", "ms_none", "ms_rigid", "ms_membrane",
            "us_none", "us_rigid", "us_membrane", "membrane_vs_rigid_pct",
            "membrane_share_pct", "search_share_pct", "detections_per_1000", "full_pass_pct",
            "fabric_ms_per_call", "fabric_plain_steps", "fabric_share_pct",
            "peak_mb_per_rank", "membrane_kb_per_step", "membrane_kb_per_detection",
            "fabric_kb_per_call", "ghosts_per_rank", "pair_pct_membrane"]

# peak resident memory of one rank, written to PREFIX.RANK (between mpirun and the executable)
RSS_WRAPPER = ("import os, resource, subprocess, sys\n"
               "rc = subprocess.call(sys.argv[2:])\n"
               "with open(sys.argv[1] + '.' + os.environ.get('OMPI_COMM_WORLD_RANK', '0'), 'w') as f:\n"
               "    f.write('%d\\n' % resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
               "sys.exit(rc)\n")


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--scales", type=common.floats, default=[1, 2, 4, 8])
    p.add_argument("--ranks", type=common.ints, default=[1, 2])
    p.add_argument("--one-rank-up-to", type=float, default=4,
                   help="the largest scale also run on 1 rank (default 4: scale 8 on 2 ranks only)")
    p.add_argument("--prepare-scales", type=common.floats, default=[0.25, 0.5, 1])
    p.add_argument("--nsettle", type=int, default=2000)
    p.add_argument("--nwarm", type=int, default=500)
    p.add_argument("--nmembrane", type=int, default=3000,
                   help="steps the membrane settles (platens still) before its timed runs")
    p.add_argument("--nsteps", type=int, default=2000,
                   help="timed steps per run at scale 1; / S^2 above, at least 200")
    p.add_argument("--fabric-steps", type=int, default=200,
                   help="steps per compute fabric run at scale 1; / S^2 above, at least 20")
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--rounds", type=int, default=2,
                   help="processes of the rigid and the membrane shear, in turn (the fastest run counts)")
    p.add_argument("--rate", type=float, default=common.script_number("shear_setup.inc", "rate"),
                   help="axial strain rate [1/s] (default: the examples' shear_setup.inc)")
    p.add_argument("--from-csv", action="store_true")
    return p.parse_args(argv)


# ----------------------------------------------------------------------------- running
def mpi_run(np_, script, folder, name, settings, timed=True, cwd=None):
    """One run of the executable in `folder` (screen NAME.screen, peak RSS per rank
    NAME.rss.RANK), reused when NAME.done holds the same settings (and for a `timed`
    run the same executable; a sample stays valid across builds), from the folder
    `cwd` (default: the script's): (screen text, peak RSS per rank [MB], wall seconds)."""
    os.makedirs(folder, exist_ok=True)
    screen = os.path.join(folder, name + ".screen")
    done = os.path.join(folder, name + ".done")
    exe = common.sha(common.EXE) if timed else ""
    key = common.sha_text(repr((np_, common.sha(script), exe, sorted(settings.items()))))
    if not (os.path.exists(done) and open(done).read().split()[0] == key):
        rss = os.path.join(folder, name + ".rss")
        cmd = (common.mpi_command(np_) + ["/usr/bin/python3", "-c", RSS_WRAPPER, rss, common.EXE,
               "-in", script, "-log", "none"] + common.var_args(settings))
        common.log(f"  {name}: {np_} rank(s)")
        rc, wall, _ = common.run_command(cmd, cwd or os.path.dirname(script), screen, 4 * 3600)
        if rc != 0:
            raise RuntimeError(f"{name} failed ({rc}): {common.symptom(screen)} (see {os.path.relpath(screen, common.ROOT)})")
        with open(done, "w") as f:
            f.write(f"{key} {wall:.3f}\n")
    wall = float(open(done).read().split()[1])
    rss = [int(open(os.path.join(folder, f)).read()) / 1024 for f in sorted(os.listdir(folder))
           if f.startswith(name + ".rss.")]
    return open(screen, errors="replace").read(), rss, wall


LOOP = re.compile(r"^Loop time of (\S+) on (\d+) procs for (\d+) steps", re.M)
# fix membrane2d's key=value line at the end of each run (membrane_gather.cpp report_traffic)
TRAFFIC_KEYS = ("kb_per_step", "kb_per_detection", "steps", "detections", "full_passes",
                "fix_seconds", "search_seconds")
GHOSTS = re.compile(r"^Nghost:\s+(\S+) ave", re.M)
PAIR = re.compile(r"^Pair\s+time \(%\) = \S+ \((\S+)\)", re.M)


def loops(text):
    """(seconds, steps) of each run of a screen output, in order."""
    return [(float(m.group(1)), int(m.group(3))) for m in LOOP.finditer(text)]


# ----------------------------------------------------------------------------- the stages
def prepare_from_scratch(scale, np_):
    folder = os.path.join(RUNS, f"prepare_scale{common.tag(scale)}")
    os.makedirs(folder, exist_ok=True)
    data = os.path.join(folder, "sample.data")
    if not os.path.exists(data):
        common.generate_sample(scale, SEED, data)
    text, _, wall = mpi_run(np_, os.path.join(common.EXAMPLES, "in.prepare"), folder, "prepare",
                            {"data": data, "out": os.path.join(folder, "prepared.restart")}, timed=False)
    disks = len(readers.read_data_diameters(data))
    steps = sum(n for _, n in loops(text))
    return dict(scale=scale, disks=disks, ranks=np_, wall_s=wall, steps=steps,
                s_per_disk=wall / disks, us_per_disk_step=1e6 * wall / (disks * steps * 1.0 / np_)
                if steps else float("nan")), os.path.join(folder, "prepared.restart")


def read_walls(path):
    """A walls file of in.prepare or in.cuboid_prepare (OUT.walls: 'variable NAME equal VALUE' lines)."""
    values = params.read_variables(path, follow_includes=False)
    return {name: params.number(values, name) for name in values}


def tile_data(base_data, walls, tiles, out_data, out_walls):
    """The data file of `base_data` repeated tiles x tiles times, one wall box apart
    (xr0 - xl0, yt0 - yb0), and the walls file of the tiled box."""
    a = readers.read_data_atoms(base_data)
    atoms = list(zip(a["type"].astype(int), a["diameter"], a["x"], a["y"]))
    wx, wy = walls["xr0"] - walls["xl0"], walls["yt0"] - walls["yb0"]
    tiled = dict(xl0=walls["xl0"], xr0=walls["xl0"] + tiles * wx, yb0=walls["yb0"],
                 yt0=walls["yb0"] + tiles * wy, W0=walls["W0"] * tiles, H0=walls["H0"] * tiles,
                 scale=walls["scale"] * tiles)
    margin = sample.MARGIN   # as the sample command
    W, H = tiles * wx, tiles * wy
    rho = common.script_number(os.path.join(common.EXAMPLES, "material.inc"), "rho")
    with open(out_data, "w") as f:
        f.write(f"LIGGGHTS data: {len(atoms)} disks tiled {tiles} x {tiles} by bench/scaling.py\n\n")
        f.write(f"{len(atoms) * tiles * tiles} atoms\n3 atom types\n\n")
        f.write("%.12g %.12g xlo xhi\n" % (tiled["xl0"] - margin * W, tiled["xr0"] + margin * W))
        f.write("%.12g %.12g ylo yhi\n" % (tiled["yb0"] - margin * H, tiled["yt0"] + margin * H))
        f.write("%.12g %.12g zlo zhi\n\nAtoms\n\n" % (-0.05 * tiled["scale"], 0.05 * tiled["scale"]))
        n = 0
        for i in range(tiles):
            for j in range(tiles):
                for t, d, x, y in atoms:
                    n += 1
                    f.write("%d %d %.12g %g %.12g %.12g 0\n" % (n, t, d, rho, x + i * wx, y + j * wy))
    with open(out_walls, "w") as f:
        for k, v in tiled.items():
            f.write("variable %s equal %.17g\n" % (k, v))
    return len(atoms) * tiles * tiles


def tiled_sample(base_restart, scale, nsettle, np_):
    """The restart file of the base sample tiled `scale` x `scale` times and settled."""
    folder = os.path.join(RUNS, f"tiles{common.tag(scale)}")
    os.makedirs(folder, exist_ok=True)
    base_data = os.path.join(RUNS, "base.data")
    mpi_run(1, TILE_SCRIPT, RUNS, "export", {"export": 1, "restart": base_restart, "data": base_data},
            timed=False)
    data, walls = os.path.join(folder, "tiled.data"), os.path.join(folder, "tiled.walls")
    disks = tile_data(base_data, read_walls(base_restart + ".walls"), int(round(scale)), data, walls)
    restart = os.path.join(folder, "tiled.restart")
    mpi_run(np_, TILE_SCRIPT, folder, "settle",
            {"data": data, "walls": walls, "out": restart, "nsettle": nsettle}, timed=False)
    return restart, disks


def timed_point(restart, scale, disks, np_, args):
    """The three lateral boundaries on one sample and rank count: one CSV row."""
    folder = os.path.join(RUNS, f"scale{common.tag(scale)}_np{np_}")
    nsteps = max(200, int(args.nsteps / scale ** 2))
    nfab = max(20, int(args.fabric_steps / scale ** 2))
    base = {"restart": restart, "meshdir": common.MESHES, "nwarm": args.nwarm, "nsteps": nsteps,
            "repeat": args.repeat, "rate": args.rate}
    row = dict(scale=scale, disks=disks, ranks=np_)
    peak = []
    # rigid and membrane in turn, in separate processes: this machine's speed
    # drifts by +-20 % from one process to the next
    order = [("none", 0)] + [(("rigid", "membrane")[k % 2], (2, 1)[k % 2]) for k in range(2 * args.rounds)]
    for turn, (name, lateral) in enumerate(order):
        again = turn > 2     # a later round of the same boundary
        settings = dict(base, lateral=lateral, every="auto",
                        fabric=nfab if lateral == 1 and not again else 0)
        if lateral == 1:
            # the membrane takes over from the walls of the tiled sample: its chain
            # settles for --nmembrane steps (platens still) before the timed runs
            settled = os.path.join(folder, "membrane_settled.restart")
            mpi_run(np_, COST_SCRIPT, folder, "membrane_settle",
                    dict(base, lateral=1, every="auto", nwarm=args.nmembrane, settle=1, settled=settled))
            shutil.copy(restart + ".walls", settled + ".walls")   # W0 H0 scale (the meshes are in the restart)
            settings.update(restart=settled, nwarm=100)
        text, rss, _ = mpi_run(np_, COST_SCRIPT, folder, name + ("_round%d" % ((turn - 1) // 2) if again else ""),
                               settings)
        peak += rss
        runs = loops(text)
        timed = runs[1:1 + args.repeat]
        fastest = min(1e3 * t / n for t, n in timed)
        row["ms_" + name] = min(fastest, row.get("ms_" + name, fastest))
        row["us_" + name] = 1e3 * row["ms_" + name] / disks
        if lateral != 1 or again:
            continue
        pair = [float(x) for x in PAIR.findall(text)]
        row["pair_pct_membrane"] = pair[1] if len(pair) > 1 else float("nan")
        ghosts = [float(x) for x in GHOSTS.findall(text)]
        row["ghosts_per_rank"] = ghosts[1] if len(ghosts) > 1 else 0.0
        traffic = [tuple(line[k] for k in TRAFFIC_KEYS)
                   for line in readers.key_value_lines(text, "membrane2d_traffic")]
        # the timed runs: each the report just before its Loop time line
        shares, searches, kb_step, kb_det, det, full = [], [], 0.0, 0.0, 0.0, 0.0
        for (t, n), tr in zip(timed, traffic[1:1 + args.repeat]):
            shares.append(100 * tr[5] / t)
            searches.append(100 * tr[6] / t)
            kb_step, kb_det, det = tr[0], tr[1], 1000.0 * tr[3] / tr[2]
            full = 100.0 * tr[4] / tr[3] if tr[3] else 0.0
        row["membrane_share_pct"] = min(shares)
        row["search_share_pct"] = min(searches)
        row["membrane_kb_per_step"], row["membrane_kb_per_detection"] = kb_step, kb_det
        row["detections_per_1000"] = det
        row["full_pass_pct"] = full
        fab = runs[1 + args.repeat:]
        plain = min(1e3 * t / n for t, n in fab[0::2])
        with_fabric = min(1e3 * t / n for t, n in fab[1::2])
        row["fabric_ms_per_call"] = with_fabric - plain
        row["fabric_plain_steps"] = (with_fabric - plain) / plain
        row["fabric_share_pct"] = 100 * (with_fabric - plain) / (NOUT * row["ms_membrane"])
        reduction_doubles = 2 * (9 + 3 * 18) + 2 * 5 + 2   # fabric_sums.h, 18 bins
        row["fabric_kb_per_call"] = (8 * (FORWARD_DOUBLES + REVERSE_DOUBLES) * row["ghosts_per_rank"]
                                     + 8 * reduction_doubles) / 1e3 if np_ > 1 else 0.0
    row["peak_mb_per_rank"] = max(peak) if peak else float("nan")
    row["membrane_vs_rigid_pct"] = 100 * (row["ms_membrane"] / row["ms_rigid"] - 1)
    return row


# ----------------------------------------------------------------------------- the model
# Two typical cluster networks: (latency [s], bandwidth [B/s]) per message.
NETWORKS = {"InfiniBand (2 us, 10 GB/s)": (2e-6, 10e9), "10 Gb Ethernet (30 us, 1.2 GB/s)": (30e-6, 1.2e9)}
LIGGGHTS_COLLECTIVES = 6   # small allreduces per step of the test itself: 4 mesh force sums, neighbour check, servo
MEMBRANE_COLLECTIVES = 3   # fix membrane2d per step: count allgather, data allgatherv, watch allreduce
HALO_MESSAGES = 4          # exchanges with the 4 neighbouring sub-domains of a 2D grid


def efficiency(p, network, work_s, ghosts, halo_messages, membrane_s, membrane_bytes,
               membrane_collectives=MEMBRANE_COLLECTIVES):
    """The step at P ranks on one network (a NETWORKS value): the rigid test's work of a
    step on one rank `work_s` [s] divided evenly; its halo, HALO_MESSAGES-like
    `halo_messages` exchanges of `ghosts` ghosts of FORWARD_DOUBLES each; its
    LIGGGHTS_COLLECTIVES small allreduces; a membrane adding `membrane_s` [s] of work on
    each rank, `membrane_collectives` collectives and `membrane_bytes` received per rank.
    Returns (compute, halo, collectives, membrane [s], efficiency rigid, efficiency
    with the membrane)."""
    alpha, beta = network
    t_calc = work_s / p
    t_halo = halo_messages * alpha + 8 * FORWARD_DOUBLES * ghosts / beta
    t_coll = LIGGGHTS_COLLECTIVES * 2 * math.log2(p) * alpha
    t_mem = membrane_s + membrane_collectives * math.log2(p) * alpha + membrane_bytes / beta
    t_rigid = t_calc + t_halo + t_coll
    return t_calc, t_halo, t_coll, t_mem, work_s / (p * t_rigid), work_s / (p * (t_rigid + t_mem))


def model(rows):
    """Parallel efficiency at P = 16, 64, 256 for the largest sample, from the measured
    work per particle-step (1 rank, largest scale run on 1 rank), the ghosts per unit
    length of a sub-domain edge and the membrane's per-step work and volumes (2 ranks,
    largest scale). Returns (table lines, assumptions text)."""
    one = [r for r in rows if r["ranks"] == 1]
    two = [r for r in rows if r["ranks"] == 2]
    if not one or not two:
        return [], ""
    r1 = max(one, key=lambda r: r["disks"])
    r2 = max(two, key=lambda r: r["disks"])
    n = r2["disks"]
    scale = r2["scale"]
    width = 0.075 * scale                             # m: the cut of 2 ranks runs across the width
    ghosts_per_m = r2["ghosts_per_rank"] / width      # one cut edge per rank on 2 ranks
    lines = ["| network | P | disks per rank | compute [ms/step] | halo [ms] | collectives [ms] "
             "| membrane [ms] | efficiency, rigid | efficiency, membrane |", "|" + "---|" * 9]
    for net, (alpha, beta) in NETWORKS.items():
        for p in (16, 64, 256):
            px = max(1, round(math.sqrt(p / 2)))       # processors * * 1 on a 1 x 2 sample
            side = width / px
            ghosts = 4 * side * ghosts_per_m
            # the fix's own work on 2 ranks (chain-sized, on every rank), its gather's volume
            t_fix2 = 1e-3 * r2["membrane_share_pct"] / 100 * r2["ms_membrane"]
            volume = 1e3 * r2["membrane_kb_per_step"] + r2["detections_per_1000"] / 1000 * (
                1e3 * r2["membrane_kb_per_detection"])
            t_calc, t_halo, t_coll, t_mem, e_rigid, e_mem = efficiency(
                p, (alpha, beta), 1e-6 * r1["us_rigid"] * n, ghosts, HALO_MESSAGES, t_fix2, volume)
            lines.append(f"| {net} | {p} | {n // p} | {1e3 * t_calc:.3g} | {1e3 * t_halo:.2g} | "
                         f"{1e3 * t_coll:.2g} | {1e3 * t_mem:.2g} | {100 * e_rigid:.0f} % | {100 * e_mem:.0f} % |")
    text = (f"Assumed: the work of a step, {r1['us_rigid']:.3g} us per particle-step (rigid shear, "
            f"1 rank, {r1['disks']} disks), divides evenly over P ranks (sub-domains of equal disk "
            f"count: no load imbalance); `processors * * 1` cuts the {n}-disk sample (1 x 2) into "
            f"about square sub-domains, each with {HALO_MESSAGES} neighbours and "
            f"{ghosts_per_m:.0f} ghosts per metre of edge (measured on 2 ranks), "
            f"{8 * FORWARD_DOUBLES} bytes each per step; {LIGGGHTS_COLLECTIVES} small allreduces "
            f"per step (2 log2 P latencies each); fix membrane2d adds its measured own work per "
            f"step on 2 ranks ({r2['membrane_share_pct']:.2g} % of {r2['ms_membrane']:.3g} ms: "
            f"chain-sized, done on every rank), {MEMBRANE_COLLECTIVES} collectives of log2 P "
            f"latencies and the {r2['membrane_kb_per_step']:.3g} kB every rank receives per step, "
            f"plus {r2['membrane_kb_per_detection']:.3g} kB per detection at "
            f"{r2['detections_per_1000']:.0f} detections per 1000 steps. Compute fabric at one "
            f"call per {NOUT} steps is left out (its share is in the table above). Not modelled: "
            f"contention, the moving meshes' own parallel bookkeeping, I/O.")
    return lines, text


# ----------------------------------------------------------------------------- the report
def report(prefix):
    rows = common.read_rows(prefix + ".csv", int_keys=("disks", "ranks"))
    ctx = common.read_context(prefix + ".json")
    prep = ctx["prepare"]
    f = common.fmt
    out = ["# Scaling: sample size and rank count", "",
           f"`{ctx['command']}` ({ctx['minutes']:.0f} min on {ctx['cores']} cores; "
           f"{ctx['nsettle']} settling steps per tiled sample, {ctx['nwarm']} steps with the "
           f"platens still, then the fastest of {ctx['repeat']} timed runs in each of "
           f"{ctx.get('rounds', 1)} processes per boundary, rigid and membrane in turn, the "
           f"platens at {ctx['rate']:g} /s axial strain rate). "
           "Scale S is the linear scale of the published 75 x 150 mm sample; S > 1 is the "
           "prepared scale-1 sample tiled S x S times and settled (the preparation itself is "
           "timed from scratch below). Wall time per step divided by the disks: flat in N means "
           "cost proportional to N.", "",
           common.markdown_table(rows, [
               ("S", lambda r: f(r["scale"], "{:g}")), ("disks", lambda r: r["disks"]),
               ("ranks", lambda r: r["ranks"]),
               ("us/particle-step none / rigid / membrane",
                lambda r: " / ".join(f(r[k], "{:.3f}") for k in ("us_none", "us_rigid", "us_membrane"))),
               ("membrane vs rigid", lambda r: f(r["membrane_vs_rigid_pct"], "{:+.1f} %")),
               ("fix membrane2d share (searches)", lambda r: f(r["membrane_share_pct"], "{:.1f} %")
                + " (" + f(r["search_share_pct"], "{:.2f} %") + ")"),
               ("detections / 1000 steps (full passes)", lambda r: f(r["detections_per_1000"], "{:.0f}")
                + " (" + f(r["full_pass_pct"], "{:.0f} %") + ")"),
               ("compute fabric per call: ms, plain steps", lambda r: f(r["fabric_ms_per_call"], "{:.3g}")
                + ", " + f(r["fabric_plain_steps"], "{:.2f}")),
               (f"fabric share (1 call / {NOUT} steps)", lambda r: f(r["fabric_share_pct"], "{:.2f} %")),
               ("peak MB per rank", lambda r: f(r["peak_mb_per_rank"], "{:.0f}")),
               ("kB per rank: membrane per step, per detection; fabric per call",
                lambda r: f(r["membrane_kb_per_step"], "{:.3g}") + ", " + f(r["membrane_kb_per_detection"], "{:.3g}")
                + "; " + f(r["fabric_kb_per_call"], "{:.3g}")),
           ]), ""]
    for np_ in sorted({r["ranks"] for r in rows}):
        sel = [r for r in rows if r["ranks"] == np_]
        for k, name in (("us_rigid", "rigid"), ("us_membrane", "membrane")):
            v = [r[k] for r in sel]
            out.append(f"- {np_} rank(s), {name}: us per particle-step from {min(v):.3f} to "
                       f"{max(v):.3f}, spread {100 * (max(v) / min(v) - 1):.0f} % over "
                       f"{min(r['disks'] for r in sel)}-{max(r['disks'] for r in sel)} disks.")
    out += ["", "Membrane share: the fix's own wall time (its timer, slowest rank) over the "
            "loop time; searches: the part spent in the chain searches, which run on one rank "
            "per side while the others wait. Fabric per call: a run with compute fabric "
            "(stability, histogram, stress) in the thermo output every step minus one without, "
            "per step, in the membrane shear. Peak memory: resident set of the largest rank, "
            "whole run. Fabric's bytes: forward communication of the ghosts "
            f"({FORWARD_DOUBLES} doubles each), their contact counts back to the owners "
            f"({REVERSE_DOUBLES}), and the reduction of the partial sums (~2 kB), from LIGGGHTS' "
            "ghost count.", "",
            "## Preparation from scratch", "",
            common.markdown_table(prep, [
                ("S", lambda r: f(r["scale"], "{:g}")), ("disks", lambda r: r["disks"]),
                ("ranks", lambda r: r["ranks"]), ("steps", lambda r: r["steps"]),
                ("wall s", lambda r: f(r["wall_s"], "{:.0f}")),
                ("ms per disk", lambda r: f(1e3 * r["s_per_disk"], "{:.1f}")),
                ("us per disk-step (x ranks)", lambda r: f(r["us_per_disk_step"], "{:.3f}"))]),
            "", "## Beyond two cores: a model", ""]
    lines, text = model(rows)
    out += lines + ["", text, "", "![scaling](scaling.png)", ""]
    return "\n".join(out)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for np_, ls in ((1, "-"), (2, "--")):
        sel = sorted((r for r in rows if r["ranks"] == np_), key=lambda r: r["disks"])
        if not sel:
            continue
        n = [r["disks"] for r in sel]
        for k, c in (("us_none", "grey"), ("us_rigid", "tab:blue"), ("us_membrane", "tab:red")):
            a.plot(n, [r[k] for r in sel], ls, color=c, marker="o",
                   label=f"{k[3:]}, {np_} rank{'s' if np_ > 1 else ''}")
        b.plot([r["disks"] / np_ for r in sel], [r["peak_mb_per_rank"] for r in sel], ls,
               marker="o", label=f"{np_} rank{'s' if np_ > 1 else ''}")
    a.set_xscale("log")
    a.set_ylim(bottom=0)
    a.set_xlabel("disks")
    a.set_ylabel("wall us per particle-step")
    a.legend(fontsize=7)
    b.set_xlabel("disks per rank")
    b.set_ylabel("peak resident MB per rank")
    b.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main(argv):
    args = parse_args(argv)
    if args.from_csv:
        print(report(PREFIX))
        return 0
    t0 = time.time()
    np_max = max(args.ranks)
    prep, base = [], None
    for s in args.prepare_scales:
        common.log(f"prepare scale {common.tag(s)} from scratch")
        r, restart = prepare_from_scratch(s, np_max)
        prep.append(r)
        if s == 1:
            base = restart
    if base is None:
        _, base = prepare_from_scratch(1, np_max)
    rows = []
    for s in args.scales:
        common.log(f"scale {common.tag(s)}: tile and settle")
        restart, disks = tiled_sample(base, s, args.nsettle, np_max)
        for np_ in args.ranks:
            if np_ == 1 and s > args.one_rank_up_to:
                continue
            common.log(f"scale {common.tag(s)}, {disks} disks, {np_} rank(s)")
            rows.append(timed_point(restart, s, disks, np_, args))
    common.write_rows(PREFIX + ".csv", rows, CSV_KEYS)
    common.write_context(PREFIX + ".json", dict(
        command="bench/scaling.py " + " ".join(argv), minutes=(time.time() - t0) / 60,
        cores=os.cpu_count(), nsettle=args.nsettle, nwarm=args.nwarm, repeat=args.repeat,
        rounds=args.rounds,
        rate=args.rate,
        prepare=prep))
    plot(common.read_rows(PREFIX + ".csv", int_keys=("disks", "ranks")), PREFIX + ".png")
    text = report(PREFIX)
    with open(PREFIX + ".md", "w") as f:
        f.write(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
