"""The report of bench/stability_sweep.py: PREFIX.md and PREFIX.png from PREFIX.csv
(one row per run and sweep) and PREFIX.json (the command, its options, the
examples' defaults the runs used, the samples, hashes and invocations). Pure
functions of those: `report(prefix)` makes the report again from the two files alone
(bench/stability_sweep.py --from-csv).
"""
import argparse
import math
import os
import re

import numpy as np

from liggghts_membrane.bench.common import fmt, markdown_table as table, read_context, read_rows, sci

# a number in a message (not the 2 of "membrane2d")
NUMBER = r"(?<![A-Za-z_\d])[-+]?\d[\d.]*(?:e[-+]?\d+)?"
INT_KEYS = ("steps", "steps_planned")
TEXT_KEYS = ("sweep", "case", "sample", "setting", "mode", "status", "how", "error", "warnings", "run")


def short(msg):
    """A message without its source location '(/path/file.cpp:123)'."""
    return re.sub(r"\s*\((?:[./\w-]+/)?[\w.-]+\.(?:cpp|h):\d+\)", "", msg).strip()


CSV_KEYS = ["sweep", "case", "sample", "setting", "x", "dt", "dt_frac", "alpha", "kn", "kn_factor",
            "p_factor", "mode", "status", "how", "error", "warnings", "steps", "steps_planned",
            "wall_s", "cpu_s", "I_max", "peak_ratio", "d_peak", "final_ev", "KE_max", "KE_ratio",
            "servo_rms", "servo_max", "servo_lag1", "overlap_mean", "overlap_max", "escaped", "chain_failures",
            "widenings", "s1_end", "porosity", "run"]


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


