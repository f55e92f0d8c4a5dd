#!/usr/bin/python3
"""Run time against error of the 2D DEM biaxial test (examples/biaxial).

    /usr/bin/python3 bench/accuracy_sweep.py [--scale 0.5] [--strain 0.05] [--jobs 2]
        [--rates 0.00125,0.0025,0.005,0.01,0.02,0.04,0.08] [--everys auto,1,2,5,10,50]
        [--dts 1e-4,5e-5,2e-4,4e-4,8e-4] [--seeds 12345,54321] [--workdir out/accuracy_sweep]
        [--dampings viscous:500,viscous:100,viscous:2000,viscous:5000,local:0.1,local:0.3,local:0.7]
        [--damping-rates R1,R2] [--ranks 1,2,4] [--sweeps rate,every,dt,seed[,damping,ranks]]
    /usr/bin/python3 bench/accuracy_sweep.py --from-csv [--prefix bench/accuracy_sweep]

One command: generates and prepares (examples/biaxial/in.prepare) one sample per
seed, shears it (in.shear_rigid / in.shear_membrane) on ONE MPI rank per run (the
ranks sweep excepted), at most --jobs runs at a time, and compares every run with
the reference run of its sweep:

  rate     both cases, -var rate R; reference = the slowest rate of --rates
  every    membrane, -var every auto|N at --default-rate; reference = the smallest N (1:
           a detection every step); auto must equal it exactly (same chains every step)
  dt       rigid, -var dt DT at --default-rate; reference = --default-dt (the dt of
           the shear scripts, read from examples/biaxial/shear_setup.inc)
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
s1/s3 and eps_v; peak s1/s3 and its strain, E, phi, psi (liggghts_membrane.curves);
RMS difference of the fabric a, C_n and mean lambda (gsi). Wall time = the sum of
the 'Loop time' lines of the run's log; CPU time = user+sys of the process and, for
an N-rank run, of all its ranks (mpirun reaps them). The output interval is set to a fixed
strain (--dstrain-out, the examples' 500 steps at rate 0.01, dt 1e-4), so every run
has the same curve resolution and the same number of fabric evaluations.

Plan / run / report: the plan is the list of runs and comparisons of the sweeps
asked; run executes the missing runs into --workdir (a run folder with the same
parameters, executable and script hashes is reused: the command can be re-run to
resume; the executable is copied into --workdir at the start, so a rebuild by someone
else does not change it in the middle of the sweep); the report is made from the CSV
it writes, PREFIX.csv (raw numbers), and PREFIX.json (the command, its options, the
hashes, invocations and per-run load), by bench/accuracy_report.py: PREFIX.png (time
vs RMS error of s1/s3 with the scatter level and the Pareto front) and PREFIX.md (the
table, the recommendations and, with the ranks sweep, the speed-up and efficiency per
rank count), also printed. --report-only: no runs, the report of what is in
--workdir; --from-csv: no runs and no --workdir, the report again from PREFIX.csv and
PREFIX.json alone (the published bench/accuracy_sweep.* and accuracy_published.*).
"""
import argparse
import concurrent.futures as cf
import math
import os
import shutil
import sys
import threading

import numpy as np

from liggghts_membrane.bench import common
from liggghts_membrane.bench.common import EXAMPLES, MESHES, ROOT, HERE, floats, ints, log, tag
from liggghts_membrane.bench.accuracy_report import (CSV_KEYS, ERR_KEYS, damping, damping_spec, every_key, judge,
                             report, run_name)
from liggghts_membrane import curves, readers
from liggghts_membrane.curves import measured


def everys(text):
    """'auto,1,2' -> ['auto', 1, 2]"""
    return [w.strip() if w.strip() == "auto" else int(w) for w in text.split(",") if w.strip()]


def dampings(text):
    out = []
    for w in text.split(","):
        if w.strip() and damping(w) not in out:
            out.append(damping(w))
    return out


def damping_vars(d):
    """The -var overrides of in.shear_* for a damping."""
    if d[0] == "viscous":
        return ["-var", "damping", "0", "-var", "gvisc", repr(d[1])]
    return ["-var", "damping", "1", "-var", "adamp", repr(d[1])]


