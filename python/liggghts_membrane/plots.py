"""The PNG figures: rigid and membrane on the same axes wherever both make sense.

Every function takes `runs`, a list of Run objects (see biaxial_report.py) with
.name, .table (OutputTable), .curves (dict of curves.analyse_curves) and, where
available, .roses and .fields; a missing column or file is written on the panel.
"""
import math

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import rose, stats  # noqa: E402
from .curves import measured  # noqa: E402

COLOURS = {"rigid": "C0", "membrane": "C3"}
OTHER_COLOURS = ("C2", "C1", "C4", "C5", "C6", "C8", "C9", "C7")


def assign_colours(runs):
    """Rigid and membrane keep their colours; other runs take the others in turn."""
    others = iter(OTHER_COLOURS * len(runs))
    for run in runs:
        run.colour = COLOURS.get(run.name) or next(others)


def _colour(run):
    return run.colour or COLOURS.get(run.name, "C2")


def _note(ax, text):
    ax.text(0.02, 0.02, text, transform=ax.transAxes, fontsize=7, va="bottom", color="0.3")


def stress_strain(runs, path):
    """sigma1/sigma3 and eps_v against eps_11, with the peak marked."""
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.5, 7), sharex=True)
    for run in runs:
        t, c = run.table, _colour(run)
        ax1.plot(100 * t["ea"], t["s1/s3"], color=c, label=run.name)
        ax2.plot(100 * t["ea"], 100 * t["ev"], color=c, label=run.name)
        if measured(run.curves["peak_index"]):
            k = run.curves["peak_index"]
            ax1.plot(100 * t["ea"][k], t["s1/s3"][k], "o", color=c, mfc="none",
                     label=f"{run.name} peak {t['s1/s3'][k]:.3f} at {100 * t['ea'][k]:.2f} %")
        if measured(run.curves["psi"]):
            e = run.curves["ea_psi"]
            ax2.plot(100 * e, 100 * np.interp(e, t["ea"], t["ev"]), "x", color=c,
                     label=f"{run.name} max dilation rate, psi = {run.curves['psi']:.1f}°")
    ax1.set_ylabel(r"$\sigma_1/\sigma_3$")
    ax2.set_ylabel(r"$\varepsilon_v$ [%] (contraction > 0)")
    ax2.set_xlabel(r"$\varepsilon_{11}$ [%]")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def _series(ax, runs, column, style="-", label=None):
    """Plot one column against eps_11 for every run; note the runs that lack it."""
    lacking = []
    for run in runs:
        if run.table.has(column):
            ax.plot(100 * run.table["ea"], run.table[column], style, color=_colour(run),
                    label=f"{run.name} {label or column}")
        else:
            lacking.append(run.name)
    if lacking:
        _note(ax, f"no '{column}' column: {', '.join(lacking)}")


def fabric_evolution(runs, path):
    """a (with a_n, a_t), C_n and Z_m, mean lambda against eps_11, and a against lambda."""
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5))
    ax_a, ax_c, ax_l, ax_al = axes.ravel()
    _series(ax_a, runs, "a", "-", "a")
    _series(ax_a, runs, "an", "--", r"$a_n$")
    _series(ax_a, runs, "at", ":", r"$a_t$")
    ax_a.set_ylabel("anisotropy")
    _series(ax_c, runs, "C_n", "-", r"$C_n$")
    _series(ax_c, runs, "Zm", "--", r"$Z_m$")
    ax_c.set_ylabel("coordination number")
    _series(ax_l, runs, "gsi", "-", r"mean $\lambda$ (2+ contacts)")
    if any(r.table.has("gsi_all") for r in runs):
        _series(ax_l, [r for r in runs if r.table.has("gsi_all")], "gsi_all", "--",
                r"mean $\lambda$, rattlers as 1 (published)")
    ax_l.set_ylabel(r"mean geometrical stability index $\lambda$")
    for ax in (ax_a, ax_c, ax_l):
        ax.set_xlabel(r"$\varepsilon_{11}$ [%]")
    lacking = []
    for run in runs:
        t = run.table
        if t.has("a") and t.has("gsi"):
            ax_al.plot(t["gsi"], t["a"], "-", color=_colour(run), label=run.name)
            ax_al.plot(t["gsi"][:1], t["a"][:1], "o", color=_colour(run), mfc="none")
        else:
            lacking.append(run.name)
    if lacking:
        _note(ax_al, f"no 'a' or 'gsi' column: {', '.join(lacking)}")
    ax_al.set_xlabel(r"mean $\lambda$ (circle: $\varepsilon_{11}$ = 0)")
    ax_al.set_ylabel("a")
    for ax in axes.ravel():
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def _stairs(centres_deg, values):
    """Closed stair polygon (angles in rad, radii) of a polar histogram."""
    width = 360.0 / len(centres_deg)
    edges = np.radians(np.column_stack([centres_deg - width / 2, centres_deg + width / 2]).ravel())
    radii = np.repeat(values, 2)
    return np.append(edges, edges[0]), np.append(radii, radii[0])


