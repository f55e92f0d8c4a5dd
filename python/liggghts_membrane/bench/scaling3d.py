#!/usr/bin/env python3
"""How fix membrane3d's cost grows with the sample and the rank count: one command,

    /usr/bin/python3 bench/scaling3d.py            (the full table: see bench/scaling3d.md)
    /usr/bin/python3 bench/scaling3d.py --quick    (the two smallest sizes: minutes)

writes bench/scaling3d.csv (one row per size, rank count and lateral boundary) and
bench/scaling3d.md (the table and the parallel-efficiency model); the runs are kept in
out/bench/scaling3d/ and reused while their inputs are the same.

1. The cuboid sample of examples/triaxial (in.cuboid_prepare, seed 86028121: 3 981
   spheres, 36 mm square, prepared once on 1 rank) tiled nx x ny x nz times (--tiles;
   tiles side by side one wall box apart, layers one platen height apart) and settled
   --nsettle steps with its upper platen and four side walls servo-controlled at p
   (bench/in.scaling3d_sample); 1x1x1 is the prepared sample itself.
2. At each size and rank count, bench/in.membrane3d_cuboid_cost (processors * * 1)
   with each lateral boundary in its own process: the four servo walls, and fix
   membrane3d placed only (every 1e8: one detection before the timed steps), every
   200, every 50, every auto. --nhold steps held (the membrane every 50), then --repeat
   timed runs of --nsteps / tiles steps (at least --min-steps), the platen still; each
   boundary in --rounds processes, the boundaries in turn; the fastest run counts. Measured: wall time per step (LIGGGHTS' Loop time) and rank 0's
   CPU time per step (bench/cpu_ticks.sh), the fix's own time, its detections and their
   time (slowest rank), the bytes each rank received from the fix per step and per
   detection (its membrane3d_traffic line), the time of the first detection (from all
   spheres), the peak resident memory of each rank (a wrapper around each rank), the
   ghosts per rank.
3. The model (bench/scaling.py's efficiency()): parallel efficiency at P = 16, 64, 256
   for --model-spheres spheres, the walls' work divided over P and the membrane's
   work split into a part that divides and one that does not (from 1 and 2 ranks).

`--from-csv` makes the report again from scaling3d.csv and scaling3d.json alone.
"""
import argparse
import math
import os
import re
import sys
import time

from liggghts_membrane import readers
from liggghts_membrane.bench import common
from liggghts_membrane.bench.scaling import NETWORKS, efficiency, loops, mpi_run, read_walls

PREFIX = os.path.join(common.HERE, "scaling3d")
RUNS = os.path.join(common.ROOT, "out", "bench", "scaling3d")
EXAMPLE = os.path.join(common.ROOT, "examples", "triaxial")
COST_SCRIPT = os.path.join(common.HERE, "in.membrane3d_cuboid_cost")
TILE_SCRIPT = os.path.join(common.HERE, "in.scaling3d_sample")
CPU_SCRIPT = os.path.join(common.HERE, "cpu_ticks.sh")
SEED = 86028121
NEVER = 100000000    # every NEVER: the membrane placed only
# (name, boundary, every) of each timed process
CASES = [("walls", "walls", 1), ("placed", "membrane", NEVER), ("every200", "membrane", 200),
         ("every50", "membrane", 50), ("auto", "membrane", "auto")]
MEMBRANE_CASES = [c[0] for c in CASES[1:]]
CASE_TITLES = {"placed": "placed only", "every200": "every 200", "every50": "every 50",
               "auto": "every auto"}
DEFAULT_TILES = "1x1x1,2x2x1,2x2x2,4x4x2,8x8x2"
CSV_KEYS = ["tiles", "spheres", "ranks", "case", "every", "steps", "wall_ms", "cpu_ms",
            "wall_vs_walls_pct", "cpu_vs_walls_pct", "membrane_spheres", "detections_per_1000",
            "detection_ms", "first_detection_ms", "fix_ms_per_step", "kb_per_step",
            "kb_per_detection", "peak_mb_per_rank", "extra_mb_per_rank", "ghosts_per_rank",
            "contacts_per_sphere", "lx_m", "ly_m", "h_m", "run_s"]