def script_damping(path):
    """The default damping of an input script (its includes followed), from its
    'variable damping|gvisc|adamp index X' lines (in.shear_*: damping 0, gvisc 500 ->
    ('viscous', 500.0))."""
    v = common.params.read_variables(path)
    try:
        if common.params.number(v, "damping") > 0:
            return ("local", common.params.number(v, "adamp"))
        return ("viscous", common.params.number(v, "gvisc"))
    except (KeyError, ValueError) as e:
        raise SystemExit(f"{path}: {e}")


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
                   help="membrane 'every' of all sweeps but the every sweep (auto: the examples' default)")
    p.add_argument("--dts", type=floats, default=floats("1e-4,5e-5,2e-4,4e-4,8e-4"),
                   help="time steps of the rigid case (reference = --default-dt)")
    p.add_argument("--default-rate", type=float, default=0.01,
                   help="rate of the 'every', 'dt', 'damping' and 'ranks' sweeps (0.01)")
    p.add_argument("--default-dt", type=float, default=None,
                   help="time step of all runs but the dt sweep (default: the shear scripts' dt)")
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
    p.add_argument("--exe", default=common.EXE)
    p.add_argument("--prefix", default=os.path.join(HERE, "accuracy_sweep"),
                   help="output prefix: PREFIX.csv, PREFIX.json, PREFIX.png, PREFIX.md")
    p.add_argument("--time-axis", choices=("cpu", "wall"), default="cpu",
                   help="x axis of the plot and of the Pareto front: CPU time of the run "
                        "(user+sys; robust when others load the machine, default) or wall "
                        "time (the 'Loop time' sum); the table gives both")
    p.add_argument("--retry-failed", action="store_true", help="re-run runs recorded as failed")
    p.add_argument("--report-only", action="store_true", help="no runs: report what is in --workdir")
    p.add_argument("--from-csv", action="store_true",
                   help="no runs: the report again from PREFIX.csv and PREFIX.json alone")
    a = p.parse_args(argv)
    if a.jobs < 1:
        p.error("--jobs >= 1")
    a.sweeps = [s.strip() for s in a.sweeps.split(",") if s.strip()]
    unknown = set(a.sweeps) - {"rate", "every", "dt", "seed", "damping", "ranks"}
    if unknown:
        p.error(f"unknown sweep(s) {', '.join(sorted(unknown))}")
    if a.damping_rates is None:
        a.damping_rates = [a.default_rate]
    if a.default_dt is None:
        a.default_dt = common.script_number("in.shear_rigid", "dt")
    if any(n < 1 for n in a.ranks):
        p.error("--ranks >= 1")
    a.ranks = sorted(set(a.ranks) | {1})
    return a


# ----------------------------------------------------------------------------- plan
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
        self.name = run_name(case, seed, rate, dt, every, self.damping, args.default_damping[case], ranks)
        self.params = dict(case=case, seed=seed, rate=rate, dt=dt, every=every,
                           strain=args.strain, scale=args.scale, nout=self.nout,
                           script_sha=args.script_sha[case], exe_sha=args.exe_sha)
        if not self.default_damping:
            self.params["damping"] = damping_spec(self.damping)
        if ranks != 1:
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


class Plan:
    """The runs of the sweeps asked and the comparisons: entries (sweep, run, reference)."""

    def __init__(self, args):
        self.args, self.runs, self.entries = args, {}, []
        self.seed0, self.ref_rate = args.seeds[0], min(args.rates)
        self.every_d = args.default_every if args.default_every == "auto" else int(args.default_every)
        self.ref0 = {c: self.get(c, self.seed0, self.ref_rate) for c in ("rigid", "membrane")}
        for sweep in ("rate", "every", "dt", "seed", "damping", "ranks"):
            if sweep in args.sweeps:
                getattr(self, "plan_" + sweep)()
        if "rate" not in args.sweeps:      # the case references are in the CSV all the same
            self.entries[:0] = [("reference", r, r) for r in self.ref0.values()]

    def get(self, case, seed, rate, dt=None, every=None, damping=None, ranks=1):
        a = self.args
        r = Run(case, seed, rate, a.default_dt if dt is None else dt,
                (self.every_d if every is None else every) if case == "membrane" else 0, a,
                damping=damping, ranks=ranks)
        return self.runs.setdefault(r.key, r)

    def add(self, sweep, run, ref):
        self.entries.append((sweep, run, ref))

    def plan_rate(self):
        for c in self.ref0:
            for rate in sorted(self.args.rates):
                self.add("rate", self.get(c, self.seed0, rate), self.ref0[c])

    def plan_every(self):
        a = self.args
        ref = self.get("membrane", self.seed0, a.default_rate,
                       every=min([e for e in a.everys if e != "auto"] or [1]))
        for ev in sorted(a.everys, key=every_key):
            self.add("every", self.get("membrane", self.seed0, a.default_rate, every=ev), ref)

    def plan_dt(self):
        a = self.args
        ref = self.get("rigid", self.seed0, a.default_rate)
        for dt in sorted(a.dts):
            self.add("dt", self.get("rigid", self.seed0, a.default_rate, dt=dt), ref)

    def plan_seed(self):
        a = self.args
        if len(a.seeds) < 2:
            return
        seed2, others = a.seeds[1], sorted(set(a.scatter_rates) - {self.ref_rate})
        for c in self.ref0:
            self.add("seed", self.get(c, seed2, self.ref_rate), self.ref0[c])
        for rate in others:
            for c in self.ref0:
                self.add("seed@rate", self.get(c, seed2, rate), self.get(c, self.seed0, rate))
        # the same runs give the rate error on the second sample too (no extra run)
        if "rate" in a.sweeps:
            for rate in others:
                for c in self.ref0:
                    self.add("rate@seed2", self.get(c, seed2, rate), self.get(c, seed2, self.ref_rate))

    def plan_damping(self):
        # reference: the case reference of the rate sweep (slowest rate, default damping);
        # the default damping at a rate of the rate sweep is that very run
        for rate in sorted(self.args.damping_rates):
            for c in self.ref0:
                for d in self.args.dampings:
                    self.add("damping", self.get(c, self.seed0, rate, damping=d), self.ref0[c])

    def plan_ranks(self):
        for c in self.ref0:
            ref = self.get(c, self.seed0, self.args.default_rate, ranks=1)
            for n in self.args.ranks:
                self.add("ranks", self.get(c, self.seed0, self.args.default_rate, ranks=n), ref)

    def seeds(self):
        return sorted({r.seed for r in self.runs.values()}, key=self.args.seeds.index)


