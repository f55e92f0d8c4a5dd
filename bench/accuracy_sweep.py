#!/usr/bin/python3
"""Run time against error of the 2D DEM biaxial test (examples/biaxial).

    /usr/bin/python3 bench/accuracy_sweep.py [--scale 0.5] [--strain 0.05] [--jobs 2]
        [--rates 0.00125,0.0025,0.005,0.01,0.02,0.04,0.08] [--everys auto,1,2,5,10,50]
        [--dts 1e-4,5e-5,2e-4,4e-4,8e-4] [--seeds 12345,54321] [--workdir out/accuracy_sweep]
        [--dampings viscous:500,viscous:100,viscous:2000,viscous:5000,local:0.1,local:0.3,local:0.7]
        [--damping-rates R1,R2] [--ranks 1,2,4] [--sweeps rate,every,dt,seed[,damping,ranks]]

One command: generates and prepares (examples/biaxial/in.prepare) one sample per
seed, shears it (in.shear_rigid / in.shear_membrane) on ONE MPI rank per run (the
ranks sweep excepted), at most --jobs runs at a time, and compares every run with
the reference run of its sweep:

  rate     both cases, -var rate R; reference = the slowest rate of --rates
  every    membrane, -var every auto|N at --default-rate; reference = the smallest N (1:
           a detection every step); auto must equal it exactly (same chains every step)
  dt       rigid, -var dt DT at --default-rate; reference = --default-dt
  seed     the reference (slowest rate) of both cases repeated on the second seed:
           the sample-to-sample scatter; an error below it is noise
  damping  both cases at --default-rate (and at any other --damping-rates) with each
           damping of --dampings: viscous:G = -var damping 0 -var gvisc G (fix viscous,
           N s/m; in.shear_membrane's settling drag uses gvisc too), local:A = -var
           damping 1 -var adamp A (fix damping/local alpha A). Reference = the case
           reference of the rate sweep (slowest rate, the scripts' default damping):
           damping changes the physics at a given rate, the question is which damping
           comes closest to the quasi-static answer. The scripts' default damping
           (read from their 'variable damping/gvisc/adamp index' lines: viscous:500)
           is the very run of the rate sweep at that rate (same name, reused).
  ranks    both cases at --default-rate (default dt, every and damping, first seed) on
           each of --ranks MPI ranks (mpirun --allow-run-as-root --oversubscribe -np N;
           1 rank = the same run as the rate sweep's at that rate, without mpirun);
           reference = the 1-rank run.
           Wall time, speed-up and parallel efficiency against 1 rank; the errors show
           how far the trajectories of a chaotic granular system drift apart when only
           the order of floating-point sums changes. An N-rank run takes min(N, --jobs)
           of the --jobs slots (with --jobs 2 it runs alone, after the 1-rank runs);
           N > os.cpu_count() is marked oversubscribed. Speed-ups need an otherwise
           idle machine.
The last two are not in the default --sweeps (rate,every,dt,seed): add them with
--sweeps rate,every,dt,seed,damping,ranks.

Errors over 0..final strain on a common eps_11 grid: RMS and max difference of
s1/s3 and eps_v; peak s1/s3 and its strain, E, phi, psi (scripts/biaxial/curves.py);
RMS difference of the fabric a, C_n and mean lambda (gsi). Wall time = the sum of
the 'Loop time' lines of the run's log; CPU time = user+sys of the process and, for
an N-rank run, of all its ranks (mpirun reaps them). The output interval is set to a fixed
strain (--dstrain-out, the examples' 500 steps at rate 0.01, dt 1e-4), so every run
has the same curve resolution and the same number of fabric evaluations.

Writes bench/accuracy_sweep.csv (raw numbers), bench/accuracy_sweep.png (wall
time vs RMS error of s1/s3 with the scatter level and the Pareto front) and
bench/accuracy_sweep.md (the table, the recommendations and, with the ranks sweep, the
speed-up and efficiency per rank count), and prints the report. Runs already finished
in --workdir (same parameters) are reused: the command can be re-run to resume.
The executable is copied into --workdir at the start, so a rebuild by someone
else does not change it in the middle of the sweep.
"""
import argparse
import concurrent.futures as cf
import csv
import hashlib
import json
import math
import os
import re
import shutil
import subprocess
import sys
import threading
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "scripts"))

from biaxial import curves, readers  # noqa: E402
from biaxial.curves import measured  # noqa: E402

EXAMPLES = os.path.join(ROOT, "examples", "biaxial")
PUBLISHED_RATE = 0.02 / 60.0          # 2 %/min
LOCK = threading.Lock()


def log(msg):
    with LOCK:
        print(msg, flush=True)


def floats(text):
    return [float(w) for w in text.split(",") if w.strip()]


def everys(text):
    """'auto,1,2' -> ['auto', 1, 2]"""
    return [w.strip() if w.strip() == "auto" else int(w) for w in text.split(",") if w.strip()]


def every_key(e):
    """auto first, then the intervals in order"""
    return (0, 0) if e == "auto" else (1, int(e))


def ints(text):
    return [int(w) for w in text.split(",") if w.strip()]


def damping(text):
    """'viscous:G' or 'local:A' -> ('viscous', G) / ('local', A) (the canonical form)."""
    kind, _, value = text.strip().partition(":")
    kind = {"viscous": "viscous", "visc": "viscous", "local": "local"}.get(kind.strip().lower())
    try:
        x = float(value)
    except ValueError:
        x = float("nan")
    if kind is None or not (x >= 0 and math.isfinite(x)):
        raise argparse.ArgumentTypeError(f"damping '{text}': expected viscous:G or local:A")
    if kind == "local" and x >= 1:
        raise argparse.ArgumentTypeError(f"damping '{text}': local damping alpha must be < 1")
    return (kind, x)


def dampings(text):
    out = []
    for w in text.split(","):
        if w.strip() and damping(w) not in out:
            out.append(damping(w))
    return out


def damping_spec(d):
    """('viscous', 500.0) -> 'viscous:500' (the --dampings form; CSV, meta.json)."""
    return f"{d[0]}:{tag(d[1])}"


def damping_text(d):
    """The setting as the table gives it."""
    return f"damping viscous {tag(d[1])} N·s/m" if d[0] == "viscous" else \
        f"damping local α {tag(d[1])}"


def damping_vars(d):
    """The -var overrides of in.shear_* for a damping."""
    if d[0] == "viscous":
        return ["-var", "damping", "0", "-var", "gvisc", repr(d[1])]
    return ["-var", "damping", "1", "-var", "adamp", repr(d[1])]


