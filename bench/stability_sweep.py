#!/usr/bin/python3
"""Numerical-stability limits of the 2D DEM biaxial test (examples/biaxial).

    /usr/bin/python3 bench/stability_sweep.py [--scale 0.25] [--strain 0.02] [--rate 0.01]
        [--dt-fracs 0.1,0.2,0.3,0.5,0.7,1,1.5,2] [--alphas 0.25,0.5,1,2,4,8,16,32]
        [--p-factors 2,5,10,20,50,100] [--nramp 2000] [--kn-factors 0.01,0.1,1,10,100]
        [--loose-n0 0.18,0.20] [--sweeps dt,alpha,pressure,kn,loose] [--jobs 2]
        [--retry-failed] [--report-only] [--workdir out/stability_sweep]

One command: generates one small sample (generate_sample.py --scale 0.25, ~526
disks), prepares it with examples/biaxial/in.prepare, and pushes each numerical
parameter of the test until it fails, one MPI rank per run, at most --jobs runs at
a time:

  dt        in.shear_rigid and in.shear_membrane, -var dt = FRAC * sqrt(m_min/k_n)
            (m_min = pi r_min^2 rho of the prepared sample's smallest disk), plus the
            default 1e-4 s (the reference of every sweep)
  alpha     in.shear_rigid, -var alpha (side-wall servo gain G = alpha 1.075e-3/(k_n dt));
            also the servo error = RMS of s3/sigma3 - 1 over the output lines
  pressure  bench/in.stability_pressure: the membrane at 1e5 Pa on the still sample,
            then the pressure to FACTOR x 1e5 Pa as a jump or a linear ramp over
            --nramp steps (pressure v_p), held --nhold steps, platens still
  kn        both shears, -var kn = FACTOR x 8.45e7 at dt 1e-4 on the sample prepared
            at 8.45e7 (its overlaps give FACTOR x 100 kPa at the first step), and on
            samples prepared at that kn (in.prepare -var kn; --no-kn-prepared skips them)
  loose     in.prepare -var n0 N0 -var mugrow 0.9 (frictional growth: a looser sample),
            both shears at the default settings

Each run gets a status: ok; error (LIGGGHTS stopped with an ERROR line: the first one
is recorded); failed (crash, timeout or no completion line); unstable (it finished but
the output table shows a symptom: s1/s3 non-finite or > 50, KE blow-up, s3 servo error
> --servo-tol, membrane chain failures, energy not conserved). WARNING lines are
recorded deduplicated (the mesh-scaling and thermo_style warnings every run prints are
left out). Per run: steps, wall and CPU time, max inertial number I, peak s1/s3,
final ev, max KE, servo error, mean overlap f0/k_n, escaped disks, chain failures.

Writes bench/stability_sweep.csv (raw rows), bench/stability_sweep.md (a table per
sweep and the limits found) and bench/stability_sweep.png (one panel per sweep). Runs
already finished in --workdir with the same parameters, executable and input-script
hashes are reused (the executable is copied into --workdir at the start and hashed:
after a rebuild everything is re-run, samples included); --retry-failed re-runs the
runs that ended in an error, a crash or a timeout.
"""
import argparse
import concurrent.futures as cf
import csv
import json
import math
import os
import re
import shutil
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import accuracy_sweep as acc  # noqa: E402  (run_command, loop_times, sha, symptom, ...)
from accuracy_sweep import fmt, floats, log, run_command, sha, tag  # noqa: E402
from biaxial import readers  # noqa: E402  (scripts/ is on sys.path through accuracy_sweep)

ROOT = acc.ROOT
EXAMPLES = acc.EXAMPLES
KN0 = 8.45e7            # the examples' contact stiffness [N/m]
RHO = 2e8               # density [kg/m^3]
SIGMA = 1e5             # confining stress [Pa]
DT0 = 1e-4              # the examples' time step [s]
ALPHA0 = 0.5            # the examples' servo gain factor
# a number in a message (not the 2 of "membrane2d")
NUMBER = r"(?<![A-Za-z_\d])[-+]?\d[\d.]*(?:e[-+]?\d+)?"
# warnings every run prints, not about stability
BENIGN = ("Mesh for fix mesh/surface/stress has been scaled",
          "New thermo_style command, previous thermo_modify settings will be lost")


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scale", type=float, default=0.25, help="generate_sample.py --scale (0.25)")
    p.add_argument("--seed", type=int, default=12345)
    p.add_argument("--strain", type=float, default=0.02, help="final axial strain of the shears")
    p.add_argument("--rate", type=float, default=0.01, help="axial strain rate [1/s]")
    p.add_argument("--dstrain-out", type=float, default=1e-4,
                   help="axial strain between output lines of the shears (1e-4)")
    p.add_argument("--dt-fracs", type=floats, default=floats("0.1,0.2,0.3,0.5,0.7,1,1.5,2"),
                   help="time steps as fractions of sqrt(m_min/k_n)")
    p.add_argument("--alphas", type=floats, default=floats("0.25,0.5,1,2,4,8,16,32"),
                   help="side-wall servo gain factors of in.shear_rigid")
    p.add_argument("--p-factors", type=floats, default=floats("2,5,10,20,50,100"),
                   help="membrane pressure targets as multiples of 1e5 Pa")
    p.add_argument("--nramp", type=int, default=2000, help="steps of the pressure ramp")
    p.add_argument("--nhold", type=int, default=3000, help="steps after the jump/ramp")
    p.add_argument("--kn-factors", type=floats, default=floats("0.01,0.1,1,10,100"),
                   help="contact stiffness as multiples of 8.45e7 N/m (at dt 1e-4 s)")
    p.add_argument("--no-kn-prepared", dest="kn_prepared", action="store_false",
                   help="skip the samples prepared at each kn")
    p.add_argument("--loose-n0", type=floats, default=floats("0.18,0.20"),
                   help="in.prepare porosities to grow to (with -var mugrow 0.9)")
    p.add_argument("--sweeps", default="dt,alpha,pressure,kn,loose")
    p.add_argument("--servo-tol", type=float, default=0.05,
                   help="RMS of s3/sigma3 - 1 above which a rigid run counts as unstable (0.05)")
    p.add_argument("--ke-factor", type=float, default=100.0,
                   help="KE blow-up: max KE above this multiple of the default run's (100)")
    p.add_argument("--jobs", type=int, default=2, help="runs at a time, 1 rank each (2)")
    p.add_argument("--timeout", type=float, default=600.0, help="per run [s] (600)")
    p.add_argument("--workdir", default=os.path.join(ROOT, "out", "stability_sweep"))
    p.add_argument("--exe", default=os.path.join(ROOT, "build", "app", "liggghts-membrane"))
    p.add_argument("--prefix", default=os.path.join(HERE, "stability_sweep"),
                   help="output prefix: PREFIX.csv, PREFIX.png, PREFIX.md")
    p.add_argument("--retry-failed", action="store_true",
                   help="re-run runs (and preparations) that ended in an error, crash or timeout")
    p.add_argument("--report-only", action="store_true", help="no runs: report what is there")
    a = p.parse_args(argv)
    a.sweeps = [s.strip() for s in a.sweeps.split(",") if s.strip()]
    a.jobs = max(1, min(a.jobs, 2))
    return a