HALO_MESSAGES_3D = 6          # a sub-domain of a 3D grid exchanges with 6 neighbours
MEMBRANE_COLLECTIVES_3D = 3   # fix membrane3d per step: detection due, count and data allgathers


def tiles_list(text):
    """'1x1x1,2x2x1' -> [(1, 1, 1), (2, 2, 1)]."""
    out = []
    for word in text.split(","):
        if word.strip():
            t = tuple(int(v) for v in word.strip().lower().split("x"))
            if len(t) != 3 or min(t) < 1:
                raise argparse.ArgumentTypeError(f"tiles {word!r}: NXxNYxNZ, each at least 1")
            out.append(t)
    return out


def tag(t):
    return "x".join(str(v) for v in t)


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--tiles", type=tiles_list, default=tiles_list(DEFAULT_TILES),
                   help=f"the sizes, nx x ny x nz tiles of the cuboid sample (default {DEFAULT_TILES}: "
                        "4 k, 16 k, 32 k, 127 k, 510 k spheres)")
    p.add_argument("--quick", action="store_true", help="the two smallest sizes only")
    p.add_argument("--ranks", type=common.ints, default=[1, 2])
    p.add_argument("--nsettle", type=int, default=3000, help="settling steps of a tiled sample")
    p.add_argument("--nhold", type=int, default=1000,
                   help="steps held before the timed runs at 1 tile; / tiles above, at least --min-steps")
    p.add_argument("--nsteps", type=int, default=1000,
                   help="steps per timed run at 1 tile; / tiles above, at least --min-steps")
    p.add_argument("--min-steps", type=int, default=100)
    p.add_argument("--repeat", type=int, default=1, help="timed runs per process (the fastest counts)")
    p.add_argument("--rounds", type=int, default=2,
                   help="processes of each boundary, the boundaries in turn (the fastest run counts)")
    p.add_argument("--model-spheres", type=float, default=1e6)
    p.add_argument("--prefix", default=PREFIX, help="the report's files PREFIX.csv, .json, .md")
    p.add_argument("--from-csv", action="store_true")
    args = p.parse_args(argv)
    if args.quick:
        args.tiles = sorted(args.tiles, key=lambda t: t[0] * t[1] * t[2])[:2]
    return args