def rose_states(run):
    """[(label, step)] of the rose states drawn: 0 %, the peak (when there is one), the end."""
    t = run.table
    states = [("start", int(t["step"][0]))]
    if measured(run.curves["peak_index"]):
        states.append(("peak", int(t["step"][run.curves["peak_index"]])))
    states.append(("end", int(t["step"][-1])))
    return states


def rose_panel_data(run, step, block_step, block):
    """What one rose panel draws for one run: the histogram, and the fitted curves
    with the parameters of the OUT line nearest to the block's step."""
    params = rose.fit_parameters(run.table, block_step)
    theta = np.linspace(0.0, 360.0, 361)
    data = {"params": params, "theta": theta, "centres": block["centre_deg"],
            "density": rose.normal_density(block["count"], block["centre_deg"]),
            "mean_fn": block["mean_fn"], "block_step": block_step,
            "ea": float(np.interp(block_step, run.table["step"], run.table["ea"]))}
    if "a" in params and "theta_a" in params:
        data["E_fit"] = rose.model_normal_density(theta, params["a"], params["theta_a"])
    if all(k in params for k in ("f0", "an", "theta_n")):
        data["f_fit"] = rose.model_mean_force(theta, params["f0"], params["an"], params["theta_n"])
    data["a_hist"] = rose.histogram_anisotropy(block["centre_deg"], block["count"])
    return data


def roses(runs, path):
    """Rose diagrams of the normal density and of the mean normal force at 0 %, peak
    and end, rigid and membrane on the same polar axes. Returns the panel data drawn
    (so that tests can check where the fitted parameters came from)."""
    fig, axes = plt.subplots(2, 3, figsize=(13, 8.5), subplot_kw={"projection": "polar"})
    drawn = {}
    for col, state in enumerate(("start", "peak", "end")):
        axes[0, col].set_title(f"contact normals E(θ): {state}", fontsize=9)
        axes[1, col].set_title(f"mean normal force [N]: {state}", fontsize=9)
        for run in runs:
            steps = dict(rose_states(run))
            if not run.roses or state not in steps:
                why = "no rose file" if not run.roses else "no peak"
                _note(axes[0, col], f"{run.name}: {why}")
                continue
            block_step, block = rose.select_blocks(run.roses, [steps[state]])[0]
            d = rose_panel_data(run, steps[state], block_step, block)
            drawn[(run.name, state)] = d
            c, p = _colour(run), d["params"]
            ang, rad = _stairs(d["centres"], d["density"])
            axes[0, col].plot(ang, rad, color=c, lw=0.8, alpha=0.7,
                              label=f"{run.name} ε11={100 * d['ea']:.2f} % "
                                    f"(hist. a={d['a_hist'][0]:.3f})")
            if "E_fit" in d:
                axes[0, col].plot(np.radians(d["theta"]), d["E_fit"], color=c, lw=1.8,
                                  label=f"fit a={p['a']:.3f}, θa={p['theta_a']:.1f}°")
            ang, rad = _stairs(d["centres"], d["mean_fn"])
            axes[1, col].plot(ang, rad, color=c, lw=0.8, alpha=0.7, label=f"{run.name}")
            if "f_fit" in d:
                axes[1, col].plot(np.radians(d["theta"]), d["f_fit"], color=c, lw=1.8,
                                  label=f"fit f0={p['f0']:.3g} N, an={p['an']:.3f}, "
                                        f"θn={p['theta_n']:.1f}°")
    for ax in axes.ravel():
        ax.tick_params(labelsize=7)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=6.5, loc="upper center", bbox_to_anchor=(0.5, -0.06))
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return drawn


