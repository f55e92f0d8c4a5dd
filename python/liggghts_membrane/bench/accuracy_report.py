"""The report of bench/accuracy_sweep.py: PREFIX.md and PREFIX.png from PREFIX.csv
(one row per comparison of a run with its reference) and PREFIX.json (the command,
its options and what the CSV does not hold: hashes, invocations, per-run load and
time split). Pure functions of those rows: `report(prefix)` makes the report again
from the two files alone (bench/accuracy_sweep.py --from-csv).
"""
import argparse
import math
import os

import numpy as np

from liggghts_membrane.bench.common import fmt, read_context, read_rows, tag

PUBLISHED_RATE = 0.02 / 60.0          # the published procedure's 2 %/min
CASES = ("rigid", "membrane")
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
INT_KEYS = ("seed", "ranks", "is_reference", "steps", "oversubscribed")


# ----------------------------------------------------------------------------- settings
def every_key(e):
    """auto first, then the intervals in order"""
    return (0, 0) if e == "auto" else (1, int(e))


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


def damping_spec(d):
    """('viscous', 500.0) -> 'viscous:500' (the --dampings form; CSV, PREFIX.json)."""
    return f"{d[0]}:{tag(d[1])}"


def damping_text(d, prefix=True):
    """The setting as the table gives it ('damping viscous 500 N·s/m')."""
    t = f"viscous {tag(d[1])} N·s/m" if d[0] == "viscous" else f"local α {tag(d[1])}"
    return ("damping " + t) if prefix else t


def run_name(case, seed, rate, dt, every, damping_, default_damping, ranks):
    """The folder name of a run; the scripts' default damping and 1 rank leave it as it
    was before these two parameters existed, so runs made then are reused."""
    name = f"{case}_seed{seed}_rate{tag(rate)}_dt{tag(dt)}" + (f"_every{every}" if case == "membrane" else "")
    if damping_ != default_damping:
        name += ("_visc" if damping_[0] == "viscous" else "_local") + tag(damping_[1])
    if ranks != 1:
        name += f"_np{ranks}"
    return name


# ----------------------------------------------------------------------------- judging rows
def within(row, scatter):
    """'yes' when every GATE_KEYS error is within the scatter, else the keys that exceed it."""
    if scatter is None or row["status"] != "ok":
        return "n/a"
    over = [k for k in GATE_KEYS if abs(row.get(k, np.nan)) > abs(scatter.get(k, np.nan))
            or not np.isfinite(row.get(k, np.nan))]
    return "yes" if not over else "no: " + " ".join(over)


def sweep_of(row):
    """The sweeps whose rows are judged against the scatter (not the scatter rows)."""
    return row["sweep"] if row["sweep"] in ("rate", "every", "dt", "rate@seed2", "damping",
                                            "ranks") else None


def scatter_rows(rows):
    """The scatter level of each error and case: RMS over the seed comparisons (at the
    reference rate and at --scatter-rates; one pair of samples gives one random value),
    as 'scatter' rows for the CSV."""
    out = []
    for c in CASES:
        sr = [r for r in rows if r["case"] == c and r["sweep"].startswith("seed") and r["status"] == "ok"]
        if sr:
            row = dict(sweep="scatter", case=c, seed="", rate="", dt="", every="",
                       reference=f"RMS of the {len(sr)} seed comparisons", is_reference=0,
                       status="ok", symptom="", steps="", wall_s=float("nan"),
                       cpu_s=float("nan"), I_max=float("nan"), escaped="", chain_failures="",
                       rms_ratio_vs_case_ref=float("nan"), within_scatter="")
            row.update({k: float(np.sqrt(np.nanmean([r[k] ** 2 for r in sr])))
                        if any(np.isfinite(r[k]) for r in sr) else float("nan")
                        for k in ERR_KEYS + ["mean_ratio"]})
            out.append(row)
    return out