def steps_for(tiles, n, least):
    """n steps at one tile, divided by the tile count, at least `least`."""
    return max(least, n // (tiles[0] * tiles[1] * tiles[2]))


# ----------------------------------------------------------------------------- the samples
def base_sample():
    """The prepared cuboid sample (in.cuboid_prepare, 1 rank, kept): its prefix."""
    folder = os.path.join(RUNS, "base")
    prefix = os.path.join(folder, "cuboid")
    mpi_run(1, os.path.join(EXAMPLE, "in.cuboid_prepare"), folder, "prepare",
            {"seed": SEED, "out": prefix}, timed=False)
    return prefix


def tile_data(atoms, walls, tiles, W, out_data, out_walls):
    """The spheres `atoms` (read_data_atoms) repeated nx x ny x nz times about the
    z axis, one wall box apart in x and y and one platen height (top0) apart in z; the
    walls file of the tiled box (top0 xlo0 xhi0 ylo0 yhi0); the box large enough for
    cuboid_walls.inc's meshes of size W. Returns the sphere count."""
    nx, ny, nz = tiles
    lx, ly, h = walls["xhi0"] - walls["xlo0"], walls["yhi0"] - walls["ylo0"], walls["top0"]
    tiled = dict(top0=nz * h, xlo0=walls["xlo0"] - (nx - 1) / 2 * lx, xhi0=walls["xhi0"] + (nx - 1) / 2 * lx,
                 ylo0=walls["ylo0"] - (ny - 1) / 2 * ly, yhi0=walls["yhi0"] + (ny - 1) / 2 * ly)
    n = len(atoms["id"])
    zhi = max(2.5 * W, nz * h) + 0.01
    with open(out_data, "w") as f:
        f.write(f"LIGGGHTS data: {n} spheres tiled {tag(tiles)} by bench/scaling3d.py\n\n")
        f.write(f"{n * nx * ny * nz} atoms\n2 atom types\n\n")
        f.write("%.12g %.12g xlo xhi\n%.12g %.12g ylo yhi\n" % (-1.6 * W, 1.6 * W, -1.6 * W, 1.6 * W))
        f.write("%.12g %.12g zlo zhi\n\nAtoms\n\n" % (-0.002, zhi))
        k = 0
        for i in range(nx):
            for j in range(ny):
                for m in range(nz):
                    dx, dy, dz = (i - (nx - 1) / 2) * lx, (j - (ny - 1) / 2) * ly, m * h
                    for a in range(n):
                        k += 1
                        f.write("%d %d %.12g %.12g %.12g %.12g %.12g\n" % (
                            k, atoms["type"][a], atoms["diameter"][a], atoms["density"][a],
                            atoms["x"][a] + dx, atoms["y"][a] + dy, atoms["z"][a] + dz))
    with open(out_walls, "w") as f:
        for key, v in tiled.items():
            f.write("variable %s equal %.17g\n" % (key, v))
    return k


def tiled_sample(base, tiles, W, nsettle, np_):
    """(prefix of the sample tiled `tiles` and settled, spheres, W of its meshes)."""
    base_data = os.path.join(RUNS, "base", "cuboid.data")
    mpi_run(1, TILE_SCRIPT, os.path.join(RUNS, "base"), "export",
            {"export": 1, "restart": base + ".restart", "data": base_data}, timed=False, cwd=EXAMPLE)
    atoms = readers.read_data_atoms(base_data)
    if tiles == (1, 1, 1):
        return base, len(atoms["id"]), W
    folder = os.path.join(RUNS, "tiles" + tag(tiles))
    os.makedirs(folder, exist_ok=True)
    w = W * max(tiles[0], tiles[1])
    data, walls = os.path.join(folder, "tiled.data"), os.path.join(folder, "tiled.walls")
    n = tile_data(atoms, read_walls(base + ".walls"), tiles, w, data, walls)
    prefix = os.path.join(folder, "tiled")
    mpi_run(np_, TILE_SCRIPT, folder, "settle", {"data": data, "walls": walls, "W": w, "out": prefix,
                                                  "nsettle": nsettle}, timed=False, cwd=EXAMPLE)
    return prefix, n, w


# ----------------------------------------------------------------------------- one run's figures
CPU = re.compile(r"^BENCH_CPU (start|end)(\d+) (\d+) (\d+) (\d+)", re.M)
GHOSTS = re.compile(r"^Nghost:\s+(\S+) ave", re.M)
CONTACTS = re.compile(r"^BENCH contacts per sphere (\S+)", re.M)
MEMBRANE = re.compile(r"^BENCH membrane spheres (\S+)", re.M)


def cpu_seconds(text):
    """Rank 0's CPU seconds of each timed run, in order, from the BENCH_CPU lines of
    bench/cpu_ticks.sh around it (startK / endK: user and system ticks, ticks a second)."""
    start, out = {}, {}
    for m in CPU.finditer(text):
        ticks = int(m.group(3)) + int(m.group(4))
        if m.group(1) == "start":
            start[m.group(2)] = ticks
        elif m.group(2) in start:
            out[int(m.group(2))] = (ticks - start[m.group(2)]) / int(m.group(5))
    return [out[k] for k in sorted(out)]


def run_figures(text, repeat, membrane):
    """The figures of one process of in.membrane3d_cuboid_cost: the fastest of its
    `repeat` timed runs (the last Loop times; with the membrane, the last `repeat`
    membrane3d_traffic lines, the one before them the run 0 of its first detection)."""
    timed = loops(text)[-repeat:]
    if len(timed) < repeat:
        raise ValueError(f"{len(timed)} timed runs in the output, {repeat} expected")
    steps = timed[0][1]
    walls = [t for t, _ in timed]
    cpu = cpu_seconds(text)[-repeat:]
    ghosts = GHOSTS.findall(text)
    contacts = CONTACTS.findall(text)
    row = dict(steps=steps, wall_ms=1e3 * min(walls) / steps,
               cpu_ms=1e3 * min(cpu) / steps if len(cpu) == repeat else float("nan"),
               ghosts_per_rank=float(ghosts[-1]) if ghosts else 0.0,
               contacts_per_sphere=float(contacts[-1]) if contacts else float("nan"))
    if not membrane:
        return row
    lines = readers.key_value_lines(text, "membrane3d_traffic")
    if len(lines) < repeat + 1:
        raise ValueError(f"{len(lines)} membrane3d_traffic lines, {repeat + 1} expected")
    first, runs = lines[-repeat - 1], lines[-repeat:]
    fastest = runs[walls.index(min(walls))]
    dets = sum(r["detections"] for r in runs)
    with_detections = [r for r in runs if r["detections"] > 0]
    row.update(
        membrane_spheres=float(MEMBRANE.findall(text)[-1]) if MEMBRANE.findall(text) else float("nan"),
        detections_per_1000=1000.0 * dets / sum(r["steps"] for r in runs),
        detection_ms=min(1e3 * r["detection_seconds"] / r["detections"] for r in with_detections)
        if with_detections else float("nan"),
        first_detection_ms=1e3 * first["detection_seconds"] / max(first["detections"], 1),
        fix_ms_per_step=min(1e3 * r["fix_seconds"] / r["steps"] for r in runs),
        kb_per_step=fastest["kb_per_step"],
        kb_per_detection=max(r["kb_per_detection"] for r in runs) if dets else first["kb_per_detection"])
    return row


def fastest(rounds):
    """The figures of several processes of one case: the smallest of each time, the
    largest memory, the mean seconds of a process, the rest of the fastest by wall time."""
    out = dict(min(rounds, key=lambda r: r["wall_ms"]))
    for key in ("cpu_ms", "detection_ms", "first_detection_ms", "fix_ms_per_step"):
        values = [r[key] for r in rounds if key in r and r[key] == r[key]]
        if values:
            out[key] = min(values)
    out["peak_mb_per_rank"] = max(r["peak_mb_per_rank"] for r in rounds)
    out["run_s"] = sum(r["run_s"] for r in rounds) / len(rounds)
    return out


def timed_point(sample, spheres, W, tiles, np_, args):
    """The five lateral boundaries on one sample and rank count: five CSV rows."""
    folder = os.path.join(RUNS, f"tiles{tag(tiles)}_np{np_}")
    nsteps = steps_for(tiles, args.nsteps, args.min_steps)
    base = {"sample": sample, "W": W, "nhold": steps_for(tiles, args.nhold, args.min_steps),
            "nsteps": nsteps, "repeat": args.repeat, "pz": 1, "cpuscript": CPU_SCRIPT,
            "thermo": 100000}
    walls_file = read_walls(sample + ".walls")
    size = dict(lx_m=walls_file["xhi0"] - walls_file["xlo0"], ly_m=walls_file["yhi0"] - walls_file["ylo0"],
                h_m=walls_file["top0"])
    rounds = {name: [] for name, _, _ in CASES}
    # the cases in turn, round after round: this machine's speed drifts from one
    # process to the next
    for k in range(args.rounds):
        for name, boundary, every in CASES:
            text, rss, wall = mpi_run(np_, COST_SCRIPT, folder, f"{name}_round{k + 1}",
                                      dict(base, boundary=boundary, timedevery=every), cwd=EXAMPLE)
            figures = run_figures(text, args.repeat, boundary == "membrane")
            rounds[name].append(dict(figures, peak_mb_per_rank=max(rss) if rss else float("nan"), run_s=wall))
    rows = [dict(tiles=tag(tiles), spheres=spheres, ranks=np_, case=name, every=every, **size,
                 **fastest(rounds[name])) for name, _, every in CASES]
    walls = rows[0]
    for r in rows:
        r["wall_vs_walls_pct"] = 100 * (r["wall_ms"] / walls["wall_ms"] - 1)
        r["cpu_vs_walls_pct"] = 100 * (r["cpu_ms"] / walls["cpu_ms"] - 1)
        r["extra_mb_per_rank"] = r["peak_mb_per_rank"] - walls["peak_mb_per_rank"]
    return rows


# ----------------------------------------------------------------------------- the model
def power_law(points, x):
    """y at x from the last two (x, y) points (ascending x) on y = c x^k, and k; one
    point: k = 1 (proportional)."""
    (x1, y1), (x2, y2) = (points[-2], points[-1]) if len(points) > 1 else ((None, None), points[-1])
    k = 1.0 if x1 is None or x1 == x2 or y1 <= 0 or y2 <= 0 else math.log(y2 / y1) / math.log(x2 / x1)
    return y2 * (x / x2) ** k, k


def amdahl(t1, t2):
    """(s, q) of t(P) = s + q / P through t(1) = t1 and t(2) = t2, neither negative: the
    work that every rank repeats and the work that the ranks divide."""
    s = min(max(2 * t2 - t1, 0.0), t1)
    return s, t1 - s


def step_ms(r):
    """A row's time per step: rank 0's CPU time where measured (robust when others load
    the machine), else the wall time."""
    return r["cpu_ms"] if r["cpu_ms"] == r["cpu_ms"] else r["wall_ms"]


def model_inputs(rows, n_model):
    """What the model takes from the measured rows, extrapolated to n_model spheres:
    the walls' work of a step on one rank [s], the volume per sphere [m^3], the ghosts
    per m^2 of a cut between two ranks, and per membrane case (s, q) of its own time per
    step [s] and the bytes a rank receives per step (detections included); with the
    exponents of each fit. None when the rows lack 1 and 2 ranks."""
    sizes = sorted({r["spheres"] for r in rows if r["ranks"] == 1} & {r["spheres"] for r in rows if r["ranks"] == 2})
    if not sizes:
        return None
    at = {(r["spheres"], r["ranks"], r["case"]): r for r in rows}
    big = sizes[-1]
    walls1 = [(n, step_ms(at[n, 1, "walls"]) / n) for n in sizes]
    w2 = at[big, 2, "walls"]
    out = dict(spheres=big, sizes=len(sizes),
               work_s=1e-3 * walls1[-1][1] * n_model,
               volume_per_sphere=w2["lx_m"] * w2["ly_m"] * w2["h_m"] / big,
               ghosts_per_m2=w2["ghosts_per_rank"] / (w2["ly_m"] * w2["h_m"]), cases={})
    for case in MEMBRANE_CASES:
        # the split at the largest size, both parts grown as the time on 1 rank grows
        # (the 1-rank times are the steadier on a shared machine)
        t1, k = power_law([(n, 1e-3 * at[n, 1, case]["fix_ms_per_step"]) for n in sizes], n_model)
        s, q = amdahl(1e-3 * at[big, 1, case]["fix_ms_per_step"], 1e-3 * at[big, 2, case]["fix_ms_per_step"])
        r2 = at[big, 2, case]
        kb_step, k_step = power_law([(n, at[n, 2, case]["kb_per_step"]) for n in sizes], n_model)
        kb_det, k_det = power_law([(n, at[n, 2, case]["kb_per_detection"]) for n in sizes], n_model)
        share = s / (s + q) if s + q > 0 else 1.0
        out["cases"][case] = dict(s=t1 * share, q=t1 * (1 - share), k=k, s_big=s, q_big=q,
                                  k_step=k_step, k_det=k_det,
                                  bytes=1e3 * kb_step + r2["detections_per_1000"] / 1000 * 1e3 * kb_det)
    return out


def model(rows, n_model):
    """Parallel efficiency at P = 16, 64, 256 for n_model spheres with the walls and with
    each membrane (bench/scaling.py's efficiency()). Returns (table lines, assumptions)."""
    m = model_inputs(rows, n_model)
    if m is None:
        return [], "The model needs runs on 1 and 2 ranks of one size."
    lines = ["| network | P | spheres per rank | compute / halo / collectives [ms] | walls | "
             + " | ".join(CASE_TITLES[c] for c in MEMBRANE_CASES) + " |", "|" + "---|" * (5 + len(MEMBRANE_CASES))]
    for net, network in NETWORKS.items():
        for p in (16, 64, 256):
            a = (n_model * m["volume_per_sphere"] / p) ** (1 / 3)   # a cube's side
            ghosts = 6 * a * a * m["ghosts_per_m2"]
            cells = []
            for case in MEMBRANE_CASES:
                c = m["cases"][case]
                t_calc, t_halo, t_coll, t_mem, e_walls, e_mem = efficiency(
                    p, network, m["work_s"], ghosts, HALO_MESSAGES_3D, c["s"] + c["q"] / p, c["bytes"],
                    MEMBRANE_COLLECTIVES_3D)
                cells.append(f"{100 * e_mem:.0f} % ({1e3 * t_mem:.3g} ms)")
            lines.append(f"| {net} | {p} | {n_model / p:.0f} | {1e3 * t_calc:.3g} / {1e3 * t_halo:.2g} / "
                         f"{1e3 * t_coll:.2g} | {100 * e_walls:.0f} % | " + " | ".join(cells) + " |")
    fits = "; ".join(f"{CASE_TITLES[c]}: s {1e3 * v['s']:.3g} ms, q {1e3 * v['q']:.3g} ms ({1e3 * v['s_big']:.3g} "
                     f"and {1e3 * v['q_big']:.3g} ms measured, x N^{v['k']:.2f}), {v['bytes'] / 1e3:.3g} kB per "
                     f"step (N^{v['k_step']:.2f}, per detection N^{v['k_det']:.2f})" for c, v in m["cases"].items())
    text = (f"Assumed: {n_model:.3g} spheres; the walls' work of a step, {1e3 * m['work_s'] / n_model * 1e3:.3g} "
            f"us per sphere-step (rank 0's CPU time, 1 rank, {m['spheres']} spheres), divides evenly over P "
            f"ranks; each rank a cube of the sample ({m['volume_per_sphere'] * 1e9:.3g} mm^3 per sphere) with "
            f"{HALO_MESSAGES_3D} neighbours and {m['ghosts_per_m2']:.3g} ghosts per m^2 of face (measured "
            "between 2 ranks), 72 bytes each per step; bench/scaling.py's collectives; each membrane "
            f"adds {MEMBRANE_COLLECTIVES_3D} collectives and its own time t(P) = s + q / P, s the part every "
            "rank repeats and q the part the ranks divide (from its time on 1 and 2 ranks at the largest "
            "size, both grown as its time on 1 rank grows), and the bytes a rank receives (2 ranks, "
            "taken as independent of P), each extrapolated from the "
            f"{'two largest sizes' if m['sizes'] > 1 else 'largest size (proportional to N)'} as a power "
            f"of N: {fits}. In parentheses: the membrane's time per step at P. Not modelled: load "
            "imbalance, contention, the meshes' own parallel bookkeeping, I/O.")
    return lines, text


def estimate_minutes(rows, tiles, args):
    """Minutes of a run of bench/scaling3d.py over `tiles` with the same options, from
    the measured rows: each process's steps at the wall time per step of its case and
    rank count (the hold at every 50's) and its other seconds (start, restart, first
    detection: the process's seconds less its steps') in proportion to N, each
    extrapolated as a power of N over the two largest sizes; the settling on the most
    ranks at the walls' time per step."""
    base_n = min(r["spheres"] for r in rows)
    most = max(r["ranks"] for r in rows)
    total = 0.0
    for np_ in sorted({r["ranks"] for r in rows}):
        sel = sorted((r for r in rows if r["ranks"] == np_), key=lambda r: r["spheres"])
        ms = {c: [(r["spheres"], r["wall_ms"] / 1e3) for r in sel if r["case"] == c] for c, _, _ in CASES}
        for case, _, _ in CASES:
            hold = ms["walls" if case == "walls" else "every50"]
            over = []
            for r in (r for r in sel if r["case"] == case):
                steps = steps_for(tiles_list(r["tiles"])[0], args.nhold, args.min_steps)
                over.append((r["spheres"], max(0.0, r["run_s"] - steps * dict(hold)[r["spheres"]]
                                                - args.repeat * r["steps"] * dict(ms[case])[r["spheres"]])))
            for t in tiles:
                n = base_n * t[0] * t[1] * t[2]
                step = power_law(ms[case], n)[0]
                total += args.rounds * (steps_for(t, args.nhold, args.min_steps) * power_law(hold, n)[0]
                                        + args.repeat * steps_for(t, args.nsteps, args.min_steps) * step
                                        + over[-1][1] * n / over[-1][0])
                if case == "walls" and np_ == most and t != (1, 1, 1):
                    total += args.nsettle * step
    return total / 60


# ----------------------------------------------------------------------------- the report
def ratio(r, walls):
    """'x1.05 / x1.03': a membrane's time per step over the walls', wall and CPU time."""
    return (common.fmt(r["wall_ms"] / walls["wall_ms"], "×{:.2f}") + " / "
            + common.fmt(r["cpu_ms"] / walls["cpu_ms"], "×{:.2f}"))


def table_rows(rows):
    """One line per size and rank count: {key: cell} for the Markdown table."""
    out = []
    for key in sorted({(r["spheres"], r["ranks"]) for r in rows}):
        at = {r["case"]: r for r in rows if (r["spheres"], r["ranks"]) == key}
        if "walls" not in at:
            continue
        w = at["walls"]
        line = dict(tiles=w["tiles"], spheres=w["spheres"], ranks=w["ranks"],
                    walls=common.fmt(w["wall_ms"], "{:.3g}") + " / " + common.fmt(w["cpu_ms"], "{:.3g}"))
        for c in MEMBRANE_CASES:
            line[c] = ratio(at[c], w) if c in at else ""
        e50, auto = at.get("every50", {}), at.get("auto", {})
        line["membrane"] = common.fmt(e50.get("membrane_spheres", ""), "{:.0f}")
        line["auto_rate"] = common.fmt(auto.get("detections_per_1000", ""), "{:.0f}")
        line["detection"] = (common.fmt(e50.get("detection_ms", ""), "{:.3g}") + " / "
                             + common.fmt(e50.get("first_detection_ms", ""), "{:.3g}"))
        line["kb"] = (common.fmt(e50.get("kb_per_step", ""), "{:.3g}") + " / "
                      + common.fmt(e50.get("kb_per_detection", ""), "{:.3g}"))
        most = max((at[c] for c in MEMBRANE_CASES if c in at), key=lambda r: r["peak_mb_per_rank"], default=None)
        line["mb"] = (common.fmt(w["peak_mb_per_rank"], "{:.0f}") + " / " + common.fmt(
            most["peak_mb_per_rank"], "{:.0f}") + " (" + common.fmt(most["extra_mb_per_rank"], "{:+.0f}") + ")"
            if most else "")
        out.append(line)
    return out


def report(prefix):
    rows = common.read_rows(prefix + ".csv", int_keys=("spheres", "ranks", "steps"), text_keys=("tiles", "case"))
    ctx = common.read_context(prefix + ".json")
    cols = [("tiles", "tiles"), ("spheres", "spheres"), ("ranks", "ranks"),
            ("on the membrane", "membrane"), ("walls ms/step (wall / CPU)", "walls")]
    cols += [(CASE_TITLES[c] + " (wall / CPU)", c) for c in MEMBRANE_CASES]
    cols += [("every auto: detections / 1000 steps", "auto_rate"),
             ("one detection ms (every 50 / first, from all)", "detection"),
             ("kB per rank per step / per detection", "kb"),
             ("peak MB per rank: walls / membrane (difference)", "mb")]
    out = ["# fix membrane3d: scaling with the sample and the rank count", "",
           f"`{ctx['command']}` ({ctx['minutes']:.0f} min on {ctx['cores']} cores). "
           f"The cuboid sample of examples/triaxial (seed {SEED}) tiled nx x ny x nz "
           f"(tiled samples settled {ctx['nsettle']} steps); each lateral boundary in its own process: "
           f"{ctx['nhold']} steps held, then {ctx['repeat']} timed run(s) of {ctx['nsteps']} steps, both "
           f"divided by the tiles (at least {ctx['min_steps']}), the platen still; "
           f"{ctx.get('rounds', 1)} process(es) per boundary, the boundaries in turn; the fastest "
           "timed run counts.", "",
           common.markdown_table(table_rows(rows), [(title, (lambda k: lambda r: r[k])(k)) for title, k in cols]),
           "",
           "How to read it: the walls' column is the time per step of the four servo-controlled side "
           "walls (wall clock, LIGGGHTS' Loop time / rank 0's CPU time, bench/cpu_ticks.sh); each "
           "membrane's column is its time per step over the walls' (x1.10: +10 %), by wall and by "
           "CPU time (the CPU time is the steadier while other processes load the machine). "
           "*placed only* detects once before the timed steps (every 1e8) and then places the "
           "membrane found then on each step's spheres; *every auto* detects when the membrane "
           "can have changed (its detections per 1000 steps are given). One detection: the "
           "fix's detection time per detection in the every-50 runs (slowest rank), and the "
           "first detection of the timed fix (from all spheres; its run 0). kB: what each rank "
           "received in the fix's gathers per step outside detections and per detection (the fix's "
           "`membrane3d_traffic` line, doc/fix_membrane3d.md). Peak MB: the largest rank's resident "
           "set over the whole process with the walls and the largest with a membrane (the walls' side meshes count on their side).",
           "", "Targets of issue 34: every auto <= x1.10 at 4 k and >= 32 k spheres on 1 and 2 "
           "ranks; a detection on 2 ranks <= 0.6 x its time on 1 rank and flat per membrane sphere "
           "from 4 k to >= 500 k; <= 2 MB per 10 k membrane spheres per rank beyond the walls'.", ""]
    # what the run step cannot know (the code measured, the machine's load): PREFIX.json's note
    for key in ("estimate", "note"):
        if ctx.get(key):
            out += [ctx[key], ""]
    lines, text = model(rows, ctx["model_spheres"])
    out += ["## Beyond two cores: a model", ""] + lines + ["", text, ""]
    return "\n".join(out)


def sweep(args, t0):
    """Run the table (the runs kept), write PREFIX.csv, .json and .md: the report."""
    W = common.script_number(os.path.join(EXAMPLE, "in.cuboid_prepare"), "W")
    common.log("the cuboid sample (in.cuboid_prepare, 1 rank)")
    base = base_sample()
    rows = []
    for tiles in args.tiles:
        common.log(f"tiles {tag(tiles)}: tile and settle")
        sample, spheres, w = tiled_sample(base, tiles, W, args.nsettle, max(args.ranks))
        for np_ in args.ranks:
            common.log(f"tiles {tag(tiles)}, {spheres} spheres, {np_} rank(s)")
            rows += timed_point(sample, spheres, w, tiles, np_, args)
    common.write_rows(args.prefix + ".csv", rows, CSV_KEYS)
    full = tiles_list(DEFAULT_TILES)
    estimate = ""
    if args.tiles != full:
        estimate = (f"The full table (`bench/scaling3d.py`, tiles {DEFAULT_TILES}) would take about "
                    f"{estimate_minutes(rows, full, args):.0f} min on this machine (estimate_minutes(): "
                    "these runs' times per step and per process extrapolated as powers of the sphere count).")
    common.write_context(args.prefix + ".json", dict(
        command="bench/scaling3d.py " + " ".join(args.argv), minutes=(time.time() - t0) / 60,
        cores=os.cpu_count(), nsettle=args.nsettle, nhold=args.nhold, nsteps=args.nsteps,
        min_steps=args.min_steps, repeat=args.repeat, rounds=args.rounds, model_spheres=args.model_spheres,
        estimate=estimate))
    text = report(args.prefix)
    with open(args.prefix + ".md", "w") as f:
        f.write(text + "\n")
    return text


def main(argv):
    return common.sweep_main(argv, parse_args, report, sweep)