# ----------------------------------------------------------------------------- screen output
def messages(screen):
    """(first ERROR line, deduplicated WARNING lines without the benign ones)."""
    err, warns = "", []
    if os.path.exists(screen):
        for line in open(screen, errors="replace"):
            s = line.strip()
            if not err and "ERROR" in s:
                err = s[:600]
            elif s.startswith("WARNING") and not any(b in s for b in BENIGN) \
                    and s[:600] not in warns:
                warns.append(s[:600])
    return err, warns


def short(msg):
    """A message without its source location '(/path/file.cpp:123)'."""
    return re.sub(r"\s*\((?:[./\w-]+/)?[\w.-]+\.(?:cpp|h):\d+\)", "", msg).strip()


def read_table(path):
    """Columns by name of a '#'-headed table; incomplete lines are skipped."""
    header, rows = None, []
    if not os.path.exists(path):
        return None
    for line in open(path, errors="replace"):
        t = line.split()
        if not t:
            continue
        if t[0].startswith("#"):
            if not rows:
                header = line.lstrip("#").split()
            continue
        if header and len(t) == len(header):
            try:
                rows.append([float(w) for w in t])
            except ValueError:
                pass
    if header is None:
        return None
    d = np.array(rows, dtype=float).reshape(-1, len(header))
    return {h: d[:, k] for k, h in enumerate(header)}


# ----------------------------------------------------------------------------- samples
class Sample:
    """One prepared sample (generate_sample.py + in.prepare), reused by its meta.json."""

    def __init__(self, name, args, n0=None, mugrow=None, kn=None):
        self.name, self.n0, self.mugrow, self.kn = name, n0, mugrow, kn
        self.dir = os.path.join(args.workdir, "samples", name)
        self.data = os.path.join(args.workdir, "samples", f"sample_{args.seed}.data")
        self.restart = os.path.join(self.dir, "prepared.restart")
        self.vars = {k: v for k, v in (("n0", n0), ("mugrow", mugrow), ("kn", kn)) if v is not None}
        self.params = dict(scale=args.scale, seed=args.seed, vars={k: repr(v) for k, v in self.vars.items()},
                           prepare_sha=args.prepare_sha, generator_sha=args.generator_sha,
                           exe_sha=args.exe_sha)
        self.id = sha_text(json.dumps(self.params, sort_keys=True))
        self.meta = None

    @property
    def ok(self):
        return bool(self.meta) and self.meta.get("status") == "ok"


def sha_text(text):
    import hashlib
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def sample_geometry(data, ftot):
    """N, d_min, number-mean d after growth by ftot (data file at half size)."""
    d, inside = [], False
    for line in open(data):
        t = line.split()
        if not t:
            continue
        if t[0] == "Atoms":
            inside = True
            continue
        if inside:
            if not t[0].isdigit():
                break
            d.append(float(t[2]))
    d = np.array(d) * ftot
    return len(d), float(d.min()), float(d.mean())


def prepare(s, args):
    """Prepare sample s (or reuse it); fills s.meta. Never raises for a failed run."""
    metafile = os.path.join(s.dir, "meta.json")
    s.meta = acc.known_meta(s.dir, s.params, "ok", args)
    if s.meta is not None:
        return s
    os.makedirs(s.dir, exist_ok=True)
    if not os.path.exists(s.data):
        import subprocess
        subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "generate_sample.py"),
                        "--scale", repr(args.scale), "--seed", str(args.seed), "--out", s.data],
                       check=True, stdout=subprocess.DEVNULL)
    cmd = [args.exe_copy, "-in", args.scripts["prepare"], "-var", "data", s.data,
           "-var", "out", s.restart, "-var", "meshdir", os.path.join(EXAMPLES, "meshes"),
           "-log", "log.prepare"]
    for k, v in s.vars.items():
        cmd += ["-var", k, repr(v)]
    log(f"  prepare {s.name} {' '.join(f'{k} {v:g}' for k, v in s.vars.items())}")
    screen = os.path.join(s.dir, "screen.txt")
    rc, wall, cpu = run_command(cmd, s.dir, screen, args.timeout)
    text = open(screen, errors="replace").read()
    meta = dict(params=s.params, rc=rc, wall_s=wall, cpu_s=cpu, cmd=" ".join(cmd))
    m = re.search(r"PREPARED porosity after growth (\S+), after consolidation (\S+); C_n \([^)]*\) (\S+);", text)
    g = re.search(r"growth: diameters x (\S+)", text)
    e = re.search(r"equilibrium after step (\d+):.*ok = (\d)\)", text)
    err, warns = messages(screen)
    meta.update(error=err, warnings=warns)
    if rc == 0 and m and g and os.path.exists(s.restart):
        meta["porosity_grown"], meta["porosity"], meta["C_n"] = map(float, m.groups())
        meta["ftot"] = float(g.group(1))
        meta["N"], meta["d_min"], meta["d_mean"] = sample_geometry(s.data, meta["ftot"])
        meta["m_min"] = math.pi * (meta["d_min"] / 2) ** 2 * RHO
        meta["equilibrium"] = bool(e and e.group(2) == "1")
        meta["equilibrium_step"] = int(e.group(1)) if e else None
        meta["status"], meta["symptom"] = "ok", ""
    else:
        meta["status"] = "error" if err else "failed"
        meta["symptom"] = ("timeout after %.0f s: " % wall if rc == "timeout" else f"rc {rc}: ") \
            + (err or acc.symptom(screen))
    json.dump(meta, open(metafile, "w"), indent=1)
    s.meta = meta
    log(f"  prepared {s.name} in {wall:.0f} s: {meta['status']}"
        + (f", porosity {meta['porosity']:.4f}" if "porosity" in meta else f" ({meta['symptom']})"))
    return s


