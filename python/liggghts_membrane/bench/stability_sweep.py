#!/usr/bin/python3
"""Numerical-stability limits of the 2D DEM biaxial test (examples/biaxial).

    /usr/bin/python3 bench/stability_sweep.py [--scale 0.25] [--strain 0.02] [--rate 0.01]
        [--dt-fracs 0.1,0.2,0.3,0.5,0.7,1,1.5,2] [--alphas 0.25,0.5,1,2,4,8,16,32]
        [--p-factors 2,5,10,20,50,100] [--nramp 2000] [--kn-factors 0.01,0.1,1,10,100]
        [--loose-n0 0.18,0.20] [--sweeps dt,alpha,pressure,kn,loose] [--jobs 2]
        [--retry-failed] [--report-only] [--workdir out/stability_sweep]
    /usr/bin/python3 bench/stability_sweep.py --from-csv [--prefix bench/stability_sweep]

One command: generates one small sample (generate_sample.py --scale 0.25, ~526
disks), prepares it with examples/biaxial/in.prepare, and pushes each numerical
parameter of the test until it fails, one MPI rank per run, at most --jobs runs at
a time:

  dt        in.shear_rigid and in.shear_membrane, -var dt = FRAC * sqrt(m_min/k_n)
            (m_min = pi r_min^2 rho of the prepared sample's smallest disk), plus the
            scripts' default dt (the reference of every sweep)
  alpha     in.shear_rigid, -var alpha (side-wall servo gain G = alpha 1.075e-3/(k_n dt));
            also the servo error = RMS of s3/sigma3 - 1 over the output lines
  pressure  bench/in.stability_pressure: the membrane at sigma on the still sample,
            then the pressure to FACTOR x sigma as a jump or a linear ramp over
            --nramp steps (pressure v_p), held --nhold steps, platens still
  kn        both shears, -var kn = FACTOR x k_n at the default dt on the sample prepared
            at k_n (its overlaps give FACTOR x sigma at the first step), and on
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

The examples' defaults (k_n, rho, sigma, dt, alpha) are read from the input scripts
(liggghts_membrane.params: in.shear_rigid and its shear_setup.inc, in.prepare).

Plan / run / report: the plan is the list of samples and runs of the sweeps asked;
run prepares and executes the missing ones into --workdir (runs with the same
parameters, executable and input-script hashes are reused; the executable and the
scripts with their includes are copied into --workdir at the start and hashed: after
a rebuild everything is re-run, samples included; --retry-failed re-runs the runs
that ended in an error, a crash or a timeout); the report is made from the CSV it
writes, PREFIX.csv (raw rows), and PREFIX.json (the command, its options, the
defaults, the samples, hashes and invocations), by bench/stability_report.py:
PREFIX.md (a table per sweep and the limits found) and PREFIX.png (one panel per
sweep). --report-only: no runs, the report of what is in --workdir; --from-csv: no
runs and no --workdir, the report again from PREFIX.csv and PREFIX.json alone.
"""
import argparse
import concurrent.futures as cf
import json
import math
import os
import re
import sys

import numpy as np

from liggghts_membrane.bench import common
from liggghts_membrane.bench.common import EXAMPLES, HERE, MESHES, ROOT, floats, log, sci, tag
from liggghts_membrane import readers
from liggghts_membrane.params import number
from liggghts_membrane.bench.stability_report import CSV_KEYS, report, short