def script_damping(path):
    """The default damping of an input script, from its 'variable damping|gvisc|adamp
    index X' lines (in.shear_*: damping 0, gvisc 500 -> ('viscous', 500.0))."""
    v = {}
    for line in open(path, errors="replace"):
        m = re.match(r"\s*variable\s+(damping|gvisc|adamp)\s+index\s+(\S+)", line)
        if m:
            v.setdefault(m.group(1), m.group(2))
    try:
        if float(v.get("damping", 0)) > 0:
            return ("local", float(v["adamp"]))
        return ("viscous", float(v["gvisc"]))
    except (KeyError, ValueError):
        raise SystemExit(f"{path}: no 'variable damping/gvisc/adamp index' defaults found")


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scale", type=float, default=0.5,
                   help="sample size factor of generate_sample.py (0.5: ~2100 disks; 1: published)")
    p.add_argument("--strain", type=float, default=0.05, help="final axial strain (0.05)")
    p.add_argument("--rates", type=floats, default=floats("0.00125,0.0025,0.005,0.01,0.02,0.04,0.08"),
                   help="loading rates [1/s]; the slowest is the reference")
    p.add_argument("--everys", type=everys, default=everys("auto,1,2,5,10,50"),
                   help="membrane chain detection settings (auto or N); the smallest N is the "
                        "reference; the other sweeps use --default-every")
    p.add_argument("--default-every", default="auto",
                   help="membrane 'every' of all sweeps but the every sweep (the examples' default)")
    p.add_argument("--dts", type=floats, default=floats("1e-4,5e-5,2e-4,4e-4,8e-4"),
                   help="time steps of the rigid case (reference = --default-dt)")
    p.add_argument("--default-rate", type=float, default=0.01,
                   help="rate of the 'every' and 'dt' sweeps (the examples' default)")
    p.add_argument("--default-dt", type=float, default=1e-4)
    p.add_argument("--seeds", type=ints, default=ints("12345,54321"),
                   help="sample seeds: the first for all sweeps, the second for the scatter")
    p.add_argument("--scatter-rates", type=floats, default=floats("0.0025,0.01"),
                   help="extra rates at which the two seeds are also compared (the scatter at "
                        "the reference rate is the one used; these check that it does not "
                        "depend on the rate)")
    p.add_argument("--sweeps", default="rate,every,dt,seed",
                   help="which sweeps to run (comma list of rate, every, dt, seed, damping, "
                        "ranks; default rate,every,dt,seed)")
    p.add_argument("--dampings", type=dampings,
                   default=dampings("viscous:500,viscous:100,viscous:2000,viscous:5000,"
                                    "local:0.1,local:0.3,local:0.7"),
                   help="damping sweep: viscous:G (-var damping 0 -var gvisc G [N s/m]) or "
                        "local:A (-var damping 1 -var adamp A), comma list")
    p.add_argument("--damping-rates", type=floats, default=None,
                   help="rates of the damping sweep (default: --default-rate only)")
    p.add_argument("--ranks", type=ints, default=ints("1,2,4"),
                   help="MPI rank counts of the ranks sweep (1 is always added: the reference)")
    p.add_argument("--mpirun", default="mpirun",
                   help="MPI launcher of the ranks sweep, run as MPIRUN --allow-run-as-root "
                        "--oversubscribe -np N EXE ...")
    p.add_argument("--jobs", type=int, default=2,
                   help="job slots (2): 1-rank runs at a time; an N-rank run takes min(N, jobs)")
    p.add_argument("--dstrain-out", type=float, default=5e-4,
                   help="axial strain between output lines (5e-4)")
    p.add_argument("--grid", type=int, default=401, help="points of the common eps_11 grid")
    p.add_argument("--workdir", default=os.path.join(ROOT, "out", "accuracy_sweep"),
                   help="where the samples and runs go (out/ is git-ignored)")
    p.add_argument("--exe", default=os.path.join(ROOT, "build", "app", "liggghts-membrane"))
    p.add_argument("--prefix", default=os.path.join(HERE, "accuracy_sweep"),
                   help="output prefix: PREFIX.csv, PREFIX.png, PREFIX.md")
    p.add_argument("--time-axis", choices=("cpu", "wall"), default="cpu",
                   help="x axis of the plot and of the Pareto front: CPU time of the run "
                        "(user+sys; robust when others load the machine, default) or wall "
                        "time (the 'Loop time' sum); the table gives both")
    p.add_argument("--retry-failed", action="store_true", help="re-run runs recorded as failed")
    p.add_argument("--report-only", action="store_true", help="no runs: report what is there")
    a = p.parse_args(argv)
    if a.jobs < 1:
        p.error("--jobs >= 1")
    a.sweeps = [s.strip() for s in a.sweeps.split(",") if s.strip()]
    unknown = set(a.sweeps) - {"rate", "every", "dt", "seed", "damping", "ranks"}
    if unknown:
        p.error(f"unknown sweep(s) {', '.join(sorted(unknown))}")
    if a.damping_rates is None:
        a.damping_rates = [a.default_rate]
    if any(n < 1 for n in a.ranks):
        p.error("--ranks >= 1")
    a.ranks = sorted(set(a.ranks) | {1})
    return a


# ----------------------------------------------------------------------------- runs
def sha(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest()[:12]


def tag(x):
    return f"{x:g}"


class Run:
    """One shear run: parameters, files and (after it ran) its measurements.

    damping: ('viscous', G) or ('local', A); ranks: MPI ranks. The scripts' default
    damping and 1 rank leave the name and params as they were before these two
    parameters existed, so runs made then are reused."""

    def __init__(self, case, seed, rate, dt, every, args, damping=None, ranks=1):
        self.case, self.seed, self.rate, self.dt, self.every = case, seed, rate, dt, every
        self.damping = damping or args.default_damping[case]
        self.ranks = ranks
        self.nsteps = int(math.ceil(args.strain / (rate * dt)))
        self.nout = max(1, int(round(args.dstrain_out / (rate * dt))))
        self.ndump = 10 * self.nout
        self.default_damping = self.damping == args.default_damping[case]
        self.name = f"{case}_seed{seed}_rate{tag(rate)}_dt{tag(dt)}" + \
            (f"_every{every}" if case == "membrane" else "")
        self.params = dict(case=case, seed=seed, rate=rate, dt=dt, every=every,
                           strain=args.strain, scale=args.scale, nout=self.nout,
                           script_sha=args.script_sha[case], exe_sha=args.exe_sha)
        if not self.default_damping:
            self.name += ("_visc" if self.damping[0] == "viscous" else "_local") + tag(self.damping[1])
            self.params["damping"] = damping_spec(self.damping)
        if ranks != 1:
            self.name += f"_np{ranks}"
            self.params["ranks"] = ranks
        self.dir = os.path.join(args.rundir, self.name)
        self.out = os.path.join(self.dir, "shear.txt")
        self.script = args.scripts[case]
        self.meta = None
        self.table = None
        self.curves = None

    @property
    def key(self):
        return (self.case, self.seed, self.rate, self.dt, self.every, self.damping, self.ranks)

    def cost(self):
        return self.nsteps * (1.3 if self.case == "membrane" else 1.0)

    def slots(self, jobs):
        """Job slots taken: one per rank, at most all of them (then it runs alone)."""
        return min(self.ranks, jobs)


def run_command(cmd, cwd, screen, timeout):
    """(return code or 'timeout', wall [s], CPU time user+sys [s]) of one process."""
    t0 = time.time()
    with open(screen, "w") as f:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT,
                             env=dict(os.environ, OMP_NUM_THREADS="1"))
        timed_out = []
        timer = threading.Timer(timeout, lambda: (timed_out.append(1), p.kill()))
        timer.start()
        _, status, ru = os.wait4(p.pid, 0)     # per-child rusage: CPU time despite other load
        timer.cancel()
        p.returncode = rc = os.waitstatus_to_exitcode(status)
    return ("timeout" if timed_out else rc), time.time() - t0, ru.ru_utime + ru.ru_stime


def loop_times(logfile):
    """(sum of Loop times [s], sum of steps) over the log's runs."""
    tsum, nsum = 0.0, 0
    if os.path.exists(logfile):
        for line in open(logfile, errors="replace"):
            m = re.match(r"Loop time of ([-+.\deE]+) on (\d+) procs for (\d+) steps", line)
            if m:
                tsum += float(m.group(1))
                nsum += int(m.group(3))
    return tsum, nsum