# ----------------------------------------------------------------------------- runs
class Run:
    """One run: a shear (rigid/membrane) or a pressure change (bench/in.stability_pressure)."""

    def __init__(self, case, sample, args, dt=DT0, alpha=ALPHA0, kn=KN0, pfac=None, nramp=None):
        self.case, self.sample = case, sample
        self.dt, self.alpha, self.kn, self.pfac, self.nramp = dt, alpha, kn, pfac, nramp
        if case == "pressure":
            self.name = f"pressure_{sample.name}_x{tag(pfac)}_" + (f"ramp{nramp}" if nramp else "jump")
            self.nsteps = nramp + args.nhold
            self.vars = dict(ptarget=repr(pfac * SIGMA), nramp=str(nramp), nhold=str(args.nhold),
                             nout="21", dt=repr(dt), kn=repr(kn), guard=str(int(args.has_guard)))
            self.script = args.scripts["pressure"]
        else:
            self.name = f"{case}_{sample.name}_dt{dt:.4g}_a{tag(alpha)}_kn{kn:.4g}"
            self.nsteps = int(math.ceil(args.strain / (args.rate * dt)))
            # odd: a period-2 oscillation (an unstable servo) alternates between lines
            # instead of being sampled at the same phase every time
            nout = max(1, int(round(args.dstrain_out / (args.rate * dt)))) | 1
            self.vars = dict(rate=repr(args.rate), eatarget=repr(args.strain), dt=repr(dt),
                             kn=repr(kn), nout=str(nout), ndump="100000000")
            if case == "rigid":
                self.vars["alpha"] = repr(alpha)
            self.script = args.scripts[case]
        self.dir = os.path.join(args.workdir, "runs", self.name)
        self.out = os.path.join(self.dir, "out.txt")
        self.params = dict(case=case, sample=sample.id, vars=self.vars,
                           script_sha=args.script_sha[case if case != "pressure" else "pressure"],
                           exe_sha=args.exe_sha)
        self.meta = None
        self.res = {}

    def cost(self):
        return self.nsteps + (5000 if self.case == "membrane" else 0)


def execute(run, args):
    """Run (or reuse) one run; fills run.meta (what the process did)."""
    metafile = os.path.join(run.dir, "meta.json")
    run.meta = acc.cached_meta(metafile, run.params, "finished", args.retry_failed)
    if run.meta is not None:
        return run
    if not run.sample.ok and run.sample.meta.get("status") != "not run":
        run.meta = dict(params=run.params, status="failed", error="", warnings=[],
                        symptom=f"sample {run.sample.name} not prepared: {run.sample.meta.get('symptom', '')}")
        return run
    if args.report_only:
        run.meta = dict(params=run.params, status="not run", symptom="not run", error="", warnings=[])
        return run
    os.makedirs(run.dir, exist_ok=True)
    for f in os.listdir(run.dir):
        os.remove(os.path.join(run.dir, f))
    cmd = [args.exe_copy, "-in", run.script, "-var", "restart", run.sample.restart,
           "-var", "meshdir", os.path.join(EXAMPLES, "meshes"), "-var", "out", run.out,
           "-log", "log.run"]
    for k, v in run.vars.items():
        cmd += ["-var", k, v]
    screen = os.path.join(run.dir, "screen.txt")
    rc, wall, cpu = run_command(cmd, run.dir, screen, args.timeout)
    tloop, nsteps = acc.loop_times(os.path.join(run.dir, "log.run"))
    text = open(screen, errors="replace").read()
    done = [l for l in text.splitlines() if l.startswith(("SHEAR done", "PRESSURE done"))]
    err, warns = messages(screen)
    meta = dict(params=run.params, rc=rc, wall_s=wall, cpu_s=cpu, loop_time_s=tloop,
                loop_steps=nsteps, done_line=done[-1] if done else "", error=err,
                warnings=warns, cmd=" ".join(cmd))
    if rc == "timeout":
        meta["status"], meta["symptom"] = "failed", f"timeout after {wall:.0f} s"
    elif err:
        meta["status"], meta["symptom"] = "error", err
    elif rc != 0 or not done:
        meta["status"], meta["symptom"] = "failed", f"rc {rc}: " + acc.symptom(screen)
    else:
        meta["status"], meta["symptom"] = "finished", ""
    m = re.search(r"escaped (\S+) chain failures (\S+)", meta["done_line"])
    if m:
        meta["escaped"], meta["chain_failures"] = float(m.group(1)), float(m.group(2))
    json.dump(meta, open(metafile, "w"), indent=1)
    meta["executed_now"] = True
    run.meta = meta
    log(f"  {run.name}: {meta['status']} in {wall:.1f} s" + (f" ({short(meta['symptom'])[:120]})"
                                                              if meta["symptom"] else ""))
    return run


# ----------------------------------------------------------------------------- analysis
def nanmax(x):
    x = np.asarray(x, float)
    return float(np.nanmax(x)) if x.size and np.isfinite(x).any() else float("nan")


def error_step(run):
    """The step named by the ERROR line ('at step N'), else None."""
    m = re.search(r"at step (\d+)", run.meta.get("error", "") or "")
    return int(m.group(1)) if m else None


def measure(run, args):
    """Numbers from the run's output table (also of a failed run: what it wrote)."""
    r = dict(steps=0, steps_planned=run.nsteps, I_max=float("nan"), peak_ratio=float("nan"),
             final_ev=float("nan"), KE_max=float("nan"), servo_rms=float("nan"),
             servo_max=float("nan"), servo_lag1=float("nan"), overlap_mean=float("nan"), overlap_max=float("nan"),
             ea_end=float("nan"), table_symptom="", escaped=run.meta.get("escaped", float("nan")),
             chain_failures=run.meta.get("chain_failures", float("nan")),
             widenings=float("nan"), s1_end=float("nan"), energy_ratio=float("nan"))
    s = run.sample.meta or {}
    dmean, dmin = s.get("d_mean", float("nan")), s.get("d_min", float("nan"))
    if run.case == "pressure":
        t = read_table(run.out)
        if not t or not len(t["step"]):
            return r
        last = max(t["step"][-1], error_step(run) or 0)
        r["steps"] = run.nsteps if run.meta["status"] == "finished" else int(last - t["step"][0])
        ke = t["KE"]
        r["KE_max"] = nanmax(ke)
        r["overlap_max"] = nanmax(t["dmax"]) / dmin       # relative to the smallest disk
        r["overlap_mean"] = nanmax(t["dmean"]) / dmean     # relative to the mean diameter
        r["escaped"] = nanmax(t["escaped"])
        r["chain_failures"] = float(t["failures"][-1])
        r["widenings"] = float(t["widenings"][-1])
        r["s1_end"] = float(t["s1"][-1])
        r["atoms_lost"] = float(t["atoms"][0] - np.nanmin(t["atoms"]))
        # energy check: KE can never exceed the kinetic + elastic energy at the start plus
        # the work of the membrane (-int p dA) and of the platens since then
        wmem = -np.concatenate([[0.0], np.cumsum(0.5 * (t["p"][1:] + t["p"][:-1]) * np.diff(t["area"]))])
        h = t["H"]
        wpl = -np.concatenate([[0.0], np.cumsum(0.5 * (t["s1"][1:] * t["area"][1:] / h[1:]
                                                         + t["s1"][:-1] * t["area"][:-1] / h[:-1])
                                                  * np.diff(h))])
        nc = t["dsum"][0] / max(t["dmean"][0], 1e-30)
        eel0 = 0.5 * run.kn * nc * t["dmean"][0] ** 2     # >= by Jensen: x2 below
        avail = ke[0] + 2.0 * eel0 + max(nanmax(wmem + wpl), 0.0)
        r["energy_ratio"] = r["KE_max"] / avail if avail > 0 else float("nan")
        bad = []
        if not np.all(np.isfinite(ke)):
            bad.append("KE non-finite")
        elif r["energy_ratio"] > 1.0:
            bad.append(f"KE {r['KE_max']:.3g} J > energy available {avail:.3g} J (stored + work)")
        if r["atoms_lost"] > 0:
            bad.append(f"{r['atoms_lost']:g} atoms lost")
        if r["chain_failures"] > 0:
            bad.append(f"membrane chain lost {r['chain_failures']:g} times (f_mem[12])")
        r["table_symptom"] = "; ".join(bad)
        return r
    try:
        t = readers.read_output(run.out)
    except (ValueError, OSError):
        return r
    if not len(t):
        return r
    ea, ratio = t["ea"], t["s1/s3"]
    r["first_step"] = int(t["step"][0])
    # the first line is written after a 1-step run; the last one at a multiple of nout
    last = max(t["step"][-1], error_step(run) or 0)
    r["steps"] = run.nsteps if run.meta["status"] == "finished" else int(last - t["step"][0] + 1)
    r["ea_end"] = float(ea[-1])
    r["I_max"] = nanmax(t["I"])
    r["peak_ratio"] = nanmax(ratio)
    r["final_ev"] = float(t["ev"][-1])
    r["KE_max"] = nanmax(t["KE"])
    if run.case == "rigid":
        dev = t["s3"] / SIGMA - 1.0
        r["servo_rms"] = float(np.sqrt(np.mean(dev ** 2)))
        r["servo_max"] = float(np.max(np.abs(dev)))
        x = dev[np.isfinite(dev)] - np.nanmean(dev)
        r["servo_lag1"] = float(np.mean(x[1:] * x[:-1]) / np.var(x)) if len(x) > 2 and np.var(x) > 0 \
            else float("nan")
    if t.has("f0"):
        r["overlap_mean"] = nanmax(t["f0"] / run.kn) / dmean
    bad = []
    nonfin = ~np.isfinite(ratio) | (np.abs(ratio) > 50)
    if nonfin.any():
        k = int(np.nonzero(nonfin)[0][0])
        why = ""
        if np.isfinite(t["s3"][k]) and abs(t["s3"][k]) < 0.01 * SIGMA:
            why = (f": s3 = {t['s3'][k]:.3g} Pa there, the sample lost contact with the "
                   + ("side walls" if run.case == "rigid" else "membrane"))
        bad.append(f"s1/s3 non-finite or > 50 from ε = {100 * ea[k]:.2f} % "
                   f"(max {nanmax(np.abs(ratio)):.3g}){why}")
    return r | dict(table_symptom="; ".join(bad))