# the examples' defaults, from their input scripts (defined there once)
_SHEAR = common.script_parameters("in.shear_rigid")
KN0, RHO, SIGMA, DT0, ALPHA0 = (number(_SHEAR, n) for n in ("kn", "rho", "sigma", "dt", "alpha"))
# the rest bench/in.stability_pressure takes from the examples
MATERIAL = {n: _SHEAR[n] for n in ("mu", "rho", "vmax", "gvisc")}
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
                   help=f"membrane pressure targets as multiples of {sci(SIGMA)} Pa")
    p.add_argument("--nramp", type=int, default=2000, help="steps of the pressure ramp")
    p.add_argument("--nhold", type=int, default=3000, help="steps after the jump/ramp")
    p.add_argument("--kn-factors", type=floats, default=floats("0.01,0.1,1,10,100"),
                   help=f"contact stiffness as multiples of {sci(KN0)} N/m (at dt {sci(DT0)} s)")
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
    p.add_argument("--exe", default=common.EXE)
    p.add_argument("--prefix", default=os.path.join(HERE, "stability_sweep"),
                   help="output prefix: PREFIX.csv, PREFIX.json, PREFIX.png, PREFIX.md")
    p.add_argument("--retry-failed", action="store_true",
                   help="re-run runs (and preparations) that ended in an error, crash or timeout")
    p.add_argument("--report-only", action="store_true", help="no runs: report what is in --workdir")
    p.add_argument("--from-csv", action="store_true",
                   help="no runs: the report again from PREFIX.csv and PREFIX.json alone")
    a = p.parse_args(argv)
    a.sweeps = [s.strip() for s in a.sweeps.split(",") if s.strip()]
    a.jobs = max(1, min(a.jobs, 2))
    return a


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
        self.id = common.sha_text(json.dumps(self.params, sort_keys=True))
        self.meta = None

    @property
    def ok(self):
        return bool(self.meta) and self.meta.get("status") == "ok"


def prepare(s, args):
    """Prepare sample s (or reuse it); fills s.meta. Never raises for a failed run."""
    metafile = os.path.join(s.dir, "meta.json")
    s.meta = common.known_meta(s.dir, s.params, "ok", args.retry_failed, args.report_only)
    if s.meta is not None:
        return s
    os.makedirs(s.dir, exist_ok=True)
    if not os.path.exists(s.data):
        common.generate_sample(args.scale, args.seed, s.data)
    cmd = [args.exe_copy, "-in", args.scripts["prepare"], "-var", "data", s.data,
           "-var", "out", s.restart, "-var", "meshdir", MESHES,
           "-log", os.path.join(s.dir, "log.prepare")]
    for k, v in s.vars.items():
        cmd += ["-var", k, repr(v)]
    log(f"  prepare {s.name} {' '.join(f'{k} {v:g}' for k, v in s.vars.items())}")
    screen = os.path.join(s.dir, "screen.txt")
    rc, wall, cpu = common.run_command(cmd, os.path.dirname(args.scripts["prepare"]), screen, args.timeout)
    text = open(screen, errors="replace").read()
    meta = dict(params=s.params, rc=rc, wall_s=wall, cpu_s=cpu, cmd=" ".join(cmd))
    prepared = readers.key_value_lines(text, "prepared")     # in.prepare's key=value line
    m = prepared[-1] if prepared else None
    err, warns = common.messages(screen, BENIGN)
    meta.update(error=err, warnings=warns)
    if rc == 0 and m and os.path.exists(s.restart):
        meta["porosity_grown"], meta["porosity"], meta["C_n"] = m["porosity_grown"], m["porosity"], m["cn"]
        meta["ftot"] = m["growth"]
        d = readers.read_data_diameters(s.data) * meta["ftot"]      # the data file is at half size
        meta["N"], meta["d_min"], meta["d_mean"] = len(d), float(d.min()), float(d.mean())
        meta["m_min"] = math.pi * (meta["d_min"] / 2) ** 2 * RHO
        meta["equilibrium"] = m["equilibrium_ok"] == 1
        meta["equilibrium_step"] = int(m["equilibrium_step"])
        meta["status"], meta["symptom"] = "ok", ""
    else:
        meta["status"] = "error" if err else "failed"
        meta["symptom"] = ("timeout after %.0f s: " % wall if rc == "timeout" else f"rc {rc}: ") \
            + (err or common.symptom(screen))
    common.write_context(metafile, meta)
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
            self.vars = dict(sigma=repr(SIGMA), ptarget=repr(pfac * SIGMA), nramp=str(nramp), nhold=str(args.nhold),
                             nout="21", dt=repr(dt), kn=repr(kn), alpha=repr(alpha),
                             guard=str(int(args.has_guard)), **MATERIAL)
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
    run.meta = common.cached_meta(metafile, run.params, "finished", args.retry_failed)
    if run.meta is not None:
        return run
    if not run.sample.ok and run.sample.meta.get("status") != "not run":
        run.meta = dict(params=run.params, status="failed", error="", warnings=[],
                        symptom=f"sample {run.sample.name} not prepared: {run.sample.meta.get('symptom', '')}")
        return run
    if args.report_only:
        run.meta = dict(params=run.params, status="not run", symptom="not run", error="", warnings=[])
        return run
    common.empty_folder(run.dir)
    cmd = [args.exe_copy, "-in", run.script, "-var", "restart", run.sample.restart,
           "-var", "meshdir", MESHES, "-var", "out", run.out,
           "-log", os.path.join(run.dir, "log.run")]
    for k, v in run.vars.items():
        cmd += ["-var", k, v]
    screen = os.path.join(run.dir, "screen.txt")
    # in the frozen scripts' folder, where LIGGGHTS finds their includes
    rc, wall, cpu = common.run_command(cmd, os.path.dirname(run.script), screen, args.timeout)
    tloop, nsteps = common.loop_times(os.path.join(run.dir, "log.run"))
    text = open(screen, errors="replace").read()
    done = [l for l in text.splitlines() if l.startswith(("SHEAR done", "PRESSURE done"))]
    err, warns = common.messages(screen, BENIGN)
    meta = dict(params=run.params, rc=rc, wall_s=wall, cpu_s=cpu, loop_time_s=tloop,
                loop_steps=nsteps, done_line=done[-1] if done else "", error=err,
                warnings=warns, cmd=" ".join(cmd))
    if rc == "timeout":
        meta["status"], meta["symptom"] = "failed", f"timeout after {wall:.0f} s"
    elif err:
        meta["status"], meta["symptom"] = "error", err
    elif rc != 0 or not done:
        meta["status"], meta["symptom"] = "failed", f"rc {rc}: " + common.symptom(screen)
    else:
        meta["status"], meta["symptom"] = "finished", ""
    meta.update({k: v for k, v in common.done_counts(text).items()
                 if k in ("escaped", "chain_failures")})
    common.write_context(metafile, meta)
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
        try:
            t, _ = readers.read_columns(run.out)
        except (ValueError, OSError):
            return r
        if not len(t["step"]):
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