def time_split(logfile):
    """Percent of the longest run's loop time in LIGGGHTS' categories (Pair, Neigh,
    Comm, Outpt, Other; fixes such as the moving meshes and fix membrane2d are in
    Other), or {} when the log is missing."""
    best, split, current, steps = -1, {}, None, -1
    if not os.path.exists(logfile):
        return {}
    for line in open(logfile, errors="replace"):
        m = re.match(r"Loop time of ([-+.\deE]+) on (\d+) procs for (\d+) steps", line)
        if m:
            steps = int(m.group(3))
            current = {} if steps > best else None
            if current is not None:
                best = steps
            continue
        m = re.match(r"(Pair|Neigh|Comm|Outpt|Other)\s+time \(%\) = \S+ \(([-+.\deE]+)\)", line)
        if m and current is not None:
            current[m.group(1)] = float(m.group(2))
            split = current
    return split


def symptom(screen):
    """The first ERROR/WARNING-of-note line, else the last non-empty line."""
    lines = [l.strip() for l in open(screen, errors="replace")] if os.path.exists(screen) else []
    for l in lines:
        if "ERROR" in l:
            return l[:200]
    for l in lines:
        if "Lost atoms" in l or "nan" in l.lower().split():
            return l[:200]
    nonempty = [l for l in lines if l]
    return nonempty[-1][:200] if nonempty else "no output"


def cached_meta(metafile, params, done_status, retry_failed):
    """The meta.json of an earlier run with the same parameters, or None: a run that
    ended in done_status is reused, a failed one too unless retry_failed."""
    if not os.path.exists(metafile):
        return None
    meta = json.load(open(metafile))
    if meta.get("params") == params and (meta["status"] == done_status or not retry_failed):
        return meta
    return None


def known_meta(directory, params, done_status, args, **not_run):
    """What is known of a run without running it: its cached meta.json, or with
    --report-only a 'not run' placeholder (with the extra fields not_run), else None
    (the caller runs it)."""
    meta = cached_meta(os.path.join(directory, "meta.json"), params, done_status, args.retry_failed)
    if meta is None and args.report_only:
        meta = dict(params=params, status="not run", symptom="not run", **not_run)
    return meta


def execute(run, args, restart):
    """Run (or reuse) one shear run; fills run.meta."""
    metafile = os.path.join(run.dir, "meta.json")
    run.meta = known_meta(run.dir, run.params, "ok", args)
    if run.meta is not None:
        return run
    os.makedirs(run.dir, exist_ok=True)
    for f in os.listdir(run.dir):
        os.remove(os.path.join(run.dir, f))
    mpi = [args.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(run.ranks)] \
        if run.ranks > 1 else []
    cmd = mpi + [args.exe_copy, "-in", run.script,
           "-var", "restart", restart, "-var", "meshdir", os.path.join(EXAMPLES, "meshes"),
           "-var", "rate", repr(run.rate), "-var", "dt", repr(run.dt),
           "-var", "eatarget", repr(args.strain), "-var", "nout", str(run.nout),
           "-var", "ndump", str(run.ndump), "-var", "out", run.out, "-log", "log.shear"]
    if run.case == "membrane":
        cmd += ["-var", "every", str(run.every)]
    if not run.default_damping:
        cmd += damping_vars(run.damping)
    timeout = 600 + run.nsteps * 0.02        # 20 ms/step: far above the expected ~1 ms
    loadavg = os.getloadavg()[0]
    log(f"  start {run.name}: {run.nsteps} steps, output every {run.nout}"
        + (f", {run.ranks} ranks" if run.ranks > 1 else ""))
    screen = os.path.join(run.dir, "screen.txt")
    rc, wall, cpu = run_command(cmd, run.dir, screen, timeout)
    tloop, nsteps = loop_times(os.path.join(run.dir, "log.shear"))
    text = open(screen, errors="replace").read()
    done = [l for l in text.splitlines() if l.startswith("SHEAR done")]
    meta = dict(params=run.params, rc=rc, process_wall_s=wall, cpu_s=cpu, loop_time_s=tloop,
                steps=nsteps, done_line=done[-1] if done else "", cmd=" ".join(cmd),
                ranks=run.ranks, cores=os.cpu_count(), loadavg_start=loadavg)
    if rc == 0 and done:
        meta["status"], meta["symptom"] = "ok", ""
    else:
        meta["status"] = "failed"
        meta["symptom"] = ("timeout after %.0f s: " % wall if rc == "timeout" else f"rc {rc}: ") \
            + symptom(screen)
    m = re.search(r"escaped (\S+) chain failures (\S+)", meta["done_line"])
    if m:
        meta["escaped"], meta["chain_failures"] = float(m.group(1)), float(m.group(2))
    m = re.search(r"detections (\S+) changing the chain (\S+)", meta["done_line"])
    if m:   # per side: how often a detection changed the chain (what skipping it would risk)
        meta["detections"], meta["chain_changes"] = float(m.group(1)), float(m.group(2))
    json.dump(meta, open(metafile, "w"), indent=1)
    meta["executed_now"] = True
    run.meta = meta
    log(f"  end   {run.name}: {meta['status']}, loop time {tloop:.1f} s"
        + (f" ({meta['symptom']})" if meta["symptom"] else ""))
    return run


def run_all(todo, args, restarts):
    """Execute the runs in order with at most --jobs job slots busy; a run takes
    run.slots(jobs) of them (one per rank, at most all) and starts only when that
    many are free (first come, first served: no run overtakes a waiting one)."""
    cond = threading.Condition()
    free = [args.jobs]

    def work(run, need):
        try:
            return execute(run, args, restarts[run.seed])
        finally:
            with cond:
                free[0] += need
                cond.notify_all()

    with cf.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futs = []
        for run in todo:
            need = run.slots(args.jobs)
            with cond:
                cond.wait_for(lambda: free[0] >= need)
                free[0] -= need
            futs.append(pool.submit(work, run, need))
        for f in cf.as_completed(futs):
            f.result()


def prepare(seed, args):
    """Generate and prepare the sample of one seed (reused when present)."""
    base = os.path.join(args.sampledir, f"prepared_{seed}.restart")
    if os.path.exists(base) and os.path.exists(base + ".walls"):
        return base
    if args.report_only:
        raise SystemExit(f"no prepared sample {base}")
    data = os.path.join(args.sampledir, f"sample_{seed}.data")
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "generate_sample.py"),
                    "--scale", repr(args.scale), "--seed", str(seed), "--out", data], check=True)
    log(f"  prepare seed {seed}")
    screen = os.path.join(args.sampledir, f"screen.prepare_{seed}")
    rc, wall, _ = run_command([args.exe_copy, "-in", os.path.join(EXAMPLES, "in.prepare"),
                            "-var", "data", data, "-var", "out", base,
                            "-var", "meshdir", os.path.join(EXAMPLES, "meshes"),
                            "-log", os.path.join(args.sampledir, f"log.prepare_{seed}")],
                           args.sampledir, screen, 7200)
    ok = [l for l in open(screen) if l.startswith("PREPARED porosity")]
    if rc != 0 or not ok:
        raise SystemExit(f"in.prepare failed for seed {seed} (rc {rc}): {symptom(screen)}")
    log(f"  prepared seed {seed} in {wall:.0f} s: {ok[0].strip()}")
    return base