def classify(run, ref, args):
    """Status and how it fails, from the process (run.meta) and the table (run.res)."""
    m, r = run.meta, run.res
    bad = [r["table_symptom"]] if r.get("table_symptom") else []
    if run.case != "pressure":
        kref = ref.res.get("KE_max", float("nan")) if ref is not None else float("nan")
        r["KE_ratio"] = r["KE_max"] / kref if kref and np.isfinite(kref) else float("nan")
        if np.isfinite(r["KE_max"]) and r["KE_ratio"] > args.ke_factor:
            bad.append(f"KE blow-up: max KE {r['KE_max']:.3g} J = {r['KE_ratio']:.3g} × the default "
                       f"run's (> {args.ke_factor:g}×)")
        if run.case == "rigid" and r["servo_rms"] > args.servo_tol:
            lag = r.get("servo_lag1", float("nan"))
            kind = (f"σ3 oscillates step to step (period 2: lag-1 correlation {lag:.2f} of the "
                    "s3 lines, written every odd number of steps)" if lag < -0.5 else
                    "σ3 off its target (an offset, or an oscillation whose period the output "
                    "interval does not resolve)")
            bad.append(f"{kind}: RMS(s3/σ3 − 1) = {100 * r['servo_rms']:.1f} % "
                       f"(max {100 * r['servo_max']:.0f} %)")
        if run.case == "membrane" and (r.get("chain_failures") or 0) > 0:
            bad.append(f"membrane chain lost {r['chain_failures']:g} times (f_mem[12])")
        if m["status"] == "finished" and np.isfinite(r["ea_end"]) and r["ea_end"] < 0.99 * args.strain:
            bad.append(f"stopped at ε = {100 * r['ea_end']:.2f} %")
        pref = ref.res.get("peak_ratio", float("nan")) if ref is not None else float("nan")
        r["d_peak"] = r["peak_ratio"] - pref
    else:
        r["KE_ratio"] = r["energy_ratio"]
        r["d_peak"] = float("nan")
    if m["status"] == "finished":
        status = "unstable" if bad else "ok"
        how = "; ".join(bad)
    elif m["status"] == "not run":
        status, how = "not run", "not run"
    else:
        status = m["status"]                 # error / failed
        how = short(m.get("symptom", ""))
        es = error_step(run)
        if run.case == "membrane" and es is not None and es < r.get("first_step", es + 1):
            how = "in the membrane's settling before shear: " + how
        if bad:
            how += " [table: " + "; ".join(bad) + "]"
    if status != "ok" and not how:
        how = "no message"
    r["status"], r["how"] = status, how
    return r


# ----------------------------------------------------------------------------- output
CSV_KEYS = ["sweep", "case", "sample", "setting", "x", "dt", "dt_frac", "alpha", "kn", "kn_factor",
            "p_factor", "mode", "status", "how", "error", "warnings", "steps", "steps_planned",
            "wall_s", "cpu_s", "I_max", "peak_ratio", "d_peak", "final_ev", "KE_max", "KE_ratio",
            "servo_rms", "servo_max", "servo_lag1", "overlap_mean", "overlap_max", "escaped", "chain_failures",
            "widenings", "s1_end", "porosity", "run"]


def row_for(sweep, x, setting, run, args):
    m, r = run.meta, run.res
    s = run.sample.meta or {}
    sq = math.sqrt(s["m_min"] / run.kn) if s.get("m_min") else float("nan")
    return dict(sweep=sweep, case=run.case, sample=run.sample.name, setting=setting, x=x,
                dt=run.dt, dt_frac=run.dt / sq, alpha=run.alpha if run.case == "rigid" else "",
                kn=run.kn, kn_factor=run.kn / KN0,
                p_factor=run.pfac if run.pfac else "",
                mode=("" if run.case != "pressure" else ("ramp %d" % run.nramp if run.nramp else "jump")),
                status=r["status"], how=r["how"], error=m.get("error", ""),
                warnings=" | ".join(m.get("warnings", [])), steps=r["steps"],
                steps_planned=r["steps_planned"], wall_s=m.get("wall_s", float("nan")),
                cpu_s=m.get("cpu_s", float("nan")), I_max=r["I_max"], peak_ratio=r["peak_ratio"],
                d_peak=r["d_peak"], final_ev=r["final_ev"], KE_max=r["KE_max"],
                KE_ratio=r["KE_ratio"], servo_rms=r["servo_rms"], servo_max=r["servo_max"],
                servo_lag1=r["servo_lag1"],
                overlap_mean=r["overlap_mean"], overlap_max=r["overlap_max"],
                escaped=r["escaped"], chain_failures=r["chain_failures"],
                widenings=r["widenings"], s1_end=r["s1_end"],
                porosity=s.get("porosity", float("nan")), run=run.name)