# ----------------------------------------------------------------------------- run
def shear_command(run, args, restart):
    mpi = common.mpi_command(run.ranks, args.mpirun) if run.ranks > 1 else []
    cmd = mpi + [args.exe_copy, "-in", run.script,
                 "-var", "restart", restart, "-var", "meshdir", MESHES,
                 "-var", "rate", repr(run.rate), "-var", "dt", repr(run.dt),
                 "-var", "eatarget", repr(args.strain), "-var", "nout", str(run.nout),
                 "-var", "ndump", str(run.ndump), "-var", "out", run.out,
                 "-log", os.path.join(run.dir, "log.shear")]
    if run.case == "membrane":
        cmd += ["-var", "every", str(run.every)]
    if not run.default_damping:
        cmd += damping_vars(run.damping)
    return cmd


def execute(run, args, restart):
    """Run (or reuse) one shear run; fills run.meta."""
    run.meta = common.known_meta(run.dir, run.params, "ok", args.retry_failed, args.report_only)
    if run.meta is not None:
        return run
    common.empty_folder(run.dir)
    cmd = shear_command(run, args, restart)
    timeout = 600 + run.nsteps * 0.02        # 20 ms/step: far above the expected ~1 ms
    loadavg = os.getloadavg()[0]
    log(f"  start {run.name}: {run.nsteps} steps, output every {run.nout}"
        + (f", {run.ranks} ranks" if run.ranks > 1 else ""))
    screen = os.path.join(run.dir, "screen.txt")
    # in the frozen scripts' folder, where LIGGGHTS finds their includes
    rc, wall, cpu = common.run_command(cmd, os.path.dirname(run.script), screen, timeout)
    tloop, nsteps = common.loop_times(os.path.join(run.dir, "log.shear"))
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
            + common.symptom(screen)
    meta.update(common.done_counts(text))
    common.write_context(os.path.join(run.dir, "meta.json"), meta)
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
    common.generate_sample(args.scale, seed, data)
    log(f"  prepare seed {seed}")
    screen = os.path.join(args.sampledir, f"screen.prepare_{seed}")
    rc, wall, _ = common.run_command([args.exe_copy, "-in", os.path.join(EXAMPLES, "in.prepare"),
                                      "-var", "data", data, "-var", "out", base, "-var", "meshdir", MESHES,
                                      "-log", os.path.join(args.sampledir, f"log.prepare_{seed}")],
                                     args.sampledir, screen, 7200)
    ok = [l for l in open(screen) if l.startswith("PREPARED porosity")]
    if rc != 0 or not ok:
        raise SystemExit(f"in.prepare failed for seed {seed} (rc {rc}): {common.symptom(screen)}")
    log(f"  prepared seed {seed} in {wall:.0f} s: {ok[0].strip()}")
    return base