# ----------------------------------------------------------------------------- collect
def row_for(sweep, x, setting, run):
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


def sample_summary(s):
    """What the report says of a sample (PREFIX.json)."""
    m = s.meta or {}
    keep = ("status", "porosity", "porosity_grown", "C_n", "wall_s", "symptom")
    out = dict(name=s.name, vars=dict(s.vars), **{k: m[k] for k in keep if k in m})
    if "porosity" in m:
        out.update(equilibrium_step=m.get("equilibrium_step"), equilibrium=bool(m.get("equilibrium")))
    return out


def collect(plan, args, invocations, took_min):
    """The rows and the context of the report, from the runs in the cache."""
    for r in plan.runs.values():
        r.res = measure(r, args)
    refs = {c: plan.runs[plan.get(c).name] for c in plan.SHEAR}
    for r in plan.runs.values():
        r.res.update(classify(r, refs.get(r.case), args))
    rows = [row_for(sw, x, st, run) for sw, x, st, run in plan.entries]
    dm = plan.dense.meta
    options = {k: v for k, v in vars(args).items()
               if k not in ("exe_copy", "scripts", "script_sha", "exe_sha", "generator_sha", "prepare_sha",
                            "workdir", "exe", "prefix", "argv", "has_guard")}
    ctx = dict(argv=[a for a in args.argv if a != "--report-only"], args=options,
               defaults=dict(kn=KN0, rho=RHO, sigma=SIGMA, dt=DT0, alpha=ALPHA0),
               dense={k: dm[k] for k in ("N", "d_min", "m_min", "porosity")},
               samples=[sample_summary(s) for s in [plan.dense] + sorted(plan.samples.values(),
                                                                         key=lambda s: s.name)],
               exe_sha=args.exe_sha, script_sha=args.script_sha, took_min=took_min,
               invocations=[{k: i.get(k) for k in ("start", "wall_s", "runs", "exe_sha")} for i in invocations])
    return rows, ctx