# ----------------------------------------------------------------------------- analysis
def load(run):
    """Read the table and the curve analysis of a finished run; flags blow-ups."""
    if run.meta["status"] != "ok" or not os.path.exists(run.out):
        return
    try:
        run.table = readers.read_output(run.out)
        run.curves = curves.analyse_curves(run.table)
    except Exception as e:   # noqa: BLE001  (a broken table is a failed run)
        run.meta["status"], run.meta["symptom"] = "failed", f"unreadable output: {e}"
        run.table = None
        return
    r = run.table["s1/s3"]
    ea = run.table["ea"]
    if not np.all(np.isfinite(r)) or np.nanmax(np.abs(r)) > 50 or np.any(np.diff(ea) < -1e-6):
        run.meta["status"] = "unstable"
        bad = np.nonzero(~np.isfinite(r) | (np.abs(r) > 50))[0]
        at = f"from eps_11 = {100 * ea[bad[0]]:.2f} % on, " if len(bad) else ""
        run.meta["symptom"] = (f"blew up {at}s1/s3 up to {np.nanmax(np.abs(r)):.3g}, "
                               f"KE up to {np.nanmax(run.table['KE']):.3g} J; LIGGGHTS "
                               f"ran on without an error")


def num(x):
    return float(x) if x is not None and measured(x) else float("nan")


def compare(run, ref, args):
    """Errors of run against ref on the common eps_11 grid (dict)."""
    e = {}
    if run.table is None or ref.table is None:
        return e
    a, b = run.table, ref.table
    top = min(a["ea"][-1], b["ea"][-1], args.strain)
    g = np.linspace(0.0, top, args.grid)

    def diff(col):
        if not (a.has(col) and b.has(col)):
            return None
        return np.interp(g, a["ea"], a[col]) - np.interp(g, b["ea"], b[col])

    for col, k in (("s1/s3", "ratio"), ("ev", "ev"), ("a", "a"), ("C_n", "Cn"), ("gsi", "gsi")):
        d = diff(col)
        e[f"rms_{k}"] = float(np.sqrt(np.mean(d ** 2))) if d is not None else float("nan")
        e[f"max_{k}"] = float(np.max(np.abs(d))) if d is not None else float("nan")
        if k == "ratio":
            e["mean_ratio"] = float(np.mean(d)) if d is not None else float("nan")
    ca, cb = run.curves, ref.curves
    e["d_peak"] = num(ca["peak_ratio"]) - num(cb["peak_ratio"])
    e["d_ea_peak"] = num(ca["ea_peak"]) - num(cb["ea_peak"])
    e["dE_rel"] = num(ca["E"]) / num(cb["E"]) - 1.0
    e["d_phi"] = num(ca["phi_peak"]) - num(cb["phi_peak"])
    e["d_psi"] = num(ca["psi"]) - num(cb["psi"])
    e["ea_compared"] = float(top)
    return e


def row_for(sweep, run, ref, ref0, args):
    m = run.meta
    c = run.curves or {}
    row = dict(sweep=sweep, case=run.case, seed=run.seed, rate=run.rate, dt=run.dt,
               every=run.every if run.case == "membrane" else "",
               damping=damping_spec(run.damping), default_damping=int(run.default_damping),
               ranks=run.ranks,
               cores=m.get("cores") or os.cpu_count(), loadavg_start=m.get("loadavg_start"),
               time_split=time_split(os.path.join(run.dir, "log.shear")),
               reference=ref.name,
               is_reference=int(run is ref), status=m["status"], symptom=m.get("symptom", ""),
               steps=m.get("steps", ""), wall_s=m.get("loop_time_s", float("nan")),
               cpu_s=m.get("cpu_s", float("nan")),
               ms_per_step=(1e3 * m["loop_time_s"] / m["steps"]) if m.get("steps") else float("nan"),
               I_max=num(c.get("I_max")), escaped=m.get("escaped", ""),
               chain_failures=m.get("chain_failures", ""),
               chain_change_fraction=(m["chain_changes"] / (2 * m["detections"]))
               if m.get("detections") else "",
               peak_ratio=num(c.get("peak_ratio")), ea_peak=num(c.get("ea_peak")),
               E=num(c.get("E")), phi=num(c.get("phi_peak")), psi=num(c.get("psi")))
    row.update(compare(run, ref, args))
    row["rms_ratio_vs_case_ref"] = compare(run, ref0, args).get("rms_ratio", float("nan"))
    for k in ERR_KEYS + ["mean_ratio", "max_a", "max_Cn", "max_gsi", "ea_compared"]:
        row.setdefault(k, float("nan"))
    return row


# ----------------------------------------------------------------------------- output
ERR_KEYS = ["rms_ratio", "max_ratio", "rms_ev", "max_ev", "d_peak", "d_ea_peak", "dE_rel",
            "d_phi", "d_psi", "rms_a", "rms_Cn", "rms_gsi"]
# what "within the sample scatter" means (|error| <= |scatter| for each of these)
GATE_KEYS = ["rms_ratio", "rms_ev", "d_peak"]
CSV_KEYS = ["sweep", "case", "seed", "rate", "dt", "every", "damping", "ranks", "reference",
            "is_reference", "status",
            "symptom", "steps", "wall_s", "cpu_s", "ms_per_step", "I_max", "escaped", "chain_failures",
            "chain_change_fraction",
            "peak_ratio", "ea_peak", "E", "phi", "psi"] + ERR_KEYS + \
           ["mean_ratio", "max_a", "max_Cn", "max_gsi", "ea_compared", "rms_ratio_vs_case_ref",
            "within_scatter", "speedup", "efficiency", "oversubscribed"]


def within(row, scatter):
    """'' when every GATE_KEYS error is within the scatter, else the keys that exceed it."""
    if scatter is None or row["status"] != "ok":
        return "n/a"
    over = [k for k in GATE_KEYS if abs(row.get(k, np.nan)) > abs(scatter.get(k, np.nan))
            or not np.isfinite(row.get(k, np.nan))]
    return "yes" if not over else "no: " + " ".join(over)


def sweep_of(row):
    """The sweeps whose rows are judged against the scatter (not the scatter rows)."""
    return row["sweep"] if row["sweep"] in ("rate", "every", "dt", "rate@seed2", "damping",
                                            "ranks") else None