def run_plan(plan, args):
    """Prepare the samples and execute the runs not in the cache."""
    runs = plan.runs.values()
    if not args.report_only and any(r.ranks > 1 for r in runs) and shutil.which(args.mpirun) is None:
        raise SystemExit(f"ranks sweep: no MPI launcher '{args.mpirun}' (--mpirun)")
    log(f"accuracy sweep: scale {args.scale:g}, strain {args.strain:g}, {len(runs)} runs "
        f"({sum(r.nsteps for r in runs)} steps), {args.jobs} job slots, 1 rank each"
        + (" (ranks sweep: N ranks take min(N, jobs) slots, after the 1-rank runs)"
           if any(r.ranks > 1 for r in runs) else "")
        + f"; executable {args.exe_copy} (sha256 {args.exe_sha})")
    seeds = plan.seeds()
    with cf.ThreadPoolExecutor(max_workers=min(args.jobs, 2)) as pool:
        restarts = dict(zip(seeds, pool.map(lambda s: prepare(s, args), seeds)))
    # 1-rank runs longest first, then the multi-rank runs: a run starts when its job
    # slots are free, in this order (a multi-rank run waits for them, so with --jobs 2
    # a 2- or 4-rank run has the machine's 2 cores to itself, as far as this script goes)
    run_all(sorted(runs, key=lambda r: (r.ranks > 1, r.ranks, -r.cost())), args, restarts)


# ----------------------------------------------------------------------------- collect
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
    r, ea = run.table["s1/s3"], run.table["ea"]
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
               damping=damping_spec(run.damping), ranks=run.ranks, reference=ref.name,
               is_reference=int(run is ref and sweep != "seed@rate"), status=m["status"],
               symptom=m.get("symptom", ""), steps=m.get("steps", ""),
               wall_s=m.get("loop_time_s", float("nan")), cpu_s=m.get("cpu_s", float("nan")),
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
    if sweep == "ranks":
        row["oversubscribed"] = int(run.ranks > int(m.get("cores") or os.cpu_count()))
        t1, tn = ref.meta.get("loop_time_s", np.nan), m.get("loop_time_s", np.nan)
        ok = m["status"] == "ok" and ref.meta["status"] == "ok" and tn > 0
        row["speedup"] = t1 / tn if ok else float("nan")
        row["efficiency"] = row["speedup"] / run.ranks
    return row


def collect(plan, args, invocations, took_min):
    """The rows (scatter rows and 'within scatter' included) and the context of the
    report, from the runs in the cache."""
    for r in plan.runs.values():
        load(r)
    rows = judge([row_for(sweep, run, ref, plan.ref0[run.case], args) for sweep, run, ref in plan.entries])
    options = {k: v for k, v in vars(args).items()
               if k not in ("exe_copy", "scripts", "script_sha", "exe_sha", "default_damping",
                            "sampledir", "rundir", "workdir", "exe", "prefix")}
    options["dampings"] = [damping_spec(d) for d in args.dampings]
    ctx = dict(argv=[a for a in args.argv if a != "--report-only"], args=options,
               exe_sha=args.exe_sha, script_sha=args.script_sha,
               default_damping={c: damping_spec(d) for c, d in args.default_damping.items()},
               rundir=os.path.relpath(args.rundir, ROOT), took_min=took_min,
               invocations=[dict(start=i["start"], wall_s=i["wall_s"], runs=len(i["runs"]))
                            for i in invocations],
               runs={r.name: dict(cores=r.meta.get("cores") or os.cpu_count(),
                                  loadavg_start=r.meta.get("loadavg_start"),
                                  time_split=common.time_split(os.path.join(r.dir, "log.shear")))
                     for r in plan.runs.values()})
    return rows, ctx


# ----------------------------------------------------------------------------- main
def freeze(args):
    """The sweep's folders, its copy of the executable and of the input scripts (by
    content hash) and the scripts' default damping."""
    args.sampledir = os.path.join(os.path.abspath(args.workdir), f"scale{tag(args.scale)}")
    args.rundir = os.path.join(args.sampledir, f"strain{tag(args.strain)}")
    os.makedirs(args.rundir, exist_ok=True)
    args.exe_copy, args.exe_sha = common.freeze_executable(args.exe, args.sampledir, args.report_only)
    args.scripts, args.script_sha = {}, {}
    for case in ("rigid", "membrane"):
        args.scripts[case], args.script_sha[case] = common.freeze_script(
            os.path.join(EXAMPLES, f"in.shear_{case}"), os.path.join(args.sampledir, "inputs"))
    # the damping the scripts use when no -var damping is given (the runs' default);
    # read from the examples (the copies' includes are those of examples/biaxial)
    args.default_damping = {c: script_damping(os.path.join(EXAMPLES, f"in.shear_{c}")) for c in args.scripts}


def sweep(args, t_start):
    """Plan, run the missing runs, collect: the report (common.finish_sweep)."""
    freeze(args)
    plan = Plan(args)
    run_plan(plan, args)
    return common.finish_sweep(plan.runs.values(), os.path.join(args.rundir, "invocations.json"), t_start,
                              lambda executed: dict(runs=executed, argv=args.argv),
                              lambda inv, took: collect(plan, args, inv, took), args.prefix, CSV_KEYS, report)


def main(argv):
    return common.sweep_main(argv, parse_args, report, sweep)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