def plot(rows, path, args, ctx):
    """One panel per sweep: the quantity that shows the failure against the parameter."""
    d = ctx["defaults"]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = [("dt", "dt / sqrt(m_min/k_n)", "KE_max", "max KE [J]"),
              ("alpha", "servo gain factor α (rigid)", "servo_rms", "RMS(s3/σ3 − 1)"),
              ("pressure", "target / initial membrane pressure", "KE_max", "max KE [J]"),
              ("kn", f"k_n / {sci(d['kn'])} (dt {sci(d['dt'])} s)", "KE_max", "max KE [J]"),
              ("kn", f"k_n / {sci(d['kn'])} (dt {sci(d['dt'])} s)", "overlap_mean", "max mean overlap f̄₀/k_n / d̄"),
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
            ax.axvline(d["dt"] / math.sqrt(ctx["dense"]["m_min"] / d["kn"]), color="k", lw=0.8, ls=":",
                       label=f"default {sci(d['dt'])} s")
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


def by(rows, sw, c=None):
    return [r for r in rows if r["sweep"] == sw and (c is None or r["case"] == c)]


def fail(r, label):
    return f"{label}: {r['status']}: {r['how'][:170]}"


def limits_table(rows, ctx, args):
    """The largest stable value and the first failure of each parameter."""
    d, limits = ctx["defaults"], []

    # --- dt
    for c in ("rigid", "membrane"):
        rs = by(rows, "dt", c)
        if rs:
            b, bad = largest_ok(rs, "x"), first_bad(rs, "x")
            limits.append((f"time step, {c}",
                           f"{b['x']:.3g} × √(m_min/k_n) = {b['dt']:.3g} s "
                           f"({b['dt'] / d['dt']:.3g} × the default {sci(d['dt'])} s)" if b else "none",
                           fail(bad, f"{bad['x']:.3g} × ({bad['dt']:.3g} s)") if bad else "none failed"))
    rs = by(rows, "alpha")
    if rs:
        b, bad = largest_ok(rs, "x"), first_bad(rs, "x")
        limits.append(("side-wall servo gain α (rigid)",
                       f"α {b['x']:g} (servo error RMS {100 * b['servo_rms']:.2g} %)" if b else "none",
                       fail(bad, f"α {bad['x']:g}") if bad else "none failed"))
    for mode in ("jump", "ramp"):
        rs = [r for r in by(rows, "pressure") if r["mode"].startswith(mode)]
        if rs:
            b, bad = largest_ok(rs, "x"), first_bad(rs, "x")
            limits.append((f"membrane pressure {mode}" + (f" over {args.nramp} steps" if mode == "ramp" else "")
                           + f" from {sci(d['sigma'])} Pa",
                           f"{b['x']:g}× = {b['x'] * d['sigma']:.3g} Pa (max KE {b['KE_max']:.3g} J, escaped "
                           f"{fmt(b['escaped'], '{:g}')}, max δ/d_min {fmt(b['overlap_max'], '{:.2f}')})"
                           if b else "none",
                           fail(bad, f"{bad['x']:g}×") if bad else "none failed"))
    for sw in ("kn", "kn (prepared at kn)"):
        for c in ("rigid", "membrane"):
            rs = by(rows, sw, c)
            if rs:
                ok = sorted([r for r in rs if r["status"] == "ok"], key=lambda r: r["x"])
                bads = sorted([r for r in rs if r["status"] != "ok"], key=lambda r: r["x"])
                limits.append((f"k_n at dt {sci(d['dt'])} s, {c}" + (", sample prepared at that k_n" if "prepared" in sw
                                                                      else f", sample prepared at {sci(d['kn'])}"),
                               ("ok at " + ", ".join(f"× {r['x']:g}" for r in ok)) if ok else "none",
                               "; ".join(fail(r, f"× {r['x']:g}")[:130] for r in bads) or "none failed"))
    for c in ("rigid", "membrane"):
        for r in [r for r in by(rows, "loose", c) if r["sample"] != "dense"]:
            limits.append((f"loose sample {r['setting']}, {c}",
                           f"{r['status']}: porosity {fmt(r['porosity'], '{:.4f}')} (dense "
                           f"{ctx['dense']['porosity']:.4f}), peak σ1/σ3 {fmt(r['peak_ratio'], '{:.2f}')} "
                           f"({fmt(r['d_peak'], '{:+.2f}')} vs dense), final ε_v {fmt(r['final_ev'], '{:.2f}', 100)} %"
                           + (f", escaped {fmt(r['escaped'], '{:g}')}, chain failures "
                              f"{fmt(r['chain_failures'], '{:g}')}" if c == "membrane" else ""),
                           (r["how"] or "—")[:170]))
    return table(limits, [("parameter", lambda t: t[0]), ("largest stable (status ok)", lambda t: t[1]),
                          ("first failure: how it fails", lambda t: t[2])])


def accuracy_and_warning_notes(rows):
    """What the stable runs say about accuracy, and which guards fired where."""
    notes = []
    for c in ("rigid", "membrane"):
        ok = [r for r in by(rows, "dt", c) if r["status"] == "ok"]
        if len(ok) > 1:
            lo, hi = min(ok, key=lambda r: r["peak_ratio"]), max(ok, key=lambda r: r["peak_ratio"])
            notes.append(f"- Peak σ1/σ3 of the stable time-step runs, {c}: {lo['peak_ratio']:.2f} "
                         f"(dt {lo['x']:.3g} × √(m/k)) to {hi['peak_ratio']:.2f} ({hi['x']:.3g} ×), without a "
                         "trend in dt: on this small sample the peak of one run is sensitive to any "
                         "perturbation, so Δpeak is no accuracy measure here (bench/accuracy_sweep.py "
                         "compares runs with the sample-to-sample scatter).")
    kinds = {}
    for r in {r["run"]: r for r in rows}.values():
        # each kind once per run, in the order of the run's warnings (deterministic)
        for w in dict.fromkeys(re.sub(NUMBER, "#", short(x))[:90]
                               for x in r["warnings"].split(" | ") if x):
            kinds.setdefault(w, []).append(r)
    for w, rs in sorted(kinds.items(), key=lambda kv: -len(kv[1])):
        nok = sum(r["status"] == "ok" for r in rs)
        notes.append(f"- Warning \"{w}…\" in {len(rs)} run{'s' if len(rs) > 1 else ''} ({nok} of them ok, "
                     f"{len(rs) - nok} unstable/error/failed).")

    return notes


def sweep_sections(rows, ctx, args):
    """A table per sweep."""
    d, sec = ctx["defaults"], []
    cols_dt = [("setting", lambda r: r["setting"]), ("dt / √(m/k)", lambda r: fmt(r["dt_frac"], "{:.3g}"))] + COMMON
    MEM = [("escaped", lambda r: fmt(r["escaped"], "{:g}")),
           ("chain failures", lambda r: fmt(r["chain_failures"], "{:g}"))]
    for c in ("rigid", "membrane"):
        if by(rows, "dt", c):
            sec += [f"### Time step, {c}\n", table(sorted(by(rows, "dt", c), key=lambda r: r["x"]),
                                                    cols_dt + (MEM if c == "membrane" else [])), ""]
    if by(rows, "alpha"):
        cols = [("setting", lambda r: r["setting"]),
                ("servo error RMS [%]", lambda r: fmt(r["servo_rms"], "{:.2g}", 100)),
                ("servo error max [%]", lambda r: fmt(r["servo_max"], "{:.2g}", 100)),
                ("lag-1 corr.", lambda r: fmt(r["servo_lag1"], "{:.2f}"))] + COMMON
        sec += ["### Servo gain of the rigid side walls (in.shear_rigid -var alpha)\n",
                "Servo error = RMS and max of s3/σ3 − 1 over the output lines (every "
                f"{args.dstrain_out:g} of strain, an odd number of steps); 'unstable' above --servo-tol "
                f"{args.servo_tol:g}. 'lag-1 corr.': correlation of consecutive lines' deviations; "
                "near −1 = a period-2 (every other step) oscillation of the servo loop.\n",
                table(sorted(by(rows, "alpha"), key=lambda r: r["x"]), cols), ""]
    if by(rows, "pressure"):
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
                f"Membrane at {sci(d['sigma'])} Pa, 2000 steps of settling with servo platens, then the pressure to "
                f"the target (jump, or linear over {args.nramp} steps) and {args.nhold} more steps with "
                "the platens still. 'KE / available': max KE over the kinetic + stored elastic energy at "
                "the start (2·½k_n N_c δ̄², a bound from the mean overlap) + the work of the membrane "
                "(−∫p dA) and platens since then; above 1 energy was created (counted unstable). "
                "δ from compute pair/gran/local (disk–disk contacts).\n",
                table(sorted(by(rows, "pressure"), key=lambda r: (r["mode"], r["x"])), cols), ""]
    kpa = f"{d['sigma'] / 1e3:g} kPa"
    for sw, title in (("kn", f"Contact stiffness at dt {sci(d['dt'])} s on the sample prepared at {sci(d['kn'])} N/m "
                             f"(-var kn of the shears: the first step sees k_n/{sci(d['kn'])} × {kpa})"),
                      ("kn (prepared at kn)", f"Contact stiffness at dt {sci(d['dt'])} s, each sample prepared at "
                                               "that k_n (in.prepare -var kn)")):
        cols = [("setting", lambda r: r["setting"]),
                ("dt / √(m/k)", lambda r: fmt(r["dt_frac"], "{:.3g}")),
                ("max mean δ / d̄ (f̄₀/k_n)", lambda r: fmt(r["overlap_mean"], "{:.2g}"))] + COMMON
        if "prepared" in sw:
            cols.insert(1, ("porosity", lambda r: fmt(r["porosity"], "{:.4f}")))
        for c in ("rigid", "membrane"):
            if by(rows, sw, c):
                sec += [f"### {title}, {c}\n", table(sorted(by(rows, sw, c), key=lambda r: r["x"]),
                                                     cols + (MEM if c == "membrane" else [])), ""]
    if by(rows, "loose"):
        cols = [("case", lambda r: r["case"]), ("sample", lambda r: r["setting"]),
                ("porosity at 100 kPa", lambda r: fmt(r["porosity"], "{:.4f}")),
                ("escaped", lambda r: fmt(r["escaped"], "{:g}")),
                ("chain failures", lambda r: fmt(r["chain_failures"], "{:g}"))] + COMMON
        sec += ["### Loose samples (in.prepare -var n0 N0 -var mugrow 0.9), default settings\n",
                table(sorted(by(rows, "loose"), key=lambda r: (r["case"], r["x"])), cols), ""]

    return sec