def _draw_band(ax, band, x):
    """The fitted band line across the sample, or the reason it was not measured."""
    if measured(band["angle"]) and band["centre"] is not None:
        a = math.radians(band["alpha"])
        span = np.ptp(x, axis=0).max()
        s = np.array([-span, span])
        px = 1000 * (band["centre"][0] + s * math.cos(a))
        py = 1000 * (band["centre"][1] + s * math.sin(a))
        ax.plot(px, py, "k--", lw=1.2)
        ax.set_xlim(1000 * x[:, 0].min(), 1000 * x[:, 0].max())
        ax.set_ylim(1000 * x[:, 1].min(), 1000 * x[:, 1].max())
        thick = band["thickness"]
        text = f"band {band['angle']:.1f}° from horizontal"
        if measured(thick):
            text += f", {1000 * thick:.1f} mm"
        ax.set_xlabel(text, fontsize=8)
    else:
        ax.set_xlabel(str(band["angle"]), fontsize=6, wrap=True)


def field(run, path, max_arrows=2500):
    """Incremental displacement (quiver) and incremental shear strain (colour) for each
    increment of run.fields, the band points outlined and the fitted line drawn."""
    n = len(run.fields)
    fig, axes = plt.subplots(2, n, figsize=(3.6 * n + 1, 11), squeeze=False)
    for col, inc in enumerate(run.fields):
        f, x = inc["field"], inc["field"]["x"]
        title = (f"{run.name}: ε11 {100 * inc['ea'][0]:.2f}→{100 * inc['ea'][1]:.2f} %"
                 f"\n({inc['label']})")
        ax = axes[0, col]
        step = max(1, len(x) // max_arrows)
        ax.quiver(1000 * x[::step, 0], 1000 * x[::step, 1], 1000 * f["du"][::step, 0],
                  1000 * f["du"][::step, 1], angles="xy", scale_units="xy", scale=None,
                  width=0.002)
        ax.set_title(title, fontsize=9)
        ax = axes[1, col]
        g = f["gamma"]
        ok = np.isfinite(g)
        hi = np.nanpercentile(g, 99) if ok.any() else 1.0
        size = float(np.clip(12000.0 / max(len(x), 1), 2.0, 40.0))   # fills the sample
        sc = ax.scatter(1000 * x[ok, 0], 1000 * x[ok, 1], c=g[ok], s=size, cmap="viridis",
                        vmin=0, vmax=hi)
        band = f["band"]
        if band["band"].any():
            ax.scatter(1000 * x[band["band"], 0], 1000 * x[band["band"], 1], s=size / 2, c="r")
        _draw_band(ax, band, x)
        _draw_band(axes[0, col], band, x)
        fig.colorbar(sc, ax=ax, shrink=0.6, label=r"$\gamma_{max}$ increment")
        for a in axes[:, col]:
            a.set_aspect("equal")
            a.tick_params(labelsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def replicate_curves(samples, case, column, scale=1.0):
    """(grid [%], mean, half-width, n, the samples' (x [%], y)) of one column of one case
    over the samples, on the strain grid all of them cover (stats.common_grid)."""
    tables = [s[case].table for s in samples if case in s]
    xs = [100 * t["ea"] for t in tables]
    ys = [scale * t[column] for t in tables]
    grid = stats.common_grid(xs)
    mean, half, n = stats.mean_band(xs, ys, grid)
    return grid, mean, half, n, list(zip(xs, ys))


def stress_strain_band(samples, path, cases=("rigid", "membrane")):
    """sigma1/sigma3 and eps_v against eps_11: the mean over the samples (thick line),
    its 95 % interval (band, when n >= 2) and each sample (thin lines). Returns what
    was drawn: {(case, column): (grid, mean, half, n)}."""
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.5, 7), sharex=True)
    drawn = {}
    for case in cases:
        if not any(case in s for s in samples):
            continue
        c = COLOURS.get(case, "C2")
        for ax, column, scale in ((ax1, "s1/s3", 1.0), (ax2, "ev", 100.0)):
            grid, mean, half, n, each = replicate_curves(samples, case, column, scale)
            drawn[(case, column)] = (grid, mean, half, n)
            for k, (x, y) in enumerate(each):
                ax.plot(x, y, color=c, lw=0.5, alpha=0.35,
                        label=f"{case}, each sample" if k == 0 else None)
            label = f"{case}, mean of {n.max()}"
            if np.isfinite(half).any():
                ax.fill_between(grid, mean - half, mean + half, color=c, alpha=0.25, lw=0,
                                label=f"{case}, {100 * stats.CONFIDENCE:.0f} % interval of the mean")
            ax.plot(grid, mean, color=c, lw=1.8, label=label)
    ax1.set_ylabel(r"$\sigma_1/\sigma_3$")
    ax2.set_ylabel(r"$\varepsilon_v$ [%] (contraction > 0)")
    ax2.set_xlabel(r"$\varepsilon_{11}$ [%]")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    if ax1.get_legend_handles_labels()[0]:          # one legend: the same lines below
        ax1.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return drawn