# ----------------------------------------------------------------------------- plan
class Plan:
    """The samples and runs of the sweeps asked: entries (sweep, x, setting, run)."""
    SHEAR = ("rigid", "membrane")

    def __init__(self, args, dense):
        self.args, self.dense, self.runs, self.entries = args, dense, {}, []
        self.sq0 = math.sqrt(dense.meta["m_min"] / KN0)
        self.samples = {}
        if "kn" in args.sweeps and args.kn_prepared:
            for f in args.kn_factors:
                if f != 1:
                    self.samples[("kn", f)] = Sample(f"kn{tag(f)}", args, kn=f * KN0)
        if "loose" in args.sweeps:
            for n0 in args.loose_n0:
                self.samples[("loose", n0)] = Sample(f"loose_n{tag(n0)}", args, n0=n0, mugrow=0.9)

    def get(self, case, sample=None, **kw):
        r = Run(case, sample or self.dense, self.args, **kw)
        return self.runs.setdefault(r.name, r)

    def add(self, sweep, x, setting, run):
        self.entries.append((sweep, x, setting, run))

    def make(self):
        """The entries; the samples must be prepared (the loose sweep's x is their porosity)."""
        for c in self.SHEAR:
            self.add("default", 1.0, f"default (dt {sci(DT0)} s, α {ALPHA0:g}, k_n {sci(KN0)})", self.get(c))
        for sweep in ("dt", "alpha", "pressure", "kn", "loose"):
            if sweep in self.args.sweeps:
                getattr(self, "plan_" + sweep)()

    def plan_dt(self):
        sq0 = self.sq0
        for c in self.SHEAR:
            self.add("dt", DT0 / sq0, f"dt {sci(DT0)} s = {DT0 / sq0:.3f} (default)", self.get(c))
            for f in self.args.dt_fracs:
                self.add("dt", f, f"{f:g} × √(m/k) = {f * sq0:.3g} s", self.get(c, dt=float(f"{f * sq0:.6g}")))

    def plan_alpha(self):
        for a in sorted(set(self.args.alphas) | {ALPHA0}):
            self.add("alpha", a, f"α {a:g}" + (" (default)" if a == ALPHA0 else ""), self.get("rigid", alpha=a))

    def plan_pressure(self):
        for f in self.args.p_factors:
            for nr in (0, self.args.nramp):
                self.add("pressure", f, f"{sci(SIGMA)} → {f * SIGMA:.3g} Pa ({f:g}×), "
                         + (f"ramp {nr} steps" if nr else "jump"), self.get("pressure", pfac=f, nramp=nr))

    def plan_kn(self):
        a = self.args
        for c in self.SHEAR:
            for f in a.kn_factors:
                self.add("kn", f, f"k_n × {f:g}" + (" (default)" if f == 1 else ""), self.get(c, kn=f * KN0))
        if a.kn_prepared:
            for c in self.SHEAR:
                for f in a.kn_factors:
                    s = self.dense if f == 1 else self.samples[("kn", f)]
                    self.add("kn (prepared at kn)", f, f"k_n × {f:g}, sample prepared at it",
                             self.get(c, s, kn=f * KN0))

    def plan_loose(self):
        for c in self.SHEAR:
            self.add("loose", self.dense.meta["porosity"], "dense (n0 0.12, mugrow 0)", self.get(c))
            for n0 in self.args.loose_n0:
                s = self.samples[("loose", n0)]
                self.add("loose", s.meta.get("porosity", float("nan")), f"n0 {n0:g}, mugrow 0.9", self.get(c, s))