def warn_text(row, limit=3):
    """The warnings of a row, grouped by their text with the numbers taken out: the first
    of each group, with the number of similar ones (other disks, steps, values)."""
    groups = {}
    for x in row["warnings"].split(" | "):
        if x:
            x = short(x)
            groups.setdefault(re.sub(NUMBER, "#", x), []).append(x)
    out = [g[0][:170] + ("…" if len(g[0]) > 170 else "") + (f" (×{len(g)} similar)" if len(g) > 1 else "")
           for g in groups.values()]
    more = f" (+{len(out) - limit} more kinds)" if len(out) > limit else ""
    return "; ".join(out[:limit]) + more


def table(rows, cols):
    """Markdown table of rows with (title, function of row) columns."""
    out = ["| " + " | ".join(c for c, _ in cols) + " |", "|" + "---|" * len(cols)]
    for r in rows:
        out.append("| " + " | ".join(str(f(r)).replace("|", "/") for _, f in cols) + " |")
    return "\n".join(out)


def status_text(r):
    s = f"**{r['status']}**"
    if r["how"]:
        s += ": " + r["how"][:300]
    return s


COMMON = [("status: how it fails", status_text),
          ("warnings (dedup.)", warn_text),
          ("steps / planned", lambda r: f"{r['steps']} / {r['steps_planned']}"),
          ("wall [s]", lambda r: fmt(r["wall_s"], "{:.1f}")),
          ("I_max", lambda r: fmt(r["I_max"], "{:.2g}")),
          ("peak σ1/σ3", lambda r: fmt(r["peak_ratio"], "{:.3g}")),
          ("Δpeak vs default", lambda r: fmt(r["d_peak"], "{:+.3g}")),
          ("final ε_v [%]", lambda r: fmt(r["final_ev"], "{:.2f}", 100)),
          ("max KE [J]", lambda r: fmt(r["KE_max"], "{:.3g}")),
          ("KE / default", lambda r: fmt(r["KE_ratio"], "{:.3g}"))]


def largest_ok(rows, key):
    """Largest value of key with it and every smaller value ok."""
    best = None
    for r in sorted(rows, key=lambda r: r[key]):
        if r["status"] != "ok":
            break
        best = r
    return best


def first_bad(rows, key):
    for r in sorted(rows, key=lambda r: r[key]):
        if r["status"] != "ok":
            return r
    return None