def sample_notes(ctx):
    """One line per prepared sample (the dense one first)."""
    notes = []
    for m in ctx["samples"]:
        notes.append(f"- Sample {m['name']} ({', '.join(f'{k} {v:g}' for k, v in m['vars'].items()) or 'defaults'}): "
                     f"{m.get('status')}" + (f", porosity {m['porosity']:.4f} (after growth "
                                             f"{m['porosity_grown']:.4f}), C_n {m['C_n']:.2f}, "
                                             f"equilibrium loop of in.prepare left at step "
                                             f"{m.get('equilibrium_step')} (flag printed after it: ok = {int(m['equilibrium'])}), "
                                             f"{m['wall_s']:.0f} s" if "porosity" in m else
                                             f": {short(m.get('symptom', ''))[:200]}"))
    return notes


def header(ctx, args, name):
    d, dm = ctx["defaults"], ctx["dense"]
    sq0 = math.sqrt(dm["m_min"] / d["kn"])
    took = (f"this invocation took {ctx['took_min']:.1f} min" if ctx.get("took_min") is not None else
            "the runs were made by the invocations listed in the notes")
    return ["# Numerical-stability limits of the biaxial test\n",
            "Command: `" + " ".join(["/usr/bin/python3 bench/stability_sweep.py"] + ctx["argv"]) + "`  ",
            f"Sample: generate_sample.py --scale {args.scale:g} --seed {args.seed} ({dm['N']} disks), "
            f"examples/biaxial/in.prepare: porosity {dm['porosity']:.4f} at {d['sigma'] / 1e3:g} kPa; smallest disk "
            f"d_min = {1e3 * dm['d_min']:.3f} mm, m_min = π r² ρ = {dm['m_min']:.4g} kg, "
            f"√(m_min/k_n) = {sq0:.4g} s at k_n = {sci(d['kn'])} (the default dt {sci(d['dt'])} s is "
            f"{d['dt'] / sq0:.3f} of it; a single linear spring is stable below 2). Shears to "
            f"ε_11 = {args.strain:g} at {args.rate:g} /s; every run on 1 MPI rank, {args.jobs} at a "
            f"time, timeout {args.timeout:.0f} s; {took}. Executable sha256 {ctx['exe_sha']}; scripts "
            + ", ".join(f"{k} {v}" for k, v in ctx["script_sha"].items()) + ".  ",
            "Status: **ok**; **error** = LIGGGHTS stopped with an ERROR line (the first one is shown); "
            "**failed** = crash, timeout or no completion line; **unstable** = it ran to the end but the "
            f"output table shows a symptom (s1/s3 non-finite or > 50; KE blow-up: max KE > "
            f"{args.ke_factor:g} × that of the default run of the same case; rigid servo error RMS > "
            f"{args.servo_tol:g}; membrane chain failures; pressure runs: KE above the energy available). "
            "Warnings: the WARNING lines of the screen output, deduplicated (step numbers dropped), "
            "without the two every run prints (mesh scaled, new thermo_style); all of them are in the "
            f"CSV. 'Δpeak vs default': peak σ1/σ3 − that of the default run of the case (same "
            f"sample unless said). Raw rows: [{name}.csv]({name}.csv).\n",
            "![stability sweeps](%s.png)\n" % name]


def read(prefix):
    """(rows, context, args) of PREFIX.csv and PREFIX.json."""
    ctx = read_context(prefix + ".json")
    return read_rows(prefix + ".csv", INT_KEYS, TEXT_KEYS), ctx, argparse.Namespace(**ctx["args"])


def report(prefix):
    """PREFIX.md and PREFIX.png from PREFIX.csv and PREFIX.json; returns the Markdown."""
    rows, ctx, args = read(prefix)
    plot(rows, prefix + ".png", args, ctx)
    notes = accuracy_and_warning_notes(rows) + sample_notes(ctx) + [
        f"- Invocation {inv['start']}: {inv['wall_s'] / 60:.1f} min wall, {inv['runs']} runs "
        f"executed (executable {inv.get('exe_sha', '?')})." for inv in ctx["invocations"]]
    md = header(ctx, args, os.path.basename(prefix)) + [
        "## Limits found\n", limits_table(rows, ctx, args), "",
        "## Sweeps\n", *sweep_sections(rows, ctx, args),
        "## Notes\n", *notes, ""]
    text = "\n".join(md)
    with open(prefix + ".md", "w") as f:
        f.write(text)
    return text