# ----------------------------------------------------------------------------- main
def freeze(args):
    """The sweep's folder, its copy of the executable and of the input scripts (with
    their includes, by content hash); with --report-only after a change of the
    examples or the build, the hashes of the last invocation (its runs are reported)."""
    args.workdir = os.path.abspath(args.workdir)
    inputs = os.path.join(args.workdir, "inputs")
    os.makedirs(inputs, exist_ok=True)
    args.exe_copy, args.exe_sha = common.freeze_executable(args.exe, args.workdir, args.report_only)
    args.scripts, args.script_sha = {}, {}
    for key, src in (("prepare", os.path.join(EXAMPLES, "in.prepare")),
                     ("rigid", os.path.join(EXAMPLES, "in.shear_rigid")),
                     ("membrane", os.path.join(EXAMPLES, "in.shear_membrane")),
                     ("pressure", os.path.join(HERE, "in.stability_pressure"))):
        args.scripts[key], args.script_sha[key] = common.freeze_script(src, inputs)
    args.generator_sha = common.sha(common.GENERATOR)
    invocations = common.load_invocations(os.path.join(args.workdir, "invocations.json"))
    if args.report_only and invocations:
        last = invocations[-1]
        args.exe_sha = last.get("exe_sha", args.exe_sha)
        args.generator_sha = last.get("generator_sha", args.generator_sha)
        for key, h in last.get("script_sha", {}).items():
            args.scripts[key] = os.path.join(inputs, f"{os.path.basename(args.scripts[key])}.{h}",
                                             os.path.basename(args.scripts[key]))
            args.script_sha[key] = h
    args.prepare_sha = args.script_sha["prepare"]
    # the project's fix stability/guard (if the examples use it, the build has it):
    # bench/in.stability_pressure then uses it too
    args.has_guard = any("stability/guard" in open(f, errors="replace").read()
                         for f in common.script_set(os.path.join(EXAMPLES, "in.shear_rigid")))


def prepare_dense(args):
    """The dense sample first: its smallest disk sets the dt fractions."""
    dense = prepare(Sample("dense", args), args)
    if not dense.ok:
        raise SystemExit(f"preparation of the dense sample failed: {dense.meta.get('symptom')}")
    sq0 = math.sqrt(dense.meta["m_min"] / KN0)
    log(f"  dense sample: {dense.meta['N']} disks, porosity {dense.meta['porosity']:.4f}, "
        f"d_min {1e3 * dense.meta['d_min']:.3f} mm, m_min {dense.meta['m_min']:.4g} kg, "
        f"sqrt(m_min/k_n) {sq0:.4g} s (default dt = {DT0 / sq0:.3f} of it)")
    return dense


def run_plan(plan, args):
    """Prepare the other samples, then execute the runs not in the cache, longest first."""
    with cf.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        list(pool.map(lambda s: prepare(s, args), plan.samples.values()))
        plan.make()
        todo = sorted(plan.runs.values(), key=lambda r: -r.cost())
        log(f"  {len(plan.runs)} runs, {args.jobs} at a time, 1 rank each, timeout {args.timeout:.0f} s")
        for f in cf.as_completed([pool.submit(execute, r, args) for r in todo]):
            f.result()


def sweep(args, t_start):
    """Plan, run the missing runs, collect: the report (common.finish_sweep)."""
    freeze(args)
    log(f"stability sweep: scale {args.scale:g}, strain {args.strain:g} at {args.rate:g} /s, "
        f"sweeps {','.join(args.sweeps)}; executable {args.exe_copy} (sha256 {args.exe_sha})")
    plan = Plan(args, prepare_dense(args))
    run_plan(plan, args)
    entry = lambda executed: dict(runs=len(executed), argv=args.argv, exe_sha=args.exe_sha,  # noqa: E731
                                  script_sha=args.script_sha, generator_sha=args.generator_sha)
    return common.finish_sweep(plan.runs.values(), os.path.join(args.workdir, "invocations.json"), t_start,
                              entry, lambda inv, took: collect(plan, args, inv, took), args.prefix,
                              CSV_KEYS, report)


def main(argv):
    return common.sweep_main(argv, parse_args, report, sweep)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