def plot(rows, path, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = [("dt", "dt / sqrt(m_min/k_n)", "KE_max", "max KE [J]"),
              ("alpha", "servo gain factor α (rigid)", "servo_rms", "RMS(s3/σ3 − 1)"),
              ("pressure", "target / initial membrane pressure", "KE_max", "max KE [J]"),
              ("kn", "k_n / 8.45e7 (dt 1e-4 s)", "KE_max", "max KE [J]"),
              ("kn", "k_n / 8.45e7 (dt 1e-4 s)", "overlap_mean", "max mean overlap f̄₀/k_n / d̄"),
              ("loose", "porosity at 100 kPa", "peak_ratio", "peak σ1/σ3")]
    fig, axes = plt.subplots(2, 3, figsize=(16, 9.5))
    colors = {"rigid": "C0", "membrane": "C1", "jump": "C3", "ramp": "C2"}
    for ax, (sweep, xl, yk, yl) in zip(axes.flat, panels):
        sel = [r for r in rows if r["sweep"].split(" ")[0] == sweep]
        if not sel:
            ax.set_visible(False)
            continue
        groups = {}
        for r in sel:
            g = r["case"] if r["case"] != "pressure" else r["mode"].split(" ")[0]
            if r["sweep"].endswith("(prepared at kn)"):
                g += ", prepared at kn"
            groups.setdefault(g, []).append(r)
        ys = [r[yk] for r in sel if isinstance(r[yk], float) and np.isfinite(r[yk]) and r[yk] > 0]
        top = max(ys) * 3 if ys else 1.0
        ymax_ok = max([r[yk] for r in sel if r["status"] == "ok" and np.isfinite(r[yk])] or [0.0])
        for g, rs in groups.items():
            rs = sorted(rs, key=lambda r: r["x"])
            col = colors.get(g.split(",")[0], "k")
            ls = "--" if "prepared" in g else "-"
            ok = [r for r in rs if r["status"] in ("ok", "unstable") and np.isfinite(r[yk]) and r[yk] > 0]
            ax.plot([r["x"] for r in ok], [r[yk] for r in ok], ls, color=col, marker="o", label=g)
            for r in rs:
                if r["status"] == "ok":
                    continue
                uns = r["status"] == "unstable"
                # an error stops the run early: its partial value means something only
                # when it is above the stable runs' (a blow-up); else the marker goes on top
                y = r[yk] if np.isfinite(r[yk]) and r[yk] > 0 and (uns or r[yk] > ymax_ok) else top

                style = dict(marker="D", s=70, facecolors="none", edgecolors="r") if uns else \
                    dict(marker="x", s=90, color="r")
                ax.scatter([r["x"]], [y], zorder=4, label="unstable" if uns else "error / failed",
                           **style)
                ax.annotate(r["status"][0], (r["x"], y), fontsize=7, color="r",
                            xytext=(4, 4), textcoords="offset points")
        if sweep == "alpha":
            ax.axhline(args.servo_tol, color="r", lw=0.8, ls=":", label=f"--servo-tol {args.servo_tol:g}")
        if sweep == "dt":
            ax.axvline(DT0 / math.sqrt(rows[0]["_m_min"] / KN0), color="k", lw=0.8, ls=":",
                       label="default 1e-4 s")
        if sweep != "loose":
            ax.set_xscale("log")
        if yk != "peak_ratio":
            ax.set_yscale("log")
        ax.set_xlabel(xl)
        ax.set_ylabel(yl)
        ax.set_title(f"{sweep} sweep" if sweep != "kn" or yk == "KE_max" else "kn sweep: overlaps")
        ax.grid(True, which="both", alpha=0.3)
        h, lab = ax.get_legend_handles_labels()
        u = dict(zip(lab, h))
        ax.legend(u.values(), u.keys(), fontsize=7)
    fig.suptitle("Stability sweeps of the biaxial test (red ◇: unstable, red x: error / failed, "
                 "at the top when the run wrote no value; letters u/e/f = status)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


# ----------------------------------------------------------------------------- main
def main(argv):
    args = parse_args(argv)
    t_start = time.time()
    args.workdir = os.path.abspath(args.workdir)
    os.makedirs(os.path.join(args.workdir, "inputs"), exist_ok=True)
    args.exe_copy = os.path.join(args.workdir, "liggghts-membrane")
    if not args.report_only:
        shutil.copy2(args.exe, args.exe_copy + ".new")
        os.replace(args.exe_copy + ".new", args.exe_copy)
    args.exe_sha = sha(args.exe_copy) if os.path.exists(args.exe_copy) else "?"
    args.scripts, args.script_sha = {}, {}
    for key, src in (("prepare", os.path.join(EXAMPLES, "in.prepare")),
                     ("rigid", os.path.join(EXAMPLES, "in.shear_rigid")),
                     ("membrane", os.path.join(EXAMPLES, "in.shear_membrane")),
                     ("pressure", os.path.join(HERE, "in.stability_pressure"))):
        args.script_sha[key] = sha(src)
        args.scripts[key] = os.path.join(args.workdir, "inputs",
                                         f"{os.path.basename(src)}.{args.script_sha[key]}")
        if not os.path.exists(args.scripts[key]):
            shutil.copy2(src, args.scripts[key])
    args.generator_sha = sha(os.path.join(ROOT, "scripts", "generate_sample.py"))
    inv_file = os.path.join(args.workdir, "invocations.json")
    invocations = json.load(open(inv_file)) if os.path.exists(inv_file) else []
    if args.report_only and invocations:
        # report what the last invocation ran, even if the examples or the build have
        # changed since (a colleague editing them): its hashes select its runs
        last = invocations[-1]
        args.exe_sha = last.get("exe_sha", args.exe_sha)
        args.generator_sha = last.get("generator_sha", args.generator_sha)
        for key, h in last.get("script_sha", {}).items():
            args.scripts[key] = re.sub(r"\.[0-9a-f]{12}$", f".{h}", args.scripts[key])
            args.script_sha[key] = h
    args.prepare_sha = args.script_sha["prepare"]
    # the project's fix stability/guard (if the examples use it, the build has it):
    # bench/in.stability_pressure then uses it too
    args.has_guard = "stability/guard" in open(args.scripts["rigid"]).read()

    log(f"stability sweep: scale {args.scale:g}, strain {args.strain:g} at {args.rate:g} /s, "
        f"sweeps {','.join(args.sweeps)}; executable {args.exe_copy} (sha256 {args.exe_sha})")
    pool = cf.ThreadPoolExecutor(max_workers=args.jobs)

    # samples: the dense one first (its smallest disk sets the dt fractions)
    dense = prepare(Sample("dense", args), args)
    if not dense.ok:
        raise SystemExit(f"preparation of the dense sample failed: {dense.meta.get('symptom')}")
    m_min = dense.meta["m_min"]
    sq0 = math.sqrt(m_min / KN0)
    log(f"  dense sample: {dense.meta['N']} disks, porosity {dense.meta['porosity']:.4f}, "
        f"d_min {1e3 * dense.meta['d_min']:.3f} mm, m_min {m_min:.4g} kg, "
        f"sqrt(m_min/k_n) {sq0:.4g} s (default dt = {DT0 / sq0:.3f} of it)")
    samples = {}
    if "kn" in args.sweeps and args.kn_prepared:
        for f in args.kn_factors:
            if f != 1:
                samples[("kn", f)] = Sample(f"kn{tag(f)}", args, kn=f * KN0)
    if "loose" in args.sweeps:
        for n0 in args.loose_n0:
            samples[("loose", n0)] = Sample(f"loose_n{tag(n0)}", args, n0=n0, mugrow=0.9)
    list(pool.map(lambda s: prepare(s, args), samples.values()))

    runs = {}

    def get(case, sample=dense, **kw):
        r = Run(case, sample, args, **kw)
        return runs.setdefault(r.name, r)

    plan = []     # (sweep, x, setting, run)
    shear = ("rigid", "membrane")
    for c in shear:
        plan.append(("default", 1.0, "default (dt 1e-4 s, α 0.5, k_n 8.45e7)", get(c)))
    if "dt" in args.sweeps:
        for c in shear:
            plan.append(("dt", DT0 / sq0, f"dt 1e-4 s = {DT0 / sq0:.3f} (default)", get(c)))
            for f in args.dt_fracs:
                plan.append(("dt", f, f"{f:g} × √(m/k) = {f * sq0:.3g} s", get(c, dt=float(f"{f * sq0:.6g}"))))
    if "alpha" in args.sweeps:
        for a in sorted(set(args.alphas) | {ALPHA0}):
            plan.append(("alpha", a, f"α {a:g}" + (" (default)" if a == ALPHA0 else ""), get("rigid", alpha=a)))
    if "pressure" in args.sweeps:
        for f in args.p_factors:
            for nr in (0, args.nramp):
                plan.append(("pressure", f, f"1e5 → {f * SIGMA:.3g} Pa ({f:g}×), "
                             + (f"ramp {nr} steps" if nr else "jump"),
                             get("pressure", pfac=f, nramp=nr)))
    if "kn" in args.sweeps:
        for c in shear:
            for f in args.kn_factors:
                plan.append(("kn", f, f"k_n × {f:g}" + (" (default)" if f == 1 else ""), get(c, kn=f * KN0)))
        if args.kn_prepared:
            for c in shear:
                for f in args.kn_factors:
                    s = dense if f == 1 else samples[("kn", f)]
                    plan.append(("kn (prepared at kn)", f, f"k_n × {f:g}, sample prepared at it",
                                 get(c, s, kn=f * KN0)))
    if "loose" in args.sweeps:
        for c in shear:
            plan.append(("loose", dense.meta["porosity"], "dense (n0 0.12, mugrow 0)", get(c)))
            for n0 in args.loose_n0:
                s = samples[("loose", n0)]
                plan.append(("loose", s.meta.get("porosity", float("nan")),
                             f"n0 {n0:g}, mugrow 0.9", get(c, s)))

    todo = sorted(runs.values(), key=lambda r: -r.cost())
    log(f"  {len(runs)} runs, {args.jobs} at a time, 1 rank each, timeout {args.timeout:.0f} s")
    for f in cf.as_completed([pool.submit(execute, r, args) for r in todo]):
        f.result()
    pool.shutdown()

    for r in runs.values():
        r.res = measure(r, args)
    refs = {c: runs[get(c).name] for c in shear}
    for r in runs.values():
        r.res.update(classify(r, refs.get(r.case), args))

    executed = [r.name for r in runs.values() if r.meta.get("executed_now")]
    if executed:
        invocations.append(dict(start=time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(t_start)),
                                wall_s=time.time() - t_start, runs=len(executed), argv=argv,
                                exe_sha=args.exe_sha, script_sha=args.script_sha,
                                generator_sha=args.generator_sha))
        json.dump(invocations, open(inv_file, "w"), indent=1)

    rows = [row_for(sw, x, st, run, args) for sw, x, st, run in plan]
    for r in rows:
        r["_m_min"] = m_min
    with open(args.prefix + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, CSV_KEYS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    plot(rows, args.prefix + ".png", args)
    md = report(rows, samples, dense, sq0, invocations, executed, t_start, argv, args)
    open(args.prefix + ".md", "w").write(md)
    print(md)
    return 0


def report(rows, samples, dense, sq0, invocations, executed, t_start, argv, args):
    by = lambda sw, c=None: [r for r in rows if r["sweep"] == sw and (c is None or r["case"] == c)]  # noqa: E731
    limits, notes = [], []

    def fail(r, label):
        return f"{label}: {r['status']}: {r['how'][:170]}"

    # --- dt
    for c in ("rigid", "membrane"):
        rs = by("dt", c)
        if rs:
            b, bad = largest_ok(rs, "x"), first_bad(rs, "x")
            limits.append((f"time step, {c}",
                           f"{b['x']:.3g} × √(m_min/k_n) = {b['dt']:.3g} s "
                           f"({b['dt'] / DT0:.3g} × the default 1e-4 s)" if b else "none",
                           fail(bad, f"{bad['x']:.3g} × ({bad['dt']:.3g} s)") if bad else "none failed"))
    rs = by("alpha")
    if rs:
        b, bad = largest_ok(rs, "x"), first_bad(rs, "x")
        limits.append(("side-wall servo gain α (rigid)",
                       f"α {b['x']:g} (servo error RMS {100 * b['servo_rms']:.2g} %)" if b else "none",
                       fail(bad, f"α {bad['x']:g}") if bad else "none failed"))
    for mode in ("jump", "ramp"):
        rs = [r for r in by("pressure") if r["mode"].startswith(mode)]
        if rs:
            b, bad = largest_ok(rs, "x"), first_bad(rs, "x")
            limits.append((f"membrane pressure {mode}" + (f" over {args.nramp} steps" if mode == "ramp" else "")
                           + " from 1e5 Pa",
                           f"{b['x']:g}× = {b['x'] * SIGMA:.3g} Pa (max KE {b['KE_max']:.3g} J, escaped "
                           f"{fmt(b['escaped'], '{:g}')}, max δ/d_min {fmt(b['overlap_max'], '{:.2f}')})"
                           if b else "none",
                           fail(bad, f"{bad['x']:g}×") if bad else "none failed"))
    for sw in ("kn", "kn (prepared at kn)"):
        for c in ("rigid", "membrane"):
            rs = by(sw, c)
            if rs:
                ok = sorted([r for r in rs if r["status"] == "ok"], key=lambda r: r["x"])
                bads = sorted([r for r in rs if r["status"] != "ok"], key=lambda r: r["x"])
                limits.append((f"k_n at dt 1e-4 s, {c}" + (", sample prepared at that k_n" if "prepared" in sw
                                                            else ", sample prepared at 8.45e7"),
                               ("ok at " + ", ".join(f"× {r['x']:g}" for r in ok)) if ok else "none",
                               "; ".join(fail(r, f"× {r['x']:g}")[:130] for r in bads) or "none failed"))
    for c in ("rigid", "membrane"):
        for r in [r for r in by("loose", c) if r["sample"] != "dense"]:
            limits.append((f"loose sample {r['setting']}, {c}",
                           f"{r['status']}: porosity {fmt(r['porosity'], '{:.4f}')} (dense "
                           f"{dense.meta['porosity']:.4f}), peak σ1/σ3 {fmt(r['peak_ratio'], '{:.2f}')} "
                           f"({fmt(r['d_peak'], '{:+.2f}')} vs dense), final ε_v {fmt(r['final_ev'], '{:.2f}', 100)} %"
                           + (f", escaped {fmt(r['escaped'], '{:g}')}, chain failures "
                              f"{fmt(r['chain_failures'], '{:g}')}" if c == "membrane" else ""),
                           (r["how"] or "—")[:170]))

    # --- what the stable runs say about accuracy, and which guards fired where
    for c in ("rigid", "membrane"):
        ok = [r for r in by("dt", c) if r["status"] == "ok"]
        if len(ok) > 1:
            lo, hi = min(ok, key=lambda r: r["peak_ratio"]), max(ok, key=lambda r: r["peak_ratio"])
            notes.append(f"- Peak σ1/σ3 of the stable time-step runs, {c}: {lo['peak_ratio']:.2f} "
                         f"(dt {lo['x']:.3g} × √(m/k)) to {hi['peak_ratio']:.2f} ({hi['x']:.3g} ×), without a "
                         "trend in dt: on this small sample the peak of one run is sensitive to any "
                         "perturbation, so Δpeak is no accuracy measure here (bench/accuracy_sweep.py "
                         "compares runs with the sample-to-sample scatter).")
    kinds = {}
    for r in {r["run"]: r for r in rows}.values():
        for w in {re.sub(NUMBER, "#", short(x))[:90]
                  for x in r["warnings"].split(" | ") if x}:
            kinds.setdefault(w, []).append(r)
    for w, rs in sorted(kinds.items(), key=lambda kv: -len(kv[1])):
        nok = sum(r["status"] == "ok" for r in rs)
        notes.append(f"- Warning \"{w}…\" in {len(rs)} run{'s' if len(rs) > 1 else ''} ({nok} of them ok, "
                     f"{len(rs) - nok} unstable/error/failed).")

    sec = []
    cols_dt = [("setting", lambda r: r["setting"]), ("dt / √(m/k)", lambda r: fmt(r["dt_frac"], "{:.3g}"))] + COMMON
    MEM = [("escaped", lambda r: fmt(r["escaped"], "{:g}")),
           ("chain failures", lambda r: fmt(r["chain_failures"], "{:g}"))]
    for c in ("rigid", "membrane"):
        if by("dt", c):
            sec += [f"### Time step, {c}\n", table(sorted(by("dt", c), key=lambda r: r["x"]),
                                                    cols_dt + (MEM if c == "membrane" else [])), ""]
    if by("alpha"):
        cols = [("setting", lambda r: r["setting"]),
                ("servo error RMS [%]", lambda r: fmt(r["servo_rms"], "{:.2g}", 100)),
                ("servo error max [%]", lambda r: fmt(r["servo_max"], "{:.2g}", 100)),
                ("lag-1 corr.", lambda r: fmt(r["servo_lag1"], "{:.2f}"))] + COMMON
        sec += ["### Servo gain of the rigid side walls (in.shear_rigid -var alpha)\n",
                "Servo error = RMS and max of s3/σ3 − 1 over the output lines (every "
                f"{args.dstrain_out:g} of strain, an odd number of steps); 'unstable' above --servo-tol "
                f"{args.servo_tol:g}. 'lag-1 corr.': correlation of consecutive lines' deviations; "
                "near −1 = a period-2 (every other step) oscillation of the servo loop.\n",
                table(sorted(by("alpha"), key=lambda r: r["x"]), cols), ""]
    if by("pressure"):
        cols = [("setting", lambda r: r["setting"]),
                ("status: how it fails", status_text), ("warnings (dedup.)", warn_text),
                ("steps / planned", lambda r: f"{r['steps']} / {r['steps_planned']}"),
                ("wall [s]", lambda r: fmt(r["wall_s"], "{:.1f}")),
                ("max KE [J]", lambda r: fmt(r["KE_max"], "{:.3g}")),
                ("KE / available", lambda r: fmt(r["KE_ratio"], "{:.2g}")),
                ("escaped (max)", lambda r: fmt(r["escaped"], "{:g}")),
                ("chain failures", lambda r: fmt(r["chain_failures"], "{:g}")),
                ("band widenings", lambda r: fmt(r["widenings"], "{:g}")),
                ("max δ / d_min", lambda r: fmt(r["overlap_max"], "{:.3g}")),
                ("max mean δ / d̄", lambda r: fmt(r["overlap_mean"], "{:.2g}")),
                ("σ1 at end [Pa]", lambda r: fmt(r["s1_end"], "{:.3g}"))]
        sec += ["### Membrane pressure jump vs ramp (bench/in.stability_pressure)\n",
                f"Membrane at 1e5 Pa, 2000 steps of settling with servo platens, then the pressure to "
                f"the target (jump, or linear over {args.nramp} steps) and {args.nhold} more steps with "
                "the platens still. 'KE / available': max KE over the kinetic + stored elastic energy at "
                "the start (2·½k_n N_c δ̄², a bound from the mean overlap) + the work of the membrane "
                "(−∫p dA) and platens since then; above 1 energy was created (counted unstable). "
                "δ from compute pair/gran/local (disk–disk contacts).\n",
                table(sorted(by("pressure"), key=lambda r: (r["mode"], r["x"])), cols), ""]
    for sw, title in (("kn", "Contact stiffness at dt 1e-4 s on the sample prepared at 8.45e7 N/m "
                             "(-var kn of the shears: the first step sees k_n/8.45e7 × 100 kPa)"),
                      ("kn (prepared at kn)", "Contact stiffness at dt 1e-4 s, each sample prepared at "
                                               "that k_n (in.prepare -var kn)")):
        cols = [("setting", lambda r: r["setting"]),
                ("dt / √(m/k)", lambda r: fmt(r["dt_frac"], "{:.3g}")),
                ("max mean δ / d̄ (f̄₀/k_n)", lambda r: fmt(r["overlap_mean"], "{:.2g}"))] + COMMON
        if "prepared" in sw:
            cols.insert(1, ("porosity", lambda r: fmt(r["porosity"], "{:.4f}")))
        for c in ("rigid", "membrane"):
            if by(sw, c):
                sec += [f"### {title}, {c}\n", table(sorted(by(sw, c), key=lambda r: r["x"]),
                                                     cols + (MEM if c == "membrane" else [])), ""]
    if by("loose"):
        cols = [("case", lambda r: r["case"]), ("sample", lambda r: r["setting"]),
                ("porosity at 100 kPa", lambda r: fmt(r["porosity"], "{:.4f}")),
                ("escaped", lambda r: fmt(r["escaped"], "{:g}")),
                ("chain failures", lambda r: fmt(r["chain_failures"], "{:g}"))] + COMMON
        sec += ["### Loose samples (in.prepare -var n0 N0 -var mugrow 0.9), default settings\n",
                table(sorted(by("loose"), key=lambda r: (r["case"], r["x"])), cols), ""]

    for s in [dense] + sorted(samples.values(), key=lambda s: s.name):
        m = dict(s.meta or {})
        scr = os.path.join(s.dir, "screen.txt")
        e = re.search(r"equilibrium after step (\d+):.*ok = (\d)\)", open(scr, errors="replace").read()) \
            if os.path.exists(scr) else None
        m["equilibrium_step"], m["equilibrium"] = (int(e.group(1)), e.group(2) == "1") if e else (None, False)
        notes.append(f"- Sample {s.name} ({', '.join(f'{k} {v:g}' for k, v in s.vars.items()) or 'defaults'}): "
                     f"{m.get('status')}" + (f", porosity {m['porosity']:.4f} (after growth "
                                             f"{m['porosity_grown']:.4f}), C_n {m['C_n']:.2f}, "
                                             f"equilibrium loop of in.prepare left at step "
                                             f"{m.get('equilibrium_step')} (flag printed after it: ok = {int(m['equilibrium'])}), "
                                             f"{m['wall_s']:.0f} s" if "porosity" in m else
                                             f": {short(m.get('symptom', ''))[:200]}"))
    for inv in invocations:
        notes.append(f"- Invocation {inv['start']}: {inv['wall_s'] / 60:.1f} min wall, {inv['runs']} runs "
                     f"executed (executable {inv.get('exe_sha', '?')}).")
    dm = dense.meta
    wall = time.time() - t_start
    shown = [a for a in argv if a != "--report-only"]
    took = (f"this invocation took {wall / 60:.1f} min" if executed else
            "the runs were made by the invocations listed in the notes")
    md = ["# Numerical-stability limits of the biaxial test\n",
          "Command: `" + " ".join(["/usr/bin/python3 bench/stability_sweep.py"] + shown) + "`  ",
          f"Sample: generate_sample.py --scale {args.scale:g} --seed {args.seed} ({dm['N']} disks), "
          f"examples/biaxial/in.prepare: porosity {dm['porosity']:.4f} at 100 kPa; smallest disk "
          f"d_min = {1e3 * dm['d_min']:.3f} mm, m_min = π r² ρ = {dm['m_min']:.4g} kg, "
          f"√(m_min/k_n) = {sq0:.4g} s at k_n = 8.45e7 (the default dt 1e-4 s is "
          f"{DT0 / sq0:.3f} of it; a single linear spring is stable below 2). Shears to "
          f"ε_11 = {args.strain:g} at {args.rate:g} /s; every run on 1 MPI rank, {args.jobs} at a "
          f"time, timeout {args.timeout:.0f} s; {took}. Executable sha256 {args.exe_sha}; scripts "
          + ", ".join(f"{k} {v}" for k, v in args.script_sha.items()) + ".  ",
          "Status: **ok**; **error** = LIGGGHTS stopped with an ERROR line (the first one is shown); "
          "**failed** = crash, timeout or no completion line; **unstable** = it ran to the end but the "
          f"output table shows a symptom (s1/s3 non-finite or > 50; KE blow-up: max KE > "
          f"{args.ke_factor:g} × that of the default run of the same case; rigid servo error RMS > "
          f"{args.servo_tol:g}; membrane chain failures; pressure runs: KE above the energy available). "
          "Warnings: the WARNING lines of the screen output, deduplicated (step numbers dropped), "
          "without the two every run prints (mesh scaled, new thermo_style); all of them are in the "
          f"CSV. 'Δpeak vs default': peak σ1/σ3 − that of the default run of the case (same "
          f"sample unless said). Raw rows: "
          f"[{os.path.basename(args.prefix)}.csv]({os.path.basename(args.prefix)}.csv).\n",
          "![stability sweeps](%s.png)\n" % os.path.basename(args.prefix),
          "## Limits found\n",
          table(limits, [("parameter", lambda t: t[0]), ("largest stable (status ok)", lambda t: t[1]),
                         ("first failure: how it fails", lambda t: t[2])]), "",
          "## Sweeps\n", *sec,
          "## Notes\n", *notes, ""]
    return "\n".join(md)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