def scatter_of(rows):
    """{case: the scatter row's errors, with n = the number of seed comparisons}."""
    out = {}
    for r in rows:
        if r["sweep"] == "scatter":
            out[r["case"]] = dict({k: r[k] for k in ERR_KEYS + ["mean_ratio"]},
                                  n=sum(1 for x in rows if x["case"] == r["case"]
                                        and x["sweep"].startswith("seed") and x["status"] == "ok"))
    return out


def judge(rows):
    """The rows with the scatter rows appended and each run's 'within_scatter'."""
    rows = rows + scatter_rows(rows)
    scatter = scatter_of(rows)
    for row in rows:
        row["within_scatter"] = "" if row["is_reference"] or row["sweep"] != sweep_of(row) \
            else within(row, scatter.get(row["case"]))
    return rows


def pareto(points):
    """Indices of the Pareto front of (time, error) points (both minimised)."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


# ----------------------------------------------------------------------------- reading back
def read(prefix):
    """(rows, context, args) of PREFIX.csv and PREFIX.json; each row gets what the
    report derives from the context: default_damping, rate_note, cores, loadavg_start,
    time_split, run (its folder name)."""
    ctx = read_context(prefix + ".json")
    args = argparse.Namespace(**ctx["args"])
    rows = read_rows(prefix + ".csv", INT_KEYS, text_keys=("every", "damping", "reference",
                                                           "symptom", "within_scatter"))
    for r in rows:
        if r["sweep"] == "scatter":
            continue
        r["every"] = int(r["every"]) if r["every"].isdigit() else r["every"]
        dflt = damping(ctx["default_damping"][r["case"]])
        r["default_damping"] = int(damping(r["damping"]) == dflt)
        r["rate_note"] = int(r["sweep"] == "damping" and len(args.damping_rates) > 1)
        r["run"] = run_name(r["case"], r["seed"], r["rate"], r["dt"], r["every"],
                            damping(r["damping"]), dflt, r["ranks"])
        extra = ctx.get("runs", {}).get(r["run"], {})
        r["cores"] = extra.get("cores", ctx.get("cores"))
        r["loadavg_start"] = extra.get("loadavg_start")
        r["time_split"] = extra.get("time_split", {})
    return rows, ctx, args


def unique_runs(rows):
    """One row per run (its first), in the order of the rows."""
    out = {}
    for r in rows:
        if r["sweep"] != "scatter":
            out.setdefault(r["run"], r)
    return list(out.values())


# ----------------------------------------------------------------------------- text
def ranks_text(row):
    """'2 ranks', '4 ranks (oversubscribed: 2 cores)', with speed-up and efficiency."""
    n = int(row["ranks"])
    t = f"{n} rank" + ("s" if n > 1 else "")
    if row.get("oversubscribed"):
        t += f" (oversubscribed: {row['cores']} cores)"
    if n > 1 and np.isfinite(row.get("speedup", np.nan) if row.get("speedup", "") != "" else np.nan):
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


def results_table(rows):
    head = ["sweep", "case", "setting", "status", "steps", "wall [s]", "CPU [s]", "I_max",
            "RMS Δ(σ1/σ3)", "max Δ(σ1/σ3)", "mean Δ(σ1/σ3)", "RMS Δε_v [%]", "max Δε_v [%]", "Δpeak σ1/σ3",
            "Δε_peak [%]", "ΔE [%]", "Δφ [°]", "Δψ [°]", "RMS Δa", "RMS ΔC_n", "RMS Δλ",
            "RMS Δ(σ1/σ3) vs case ref", "within scatter"]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        ref = r["is_reference"]
        errs = [""] * 15 if ref else [
            fmt(r.get("rms_ratio")), fmt(r.get("max_ratio")), fmt(r.get("mean_ratio"), "{:+.3g}"),
            fmt(r.get("rms_ev"), scale=100), fmt(r.get("max_ev"), scale=100), fmt(r.get("d_peak"), "{:+.3g}"),
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


def fastest(rows, scatter, tkey):
    """The fastest setting of each sweep within the sample scatter."""
    rec = []
    for sweep, case in (("rate", "rigid"), ("rate", "membrane"), ("every", "membrane"),
                        ("dt", "rigid")):
        sel = [r for r in rows if r["sweep"] == sweep and r["case"] == case]
        second = {r["rate"]: r for r in rows if r["sweep"] == "rate@seed2" and r["case"] == case}
        good = [r for r in sel if r["is_reference"] or (
            r.get("within_scatter") == "yes" and
            (sweep != "rate" or r["rate"] not in second
             or second[r["rate"]].get("within_scatter") == "yes"))]
        if not sel or case not in scatter or not good:
            continue
        best = min(good, key=lambda r: r[tkey])
        rec.append(f"- {sweep} sweep, {case}: fastest within the sample scatter = "
                   f"**{setting(best)}** ({fmt(best['wall_s'], '{:.0f}')} s wall, "
                   f"{fmt(best['cpu_s'], '{:.0f}')} s CPU, "
                   f"RMS Δ(σ1/σ3) {fmt(best.get('rms_ratio', 0))} vs scatter "
                   f"{fmt(scatter[case]['rms_ratio'])}, I_max {fmt(best['I_max'], '{:.2g}')})")
    return rec


def damping_advice(rows, scatter, ctx, args, tkey):
    """At a given rate every damping costs about the same: which one comes closest to
    the quasi-static reference, and which are within the noise."""
    rec, ref_rate = [], min(args.rates)

    def short(r):
        return damping_text(damping(r["damping"]), prefix=False)

    for case in CASES:
        sel = [r for r in rows if r["sweep"] == "damping" and r["case"] == case]
        for rate in sorted({r["rate"] for r in sel}):
            at = [r for r in sel if r["rate"] == rate]
            ok = [r for r in at if r["status"] == "ok" and not r["is_reference"]
                  and np.isfinite(r.get("rms_ratio", np.nan))]
            if not ok:
                continue
            sc = scatter.get(case, {}).get("rms_ratio", float("nan"))
            if any(r["is_reference"] for r in at):
                rec.append(f"- damping sweep, {case} at {rate:g} /s: the reference rate, where "
                           f"the default damping is the reference itself; the others differ by "
                           + ", ".join(f"{short(r)} RMS {fmt(r['rms_ratio'])} "
                                       f"({'within' if r.get('within_scatter') == 'yes' else 'outside'})"
                                       for r in ok)
                           + f" (scatter {fmt(sc)}).")
                continue
            best = min(ok, key=lambda r: r["rms_ratio"])
            inside = [short(r) for r in at if r.get("within_scatter") == "yes"]
            failed = [short(r) for r in at if r["status"] != "ok"]
            dflt = [r for r in ok if r["damping"] == ctx["default_damping"][case]]
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
    return rec


def ranks_advice(rows, scatter):
    """The fastest rank count within the scatter, per case."""
    rec = []
    for case in CASES:
        sel = [r for r in rows if r["sweep"] == "ranks" and r["case"] == case]
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
    return rec


def ranks_line(r):
    if r["status"] != "ok":
        return f"{ranks_text(r)}: {r['status']}"
    t = f"{ranks_text(dict(r, speedup=np.nan))} {fmt(r['wall_s'], '{:.1f}')} s"
    if not r["is_reference"]:
        t += (f": speed-up {fmt(r['speedup'], '{:.2f}')}, efficiency "
              f"{fmt(r['efficiency'], '{:.0f}', 100)} %, RMS Δ(σ1/σ3) vs 1 rank "
              f"{fmt(r['rms_ratio'])}, vs the case reference "
              f"{fmt(r['rms_ratio_vs_case_ref'])}")
    if r.get("loadavg_start") is not None:
        t += f" (load average {r['loadavg_start']:.1f} at its start)"
    if r.get("time_split"):
        t += " [time: " + ", ".join(f"{k} {v:.0f} %" for k, v in r["time_split"].items()) + "]"
    return t


def ranks_section(rows, ctx, args):
    """Speed-up and parallel efficiency of the ranks sweep (empty without it)."""
    lines = [f"- {case}: " + "; ".join(ranks_line(r) for r in sel) + "."
             for case in CASES
             for sel in [[r for r in rows if r["sweep"] == "ranks" and r["case"] == case]] if sel]
    if not lines:
        return []
    ncores = max(int(r["cores"]) for r in rows if r["sweep"] == "ranks")
    return [
        "## Ranks sweep: speed-up and parallel efficiency\n",
        f"Same run (rate {args.default_rate:g} /s, dt {args.default_dt:g} s, default damping and every, seed "
        f"{args.seeds[0]}) on N MPI ranks (`{args.mpirun} --allow-run-as-root --oversubscribe -np N`; "
        f"1 rank without mpirun: the very run of the other sweeps). Speed-up = wall time "
        f"('Loop time') on 1 rank / on N ranks, efficiency = speed-up / N; the errors are "
        f"against the 1-rank run (the same physics, only the order of the floating-point "
        f"sums differs, which a chaotic granular flow amplifies) and against the case "
        f"reference. An N-rank run took min(N, {args.jobs}) of the {args.jobs} job slots, "
        f"after the 1-rank runs, which themselves ran {args.jobs} at a time. "
        f"**These figures are only meaningful on an otherwise idle machine** "
        f"({ncores} cores here; N > {ncores} is oversubscribed; the 1-minute load "
        f"average at the start of each run is given, our own runs included):\n",
        *lines, ""]


def published_rate_notes(rows, args):
    """What the published rate (2 %/min) would cost, from the case references."""
    notes, ref_rate = [], min(args.rates)
    for c in CASES:
        refs = [r for r in rows if r["case"] == c and r["sweep"] in ("rate", "reference")
                and r["is_reference"] and r["status"] == "ok"]
        if not refs:
            continue
        loop = refs[0]["wall_s"]
        f = ref_rate / PUBLISHED_RATE
        if ref_rate <= PUBLISHED_RATE * 1.01:
            notes.append(f"- Published rate 2 %/min = {PUBLISHED_RATE:.3g} /s, {c}: it is the "
                         f"reference, {loop / 60:.1f} min on 1 rank at this size.")
            continue
        notes.append(f"- Published rate 2 %/min = {PUBLISHED_RATE:.3g} /s, {c}: "
                     f"{int(math.ceil(args.strain / (PUBLISHED_RATE * args.default_dt)))} steps, about "
                     f"{loop * f / 60:.0f} min on 1 rank at this size "
                     f"(the {ref_rate:g} /s reference × {f:.1f}; steps ∝ 1/rate); not run.")
    return notes


def membrane_notes(runs):
    """Escaped disks, chain failures and how often a detection changed the chain."""
    mem = [r for r in runs if r["case"] == "membrane" and r["status"] == "ok"]
    if not mem:
        return []
    esc = sorted({float(r["escaped"]) if r["escaped"] != "" else float("nan") for r in mem})
    cf_ = sorted({float(r["chain_failures"]) if r["chain_failures"] != "" else float("nan") for r in mem})
    notes = [f"- Membrane 'SHEAR done' lines: escaped disks at the end "
             f"{', '.join(f'{x:g}' for x in esc)}; chain failures "
             f"{', '.join(f'{x:g}' for x in cf_)} (per run: the CSV)."]
    frac = [(r["every"], r["rate"], r["chain_change_fraction"]) for r in mem
            if r["chain_change_fraction"] != ""]
    if frac:
        notes.append("- Share of chain detections that changed a side's chain or escapees "
                     "(what skipping detections risks; per side, settling included): "
                     + "; ".join(f"every {e} at {rt:g} /s: {100 * x:.1f} %"
                                 for e, rt, x in sorted(frac, key=lambda t: (every_key(t[0]), t[1]))))
    return notes


def notes(rows, ctx, args):
    runs = unique_runs(rows)
    ok_runs = [r for r in runs if r["status"] == "ok"]
    total_core = sum((0.0 if not np.isfinite(r["wall_s"]) else r["wall_s"]) * r["ranks"] for r in runs)
    full = (1.0 / args.scale) ** 2
    out = published_rate_notes(rows, args)
    out.append(f"- Sum of the shear-run loop times: {total_core / 60:.1f} core-min "
               f"({len(ok_runs)}/{len(runs)} runs ok). The same command at --scale 1 "
               f"(~4× the disks, cost ∝ disks) would need about {total_core * full / 60:.0f} "
               f"core-min at --strain {args.strain:g}, {total_core * full * 0.10 / args.strain / 60:.0f} "
               f"at --strain 0.10, i.e. /{args.jobs} in wall time with --jobs {args.jobs}, plus the "
               f"preparation of 2 full samples.")
    out += [f"- {r['run']}: {r['status']}: {r['symptom']}" for r in runs if r["status"] != "ok"]
    out += membrane_notes(runs)
    fast = sorted({r["rate"] for r in ok_runs if np.isfinite(r["I_max"]) and r["I_max"] > 1e-3})
    if fast:
        out.append(f"- I_max > 1e-3 (not quasi-static: the criterion I < 1e-3 of doc/biaxial_test.md) at rates "
                   f"{', '.join(f'{x:g}' for x in fast)} /s.")
    out += [f"- Invocation {inv['start']}: {inv['wall_s'] / 60:.1f} min wall, "
            f"{inv['runs']} runs executed." for inv in ctx["invocations"]]
    return out


def header(ctx, args):
    took = (f"this invocation took {ctx['took_min']:.1f} min of wall time" if ctx.get("took_min") is not None
            else "the runs were made by the invocations listed in the Notes")
    d = {c: damping(s) for c, s in ctx["default_damping"].items()}
    return [
        "# Run time against error of the biaxial test\n",
        f"Command: `/usr/bin/python3 bench/accuracy_sweep.py {' '.join(ctx['argv'])}`".rstrip() + "  ",
        f"Sample: generate_sample.py --scale {args.scale:g} (seeds {', '.join(map(str, args.seeds))}), "
        f"in.prepare; sheared to ε_11 = {args.strain:g}; every run on 1 MPI rank"
        + (" (the ranks sweep excepted)" if "ranks" in args.sweeps else "")
        + f", {args.jobs} at a time; {took} (runs reused from {ctx['rundir']} are not re-run).  ",
        f"Errors: each run against the reference of its sweep (**ref**) on a common ε_11 grid "
        f"over 0..{args.strain:g}; Δ = run − reference. 'RMS Δ(σ1/σ3) vs case ref': against the "
        f"slowest-rate run of the same case (the y axis of the plot). 'seed' rows: the reference "
        f"repeated on a second sample (and, 'seed@rate', the same pair at other rates) = the "
        f"sample-to-sample scatter; 'scatter' rows: the RMS over those pairs, the noise level "
        f"used. "
        + ("'damping' rows: both cases with another damping (viscous G = fix viscous G "
           "N·s/m, local α = fix damping/local alpha α; the scripts' default is "
           + ", ".join(f"{damping_text(x, prefix=False)} ({c})" for c, x in d.items())
           + ") against the case reference: which damping comes closest to the "
           "quasi-static answer at that rate. " if "damping" in args.sweeps else "")
        + ("'ranks' rows: the same run on N MPI ranks against the 1-rank run (x = wall "
           "time in the plot; see the section below). " if "ranks" in args.sweeps else "")
        + f"'within scatter': |error| ≤ scatter for {', '.join(GATE_KEYS)} (E, φ, ψ and "
        f"fabric errors are given but not gated: ψ and E of one run are noisy). Wall time = "
        f"the sum of the log's 'Loop time' lines (the membrane's settling steps "
        f"included); CPU = user+sys time of the process (others used the machine too: "
        f"wall > CPU means the run was descheduled). Output every {args.dstrain_out:g} of "
        f"strain in every run. Executable sha256 {ctx['exe_sha']}, scripts "
        f"{', '.join(f'in.shear_{c} {h}' for c, h in ctx['script_sha'].items())}.\n"]


def report(prefix):
    """PREFIX.md and PREFIX.png from PREFIX.csv and PREFIX.json; returns the Markdown."""
    rows, ctx, args = read(prefix)
    scatter = scatter_of(rows)
    tkey = "cpu_s" if args.time_axis == "cpu" else "wall_s"
    fronts = plot(rows, scatter, prefix + ".png", tkey)
    front_text = [f"- {c}: " + ", ".join(f"{setting(r)} [{r['sweep']}]" for r in fr)
                  for c, fr in fronts.items()]
    md = header(ctx, args) + [
        results_table(rows), "",
        "![run time against error](%s.png)\n" % os.path.basename(prefix),
        "## Fastest settings within the sample scatter\n",
        *fastest(rows, scatter, tkey), *damping_advice(rows, scatter, ctx, args, tkey),
        *ranks_advice(rows, scatter), "",
        *ranks_section(rows, ctx, args),
        f"Pareto front ({args.time_axis} time vs RMS Δ(σ1/σ3) against the case reference, "
        f"circled in the plot):", *front_text, "",
        "## Notes\n", *notes(rows, ctx, args), ""]
    text = "\n".join(md)
    with open(prefix + ".md", "w") as f:
        f.write(text)
    return text


# ----------------------------------------------------------------------------- the plot
STYLE = {"rate": ("o", "C0"), "every": ("s", "C1"), "dt": ("^", "C2"), "seed": ("*", "C3"),
         "damping viscous": ("D", "C4"), "damping local": ("P", "C6"), "ranks": ("h", "C5")}
SWEPT = ("rate", "every", "dt", "damping", "ranks")


def _series(r):
    return r["sweep"] + (" " + r["damping"].split(":")[0] if r["sweep"] == "damping" else "")


def _label(r, sweep, multirate):
    lab = {"rate": f"{r['rate']:g}", "every": f"e{r['every']}", "dt": f"dt {r['dt']:g}",
           "damping viscous": f"v{r['damping'].split(':')[1]}",
           "damping local": f"α{r['damping'].split(':')[1]}",
           "ranks": f"{r['ranks']}r"}.get(sweep, "")
    return lab + (f"@{r['rate']:g}" if sweep.startswith("damping") and multirate else "")


def plot_case(ax, rows, case, scatter, tkey):
    """One panel: run time against the RMS error vs the case reference; returns the
    Pareto front (rows)."""
    # damping: viscous and local as two series; ranks: x = wall time whatever the axis
    # (an N-rank run's CPU time is that of its N ranks), not on the Pareto front
    def xof(r):
        return r["wall_s"] if r["sweep"] == "ranks" else r[tkey]

    rs = [r for r in rows if r["case"] == case and r["sweep"] in SWEPT]
    # the default damping at a rate of the rate sweep is that sweep's point already
    rated = {r["rate"] for r in rs if r["sweep"] == "rate"}
    pts = [r for r in rs if r["status"] == "ok"
           and (not r["is_reference"] or r["sweep"] == "ranks")
           and not (r["sweep"] == "damping" and r["default_damping"] and r["rate"] in rated)
           and r.get("rms_ratio_vs_case_ref", np.nan) > 0 and np.isfinite(xof(r))]
    sc = scatter.get(case, {}).get("rms_ratio", np.nan)
    lo = min([r["rms_ratio_vs_case_ref"] for r in pts] + ([sc] if np.isfinite(sc) else []) + [1.0]) / 2.5
    for sweep, (mk, col) in STYLE.items():
        sel = [r for r in pts if _series(r) == sweep]
        if sel:
            ax.scatter([xof(r) for r in sel], [r["rms_ratio_vs_case_ref"] for r in sel],
                       marker=mk, color=col, s=50, zorder=3,
                       label=f"{sweep} sweep" + (" (x = wall time)" if sweep == "ranks" else ""))
            multirate = len({x["rate"] for x in sel}) > 1
            for r in sel:
                ax.annotate(_label(r, sweep, multirate), (xof(r), r["rms_ratio_vs_case_ref"]), fontsize=7,
                            xytext=(4, 3), textcoords="offset points")
    for r in [r for r in rs if r["is_reference"] and r["sweep"] == "rate" and r["status"] == "ok"]:
        ax.scatter([r[tkey]], [lo], marker="v", color="k", s=60, zorder=3,
                   label=f"case reference (rate {r['rate']:g}, error 0)")
    for r in [r for r in rs if r["status"] != "ok"]:
        ax.scatter([xof(r) if np.isfinite(xof(r)) else 1], [lo], marker="x",
                   color="r", s=60, zorder=3, label="failed/unstable")
    fr = []
    cand = [r for r in pts if r["sweep"] != "ranks"]
    if cand:
        front = pareto([(r[tkey], r["rms_ratio_vs_case_ref"]) for r in cand])
        fr = sorted([cand[i] for i in front], key=lambda r: r[tkey])
        ax.plot([r[tkey] for r in fr], [r["rms_ratio_vs_case_ref"] for r in fr], "k--",
                lw=1, zorder=2, label="Pareto front")
        ax.scatter([r[tkey] for r in fr], [r["rms_ratio_vs_case_ref"] for r in fr],
                   s=160, facecolors="none", edgecolors="k", zorder=4)
    for r in rows:
        if r["case"] == case and r["sweep"] == "seed@rate" and r["status"] == "ok":
            ax.axhline(r["rms_ratio"], color="C3", lw=0.8, ls=":", label="scatter at other rates")
            ax.annotate(f"scatter @ {r['rate']:g} /s", (ax.get_xlim()[0], r["rms_ratio"]),
                        fontsize=6, color="C3", xytext=(2, 2), textcoords="offset points")
    s = scatter.get(case)
    if s and np.isfinite(s.get("rms_ratio", np.nan)):
        ax.axhspan(lo / 10, s["rms_ratio"], color="0.9", zorder=0, label="below the scatter: noise")
        ax.axhline(s["rms_ratio"], color="C3", lw=1.5,
                   label=f"sample scatter (RMS of {s['n']} seed pairs) = {s['rms_ratio']:.3g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(bottom=lo / 1.5)
    ax.set_xlabel(("CPU time (user+sys)" if tkey == "cpu_s" else "wall time ('Loop time')")
                  + " of the shear run [s], 1 rank"
                  + ("; ranks sweep: wall time on N ranks" if any(r["sweep"] == "ranks" for r in pts) else ""))
    ax.set_ylabel("RMS Δ(σ1/σ3) vs the case reference")
    ax.set_title(f"{case}: run time against error")
    ax.grid(True, which="both", alpha=0.3)
    h, lab = ax.get_legend_handles_labels()
    uniq = dict(zip(lab, h))
    ax.legend(uniq.values(), uniq.keys(), fontsize=7, loc="upper center",
              bbox_to_anchor=(0.5, -0.13), ncol=2)
    return fr


def plot(rows, scatter, path, tkey):
    """Run time against error, one panel per case; returns {case: Pareto front}."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = [c for c in CASES if any(r["case"] == c for r in rows)]
    fig, axes = plt.subplots(1, len(cases), figsize=(6.5 * len(cases), 6.2), squeeze=False)
    fronts = {}
    for ax, case in zip(axes[0], cases):
        fr = plot_case(ax, rows, case, scatter, tkey)
        if fr:
            fronts[case] = fr
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return fronts