def pareto(points):
    """Indices of the Pareto front of (time, error) points (both minimised)."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def fmt(x, spec="{:.3g}", scale=1.0):
    if x == "" or x is None:
        return ""
    try:
        x = float(x)
    except (TypeError, ValueError):
        return str(x)
    return "—" if not np.isfinite(x) else spec.format(x * scale)


def ranks_text(row):
    """'2 ranks', '4 ranks (oversubscribed: 2 cores)', with speed-up and efficiency."""
    n = int(row["ranks"])
    t = f"{n} rank" + ("s" if n > 1 else "")
    if row.get("oversubscribed"):
        t += f" (oversubscribed: {row['cores']} cores)"
    if n > 1 and np.isfinite(row.get("speedup", np.nan)):
        t += f", speed-up {row['speedup']:.2f}, efficiency {100 * row['efficiency']:.0f} %"
    return t


def setting(row):
    if row["sweep"] == "damping":
        d = damping(row["damping"])
        return damping_text(d) + (f" (rate {row['rate']:g})" if row.get("rate_note") else "")
    if row["sweep"] == "ranks":
        return ranks_text(row)
    if row["sweep"] == "every":
        return f"every {row['every']}"
    if row["sweep"] == "dt":
        return f"dt {row['dt']:g} s"
    if row["sweep"] == "scatter":
        return "pooled: RMS over the seed rows"
    if row["sweep"] == "rate@seed2":
        return f"rate {row['rate']:g} /s, seed {row['seed']}"
    if row["sweep"].startswith("seed"):
        return f"seed {row['seed']} (rate {row['rate']:g})"
    return f"rate {row['rate']:g} /s"


def markdown_table(rows):
    head = ["sweep", "case", "setting", "status", "steps", "wall [s]", "CPU [s]", "I_max",
            "RMS Δ(σ1/σ3)", "max Δ(σ1/σ3)", "mean Δ(σ1/σ3)", "RMS Δε_v [%]", "max Δε_v [%]", "Δpeak σ1/σ3",
            "Δε_peak [%]", "ΔE [%]", "Δφ [°]", "Δψ [°]", "RMS Δa", "RMS ΔC_n", "RMS Δλ",
            "RMS Δ(σ1/σ3) vs case ref", "within scatter"]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        ref = r["is_reference"]
        errs = [""] * 15 if ref else [
            fmt(r.get("rms_ratio")), fmt(r.get("max_ratio")), fmt(r.get("mean_ratio"), "{:+.3g}"), fmt(r.get("rms_ev"), scale=100),
            fmt(r.get("max_ev"), scale=100), fmt(r.get("d_peak"), "{:+.3g}"),
            fmt(r.get("d_ea_peak"), "{:+.2g}", 100), fmt(r.get("dE_rel"), "{:+.2g}", 100),
            fmt(r.get("d_phi"), "{:+.2f}"), fmt(r.get("d_psi"), "{:+.2f}"), fmt(r.get("rms_a")),
            fmt(r.get("rms_Cn")), fmt(r.get("rms_gsi")), fmt(r.get("rms_ratio_vs_case_ref")),
            r.get("within_scatter", "")]
        if r["status"] != "ok":            # no error of a failed run is meaningful
            errs = ["—"] * len(errs)
        if r["sweep"] == "scatter":       # magnitudes (RMS over the seed pairs), no sign
            errs = [e.lstrip("+") for e in errs]
        status = r["status"] + (f" ({r['symptom']})" if r["status"] != "ok" else "")
        if r["case"] == "membrane" and r["status"] == "ok" and (r["escaped"] or r["chain_failures"]):
            status += f" (escaped {r['escaped']:g}, chain failures {r['chain_failures']:g})"
        out.append("| " + " | ".join([r["sweep"], r["case"], setting(r) + (" **ref**" if ref else ""),
                                      status, str(r["steps"]), fmt(r["wall_s"], "{:.1f}"),
                                      fmt(r["cpu_s"], "{:.1f}"),
                                      fmt(r["I_max"], "{:.2g}")] + errs) + " |")
    return "\n".join(out)


def plot(rows, scatter, path, tkey):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = [c for c in ("rigid", "membrane") if any(r["case"] == c for r in rows)]
    fig, axes = plt.subplots(1, len(cases), figsize=(6.5 * len(cases), 6.2), squeeze=False)
    # damping: viscous and local as two series; ranks: x = wall time whatever the axis
    # (an N-rank run's CPU time is that of its N ranks), not on the Pareto front
    style = {"rate": ("o", "C0"), "every": ("s", "C1"), "dt": ("^", "C2"), "seed": ("*", "C3"),
             "damping viscous": ("D", "C4"), "damping local": ("P", "C6"),
             "ranks": ("h", "C5")}
    swept = ("rate", "every", "dt", "damping", "ranks")

    def series(r):
        return r["sweep"] + (" " + r["damping"].split(":")[0] if r["sweep"] == "damping" else "")

    def xof(r):
        return r["wall_s"] if r["sweep"] == "ranks" else r[tkey]

    fronts = {}
    for ax, case in zip(axes[0], cases):
        rs = [r for r in rows if r["case"] == case and r["sweep"] in swept]
        # the ranks sweep's 1-rank run is plotted too (its x is its wall time); the
        # default damping at a rate of the rate sweep is that sweep's point already
        rated = {r["rate"] for r in rs if r["sweep"] == "rate"}
        pts = [r for r in rs if r["status"] == "ok"
               and (not r["is_reference"] or r["sweep"] == "ranks")
               and not (r["sweep"] == "damping" and r["default_damping"] and r["rate"] in rated)
               and r.get("rms_ratio_vs_case_ref", np.nan) > 0 and np.isfinite(xof(r))]
        sc = scatter.get(case, {}).get("rms_ratio", np.nan)
        lo = min([r["rms_ratio_vs_case_ref"] for r in pts] + ([sc] if np.isfinite(sc) else [])
                 + [1.0]) / 2.5
        for sweep, (mk, col) in style.items():
            sel = [r for r in pts if series(r) == sweep]
            if sel:
                ax.scatter([xof(r) for r in sel], [r["rms_ratio_vs_case_ref"] for r in sel],
                           marker=mk, color=col, s=50, zorder=3,
                           label=f"{sweep} sweep" + (" (x = wall time)" if sweep == "ranks"
                                                     else ""))
                for r in sel:
                    lab = {"rate": f"{r['rate']:g}", "every": f"e{r['every']}",
                           "dt": f"dt {r['dt']:g}",
                           "damping viscous": f"v{r['damping'].split(':')[1]}",
                           "damping local": f"α{r['damping'].split(':')[1]}",
                           "ranks": f"{r['ranks']}r"}.get(sweep, "")
                    if sweep.startswith("damping") and len({x["rate"] for x in sel}) > 1:
                        lab += f"@{r['rate']:g}"
                    ax.annotate(lab, (xof(r), r["rms_ratio_vs_case_ref"]), fontsize=7,
                                xytext=(4, 3), textcoords="offset points")
        refs = [r for r in rs if r["is_reference"] and r["sweep"] == "rate" and r["status"] == "ok"]
        for r in refs:
            ax.scatter([r[tkey]], [lo], marker="v", color="k", s=60, zorder=3,
                       label=f"case reference (rate {r['rate']:g}, error 0)")
        bad = [r for r in rs if r["status"] != "ok"]
        for r in bad:
            ax.scatter([xof(r) if np.isfinite(xof(r)) else 1], [lo], marker="x",
                       color="r", s=60, zorder=3, label="failed/unstable")
        cand = [r for r in pts if r["sweep"] != "ranks"]
        if cand:
            front = pareto([(r[tkey], r["rms_ratio_vs_case_ref"]) for r in cand])
            fr = sorted([cand[i] for i in front], key=lambda r: r[tkey])
            fronts[case] = fr
            ax.plot([r[tkey] for r in fr], [r["rms_ratio_vs_case_ref"] for r in fr], "k--",
                    lw=1, zorder=2, label="Pareto front")
            ax.scatter([r[tkey] for r in fr], [r["rms_ratio_vs_case_ref"] for r in fr],
                       s=160, facecolors="none", edgecolors="k", zorder=4)
        for r in rows:
            if r["case"] == case and r["sweep"] == "seed@rate" and r["status"] == "ok":
                ax.axhline(r["rms_ratio"], color="C3", lw=0.8, ls=":",
                           label="scatter at other rates" if True else None)
                ax.annotate(f"scatter @ {r['rate']:g} /s", (ax.get_xlim()[0], r["rms_ratio"]),
                            fontsize=6, color="C3", xytext=(2, 2), textcoords="offset points")
        s = scatter.get(case)
        if s and np.isfinite(s.get("rms_ratio", np.nan)):
            ax.axhspan(lo / 10, s["rms_ratio"], color="0.9", zorder=0,
                       label="below the scatter: noise")
            ax.axhline(s["rms_ratio"], color="C3", lw=1.5,
                       label=f"sample scatter (RMS of {s['n']} seed pairs) = {s['rms_ratio']:.3g}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(bottom=lo / 1.5)
        ax.set_xlabel(("CPU time (user+sys)" if tkey == "cpu_s" else "wall time ('Loop time')")
                      + " of the shear run [s], 1 rank"
                      + ("; ranks sweep: wall time on N ranks"
                         if any(r["sweep"] == "ranks" for r in pts) else ""))
        ax.set_ylabel("RMS Δ(σ1/σ3) vs the case reference")
        ax.set_title(f"{case}: run time against error")
        ax.grid(True, which="both", alpha=0.3)
        h, lab = ax.get_legend_handles_labels()
        uniq = dict(zip(lab, h))
        ax.legend(uniq.values(), uniq.keys(), fontsize=7, loc="upper center",
                  bbox_to_anchor=(0.5, -0.13), ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return fronts


# ----------------------------------------------------------------------------- main
def main(argv):
    args = parse_args(argv)
    t_start = time.time()
    args.sampledir = os.path.join(os.path.abspath(args.workdir), f"scale{tag(args.scale)}")
    args.rundir = os.path.join(args.sampledir, f"strain{tag(args.strain)}")
    os.makedirs(args.rundir, exist_ok=True)
    args.exe_copy = os.path.join(args.sampledir, "liggghts-membrane")
    if not args.report_only:
        shutil.copy2(args.exe, args.exe_copy + ".new")
        os.replace(args.exe_copy + ".new", args.exe_copy)
    exe_sha = args.exe_sha = sha(args.exe_copy) if os.path.exists(args.exe_copy) else "?"
    # the input scripts too are copied (by content hash): runs made with another
    # version of the executable or of a script are re-run, never mixed
    args.scripts, args.script_sha = {}, {}
    os.makedirs(os.path.join(args.sampledir, "inputs"), exist_ok=True)
    for case in ("rigid", "membrane"):
        src = os.path.join(EXAMPLES, f"in.shear_{case}")
        args.script_sha[case] = sha(src)
        args.scripts[case] = os.path.join(args.sampledir, "inputs",
                                          f"in.shear_{case}.{args.script_sha[case]}")
        if not os.path.exists(args.scripts[case]):
            shutil.copy2(src, args.scripts[case])
    # the damping the scripts use when no -var damping is given (the runs' default)
    args.default_damping = {c: script_damping(args.scripts[c]) for c in args.scripts}
    seed0 = args.seeds[0]
    ref_rate, rate_d, dt_d = min(args.rates), args.default_rate, args.default_dt
    every_ref = min([e for e in args.everys if e != "auto"] or [1])
    every_d = args.default_every if args.default_every == "auto" else int(args.default_every)

    runs = {}

    def get(case, seed, rate, dt=dt_d, every=every_d, damping=None, ranks=1):
        r = Run(case, seed, rate, dt, every if case == "membrane" else 0, args,
                damping=damping, ranks=ranks)
        return runs.setdefault(r.key, r)

    cases = ("rigid", "membrane")
    plan = []   # (sweep, run, reference run)
    ref0 = {c: get(c, seed0, ref_rate) for c in cases}
    if "rate" in args.sweeps:
        for c in cases:
            for rate in sorted(args.rates):
                plan.append(("rate", get(c, seed0, rate), ref0[c]))
    if "every" in args.sweeps:
        ref = get("membrane", seed0, rate_d, every=every_ref)
        for ev in sorted(args.everys, key=every_key):
            plan.append(("every", get("membrane", seed0, rate_d, every=ev), ref))
    if "dt" in args.sweeps:
        ref = get("rigid", seed0, rate_d, dt=dt_d)
        for dt in sorted(args.dts):
            plan.append(("dt", get("rigid", seed0, rate_d, dt=dt), ref))
    if "seed" in args.sweeps and len(args.seeds) > 1:
        for c in cases:
            plan.append(("seed", get(c, args.seeds[1], ref_rate), ref0[c]))
        for rate in sorted(set(args.scatter_rates) - {ref_rate}):
            for c in cases:
                plan.append(("seed@rate", get(c, args.seeds[1], rate), get(c, seed0, rate)))
        # the same runs give the rate error on the second sample too (no extra run)
        if "rate" in args.sweeps:
            for rate in sorted(set(args.scatter_rates) - {ref_rate}):
                for c in cases:
                    plan.append(("rate@seed2", get(c, args.seeds[1], rate),
                                 get(c, args.seeds[1], ref_rate)))
    if "damping" in args.sweeps:
        # reference: the case reference of the rate sweep (slowest rate, default damping);
        # the default damping at a rate of the rate sweep is that very run
        for rate in sorted(args.damping_rates):
            for c in cases:
                for d in args.dampings:
                    plan.append(("damping", get(c, seed0, rate, damping=d), ref0[c]))
    if "ranks" in args.sweeps:
        for c in cases:
            ref = get(c, seed0, rate_d, ranks=1)
            for n in args.ranks:
                plan.append(("ranks", get(c, seed0, rate_d, ranks=n), ref))
    seeds = sorted({r.seed for r in runs.values()}, key=args.seeds.index)

    if not args.report_only and any(r.ranks > 1 for r in runs.values()) \
            and shutil.which(args.mpirun) is None:
        raise SystemExit(f"ranks sweep: no MPI launcher '{args.mpirun}' (--mpirun)")
    log(f"accuracy sweep: scale {args.scale:g}, strain {args.strain:g}, {len(runs)} runs "
        f"({sum(r.nsteps for r in runs.values())} steps), {args.jobs} job slots, 1 rank each"
        + (" (ranks sweep: N ranks take min(N, jobs) slots, after the 1-rank runs)"
           if any(r.ranks > 1 for r in runs.values()) else "")
        + f"; executable {args.exe_copy} (sha256 {exe_sha})")
    with cf.ThreadPoolExecutor(max_workers=min(args.jobs, 2 if args.jobs >= 2 else 1)) as pool:
        restarts = dict(zip(seeds, pool.map(lambda s: prepare(s, args), seeds)))
    # 1-rank runs longest first, then the multi-rank runs: a run starts when its job
    # slots are free, in this order (a multi-rank run waits for them, so with --jobs 2
    # a 2- or 4-rank run has the machine's 2 cores to itself, as far as this script goes)
    todo = sorted(runs.values(), key=lambda r: (r.ranks > 1, r.ranks, -r.cost()))
    run_all(todo, args, restarts)
    for r in runs.values():
        load(r)
    executed = [r.name for r in runs.values() if r.meta.get("executed_now")]
    inv_file = os.path.join(args.rundir, "invocations.json")
    invocations = json.load(open(inv_file)) if os.path.exists(inv_file) else []
    if executed:
        invocations.append(dict(start=time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(t_start)),
                                wall_s=time.time() - t_start, runs=executed, argv=argv))
        json.dump(invocations, open(inv_file, "w"), indent=1)

    # scatter: the two seeds' references
    rows = []
    for sweep, run, ref in plan:
        row = row_for(sweep, run, ref, ref0[run.case], args)
        if sweep == "seed@rate":
            row["is_reference"] = 0
        if sweep == "damping":
            row["rate_note"] = int(len(args.damping_rates) > 1)
        if sweep == "ranks":
            row["oversubscribed"] = int(run.ranks > int(row["cores"]))
            t1, tn = ref.meta.get("loop_time_s", np.nan), run.meta.get("loop_time_s", np.nan)
            ok = run.meta["status"] == "ok" and ref.meta["status"] == "ok" and tn > 0
            row["speedup"] = t1 / tn if ok else float("nan")
            row["efficiency"] = row["speedup"] / run.ranks
        rows.append(row)
    # the scatter level of each error: RMS over the seed comparisons (at the reference
    # rate and at --scatter-rates; a single pair of samples gives a single, random value)
    scatter = {}
    for c in cases:
        sr = [r for r in rows if r["case"] == c and r["sweep"].startswith("seed") and r["status"] == "ok"]
        if sr:
            scatter[c] = {k: float(np.sqrt(np.nanmean([r[k] ** 2 for r in sr])))
                          if any(np.isfinite(r[k]) for r in sr) else float("nan")
                          for k in ERR_KEYS + ["mean_ratio"]}
            scatter[c]["n"] = len(sr)
            row = dict(sweep="scatter", case=c, seed="", rate="", dt="", every="",
                       reference=f"RMS of the {len(sr)} seed comparisons", is_reference=0,
                       status="ok", symptom="", steps="", wall_s=float("nan"),
                       cpu_s=float("nan"), I_max=float("nan"), escaped="", chain_failures="",
                       rms_ratio_vs_case_ref=float("nan"), within_scatter="")
            row.update(scatter[c])
            rows.append(row)
    for row in rows:
        row["within_scatter"] = "" if row["is_reference"] or row["sweep"] != sweep_of(row) \
            else within(row, scatter.get(row["case"]))

    with open(args.prefix + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, CSV_KEYS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v)
                        for k, v in r.items()})
    tkey = "cpu_s" if args.time_axis == "cpu" else "wall_s"
    fronts = plot(rows, scatter, args.prefix + ".png", tkey)

    # recommendations: the fastest setting of each sweep within the scatter
    rec = []
    for sweep, case in (("rate", "rigid"), ("rate", "membrane"), ("every", "membrane"),
                        ("dt", "rigid")):
        sel = [r for r in rows if r["sweep"] == sweep and r["case"] == case]
        second = {r["rate"]: r for r in rows if r["sweep"] == "rate@seed2" and r["case"] == case}
        good = [r for r in sel if r["is_reference"] or (
            r.get("within_scatter") == "yes" and
            (sweep != "rate" or r["rate"] not in second
             or second[r["rate"]].get("within_scatter") == "yes"))]
        if not sel or case not in scatter:
            continue
        best = min(good, key=lambda r: r[tkey]) if good else None
        if best is not None:
            rec.append(f"- {sweep} sweep, {case}: fastest within the sample scatter = "
                       f"**{setting(best)}** ({fmt(best['wall_s'], '{:.0f}')} s wall, "
                       f"{fmt(best['cpu_s'], '{:.0f}')} s CPU, "
                       f"RMS Δ(σ1/σ3) {fmt(best.get('rms_ratio', 0))} vs scatter "
                       f"{fmt(scatter[case]['rms_ratio'])}, I_max {fmt(best['I_max'], '{:.2g}')})")
    # damping: at a given rate every damping costs about the same, so the question is
    # which one comes closest to the quasi-static reference (and which are within noise)
    for case in cases:
        sel = [r for r in rows if r["sweep"] == "damping" and r["case"] == case]
        for rate in sorted({r["rate"] for r in sel}):
            at = [r for r in sel if r["rate"] == rate]
            ok = [r for r in at if r["status"] == "ok" and not r["is_reference"]
                  and np.isfinite(r.get("rms_ratio", np.nan))]
            if not ok:
                continue
            if any(r["is_reference"] for r in at):
                rec.append(f"- damping sweep, {case} at {rate:g} /s: the reference rate, where "
                           f"the default damping is the reference itself; the others differ by "
                           + ", ".join(f"{damping_text(damping(r['damping']))[len('damping '):]} "
                                       f"RMS {fmt(r['rms_ratio'])} "
                                       f"({'within' if r.get('within_scatter') == 'yes' else 'outside'})"
                                       for r in ok)
                           + f" (scatter {fmt(scatter.get(case, {}).get('rms_ratio', float('nan')))}).")
                continue
            best = min(ok, key=lambda r: r["rms_ratio"])
            inside = [damping_text(damping(r["damping"]))[len("damping "):] for r in at
                      if r.get("within_scatter") == "yes"]
            failed = [damping_text(damping(r["damping"]))[len("damping "):] for r in at
                      if r["status"] != "ok"]
            dflt = [r for r in ok if r["damping"] == damping_spec(args.default_damping[case])]
            sc = scatter.get(case, {}).get("rms_ratio", float("nan"))
            rec.append(f"- damping sweep, {case} at {rate:g} /s: closest to the reference "
                       f"(rate {ref_rate:g} /s, default damping) = **{damping_text(damping(best['damping']))}** "
                       f"(RMS Δ(σ1/σ3) {fmt(best['rms_ratio'])}, Δpeak {fmt(best['d_peak'], '{:+.3g}')}, "
                       f"Δψ {fmt(best['d_psi'], '{:+.2f}')}°, {fmt(best[tkey], '{:.0f}')} s {args.time_axis}"
                       + (f"; default {dflt[0]['damping']}: RMS {fmt(dflt[0]['rms_ratio'])}, "
                          f"Δpeak {fmt(dflt[0]['d_peak'], '{:+.3g}')}" if dflt and dflt[0] is not best
                          else "")
                       + f"; scatter {fmt(sc)}); within the sample scatter: "
                       + (", ".join(inside) if inside else "none")
                       + (f"; failed/unstable: {', '.join(failed)}" if failed else ""))
    # ranks: wall time is what more ranks buy
    ranks_par = []
    for case in cases:
        sel = [r for r in rows if r["sweep"] == "ranks" and r["case"] == case]
        if not sel:
            continue
        good = [r for r in sel if r["status"] == "ok" and (r["is_reference"]
                                                           or r.get("within_scatter") == "yes")]
        if good and case in scatter:
            best = min(good, key=lambda r: r["wall_s"])
            rec.append(f"- ranks sweep, {case}: fastest within the sample scatter = "
                       f"**{ranks_text(best)}** ({fmt(best['wall_s'], '{:.1f}')} s wall, "
                       f"{fmt(best['cpu_s'], '{:.0f}')} s CPU of all ranks"
                       + ("" if best["is_reference"] else
                          f", RMS Δ(σ1/σ3) vs 1 rank {fmt(best['rms_ratio'])} vs scatter "
                          f"{fmt(scatter[case]['rms_ratio'])}") + ")")
        parts = []
        for r in sel:
            if r["status"] != "ok":
                parts.append(f"{ranks_text(r)}: {r['status']}")
                continue
            lavg = r.get("loadavg_start")
            t = f"{ranks_text(dict(r, speedup=np.nan))} {fmt(r['wall_s'], '{:.1f}')} s"
            if not r["is_reference"]:
                t += (f": speed-up {fmt(r['speedup'], '{:.2f}')}, efficiency "
                      f"{fmt(r['efficiency'], '{:.0f}', 100)} %, RMS Δ(σ1/σ3) vs 1 rank "
                      f"{fmt(r['rms_ratio'])}, vs the case reference "
                      f"{fmt(r['rms_ratio_vs_case_ref'])}")
            if lavg is not None:
                t += f" (load average {lavg:.1f} at its start)"
            split = r.get("time_split")
            if split:
                t += " [time: " + ", ".join(f"{k} {v:.0f} %" for k, v in split.items()) + "]"
            parts.append(t)
        ranks_par.append(f"- {case}: " + "; ".join(parts) + ".")
    if ranks_par:
        ncores = max(int(r["cores"]) for r in rows if r["sweep"] == "ranks")
        ranks_par = [
            "## Ranks sweep: speed-up and parallel efficiency\n",
            f"Same run (rate {rate_d:g} /s, dt {dt_d:g} s, default damping and every, seed "
            f"{seed0}) on N MPI ranks (`{args.mpirun} --allow-run-as-root --oversubscribe -np N`; "
            f"1 rank without mpirun: the very run of the other sweeps). Speed-up = wall time "
            f"('Loop time') on 1 rank / on N ranks, efficiency = speed-up / N; the errors are "
            f"against the 1-rank run (the same physics, only the order of the floating-point "
            f"sums differs, which a chaotic granular flow amplifies) and against the case "
            f"reference. An N-rank run took min(N, {args.jobs}) of the {args.jobs} job slots, "
            f"after the 1-rank runs, which themselves ran {args.jobs} at a time. "
            f"**These figures are only meaningful on an otherwise idle machine** "
            f"({ncores} cores here; N > {ncores} is oversubscribed; the 1-minute load "
            f"average at the start of each run is given, our own runs included):\n",
            *ranks_par, ""]
    total_core = sum((r.meta.get("loop_time_s", 0.0) or 0.0) * r.ranks for r in runs.values())
    notes = []
    ok_runs = [r for r in runs.values() if r.meta["status"] == "ok"]
    for c in cases:
        r = ref0[c]
        if r.meta["status"] == "ok":
            f = ref_rate / PUBLISHED_RATE
            if ref_rate <= PUBLISHED_RATE * 1.01:
                notes.append(f"- Published rate 2 %/min = {PUBLISHED_RATE:.3g} /s, {c}: it is the "
                             f"reference, {r.meta['loop_time_s'] / 60:.1f} min on 1 rank at this size.")
                continue
            notes.append(f"- Published rate 2 %/min = {PUBLISHED_RATE:.3g} /s, {c}: "
                         f"{int(math.ceil(args.strain / (PUBLISHED_RATE * dt_d)))} steps, about "
                         f"{r.meta['loop_time_s'] * f / 60:.0f} min on 1 rank at this size "
                         f"(the {ref_rate:g} /s reference × {f:.1f}; steps ∝ 1/rate); not run.")
    full = (1.0 / args.scale) ** 2
    notes.append(f"- Sum of the shear-run loop times: {total_core / 60:.1f} core-min "
                 f"({len(ok_runs)}/{len(runs)} runs ok). The same command at --scale 1 "
                 f"(~4× the disks, cost ∝ disks) would need about {total_core * full / 60:.0f} "
                 f"core-min at --strain {args.strain:g}, {total_core * full * 0.10 / args.strain / 60:.0f} "
                 f"at --strain 0.10, i.e. /{args.jobs} in wall time with --jobs {args.jobs}, plus the "
                 f"preparation of 2 full samples.")
    for r in runs.values():
        m = r.meta
        if m["status"] != "ok":
            notes.append(f"- {r.name}: {m['status']}: {m.get('symptom', '')}")
    mem = [r for r in ok_runs if r.case == "membrane"]
    if mem:
        esc = sorted({m.meta.get("escaped", float("nan")) for m in mem})
        cf_ = sorted({m.meta.get("chain_failures", float("nan")) for m in mem})
        notes.append(f"- Membrane 'SHEAR done' lines: escaped disks at the end "
                     f"{', '.join(f'{x:g}' for x in esc)}; chain failures "
                     f"{', '.join(f'{x:g}' for x in cf_)} (per run: the CSV).")
        frac = [(r.every, r.rate, r.meta["chain_changes"] / (2 * r.meta["detections"]))
                for r in mem if r.meta.get("detections")]
        if frac:
            notes.append("- Share of chain detections that changed a side's chain or escapees "
                         "(what skipping detections risks; per side, settling included): "
                         + "; ".join(f"every {e} at {rt:g} /s: {100 * x:.1f} %"
                                   for e, rt, x in sorted(frac, key=lambda t: (every_key(t[0]), t[1]))))
    fast = sorted({r.rate for r in ok_runs if r.curves and r.curves.get("I_max", 0) > 1e-3})
    if fast:
        notes.append(f"- I_max > 1e-3 (not quasi-static by the spec's criterion) at rates "
                     f"{', '.join(f'{x:g}' for x in fast)} /s.")
    for inv in invocations:
        notes.append(f"- Invocation {inv['start']}: {inv['wall_s'] / 60:.1f} min wall, "
                     f"{len(inv['runs'])} runs executed.")
    front_text = [f"- {c}: " + ", ".join(f"{setting(r)} [{r['sweep']}]" for r in fr)
                  for c, fr in fronts.items()]
    wall = time.time() - t_start
    shown = [a for a in argv if a != "--report-only"]
    took = (f"this invocation took {wall / 60:.1f} min of wall time" if executed else
            "the runs were made by the invocations listed in the Notes")
    md = ["# Run time against error of the biaxial test\n",
          f"Command: `/usr/bin/python3 bench/accuracy_sweep.py {' '.join(shown)}`".rstrip() + "  ",
          f"Sample: generate_sample.py --scale {args.scale:g} (seeds {', '.join(map(str, args.seeds))}), "
          f"in.prepare; sheared to ε_11 = {args.strain:g}; every run on 1 MPI rank"
          + (" (the ranks sweep excepted)" if "ranks" in args.sweeps else "")
          + f", {args.jobs} at a time; {took} (runs reused from {os.path.relpath(args.rundir, ROOT)} are not "
          f"re-run).  ",
          f"Errors: each run against the reference of its sweep (**ref**) on a common ε_11 grid "
          f"over 0..{args.strain:g}; Δ = run − reference. 'RMS Δ(σ1/σ3) vs case ref': against the "
          f"slowest-rate run of the same case (the y axis of the plot). 'seed' rows: the reference "
          f"repeated on a second sample (and, 'seed@rate', the same pair at other rates) = the "
          f"sample-to-sample scatter; 'scatter' rows: the RMS over those pairs, the noise level "
          f"used. "
          + ("'damping' rows: both cases with another damping (viscous G = fix viscous G "
             "N·s/m, local α = fix damping/local alpha α; the scripts' default is "
             + ", ".join(f"{damping_text(d)[len('damping '):]} ({c})"
                         for c, d in args.default_damping.items())
             + ") against the case reference: which damping comes closest to the "
             "quasi-static answer at that rate. " if "damping" in args.sweeps else "")
          + ("'ranks' rows: the same run on N MPI ranks against the 1-rank run (x = wall "
             "time in the plot; see the section below). " if "ranks" in args.sweeps else "")
          + f"'within scatter': |error| ≤ scatter for {', '.join(GATE_KEYS)} (E, φ, ψ and "
          f"fabric errors are given but not gated: ψ and E of one run are noisy). Wall time = "
          f"the sum of the log's 'Loop time' lines (the membrane's settling steps "
          f"included); CPU = user+sys time of the process (others used the machine too: "
          f"wall > CPU means the run was descheduled). Output every {args.dstrain_out:g} of "
          f"strain in every run. Executable sha256 {exe_sha}, scripts "
          f"{', '.join(f'in.shear_{c} {h}' for c, h in args.script_sha.items())}.\n",
          markdown_table(rows), "",
          "![run time against error](%s.png)\n" % os.path.basename(args.prefix),
          "## Fastest settings within the sample scatter\n", *rec, "",
          *ranks_par,
          f"Pareto front ({args.time_axis} time vs RMS Δ(σ1/σ3) against the case reference, "
          f"circled in the plot):", *front_text, "",
          "## Notes\n", *notes, ""]
    text = "\n".join(md)
    open(args.prefix + ".md", "w").write(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
