"""The comparison table over replicate samples: every quantity as mean +- 95 % interval
(Student t, n - 1 degrees of freedom) per boundary, and the rigid - membrane difference
paired by sample, with its interval and whether that interval excludes 0.

A sample is a dict {case: Run} (report.load_run) with the cases CASES; a quantity a
sample could not measure is left out of that quantity's n (and said so in the cell).
"""
import csv
import io
import math

from . import stats
from .curves import NotMeasurable, measured

CASES = ("rigid", "membrane")


def _band(run, key):
    if run.band is None:
        return run.band_reason or NotMeasurable("no displacement field")
    return run.band["field"]["band"][key]


def _scaled(x, scale):
    return x * scale if measured(x) and x is not None else x


def _plus_half(angle):
    return angle if not measured(angle) else 45.0 + angle / 2.0


def _per_d50(run):
    t = _band(run, "thickness")
    return t if not measured(t) else t / run.d50


def _ev_end(run):
    return float(run.table["ev"][-1])


# (label, value of one run in the unit shown, decimals or a format)
QUANTITIES = [
    ("peak s1/s3", lambda r: r.curves["peak_ratio"], 3),
    ("eps_11 at peak [%]", lambda r: _scaled(r.curves["ea_peak"], 100), 2),
    ("s1/s3 at the end", lambda r: r.curves["ratio_end"], 3),
    ("eps_11 at the end [%]", lambda r: _scaled(r.curves["ea_end"], 100), 2),
    ("E, initial [MPa]", lambda r: _scaled(r.curves["E"], 1e-6), 1),
    ("nu, initial", lambda r: r.curves["nu"], 3),
    ("E, initial, Love-Weber stress inside [MPa]", lambda r: _scaled(r.curves["E_lw"], 1e-6), 1),
    ("eps_11 at half the peak deviator (E50 window) [%]", lambda r: _scaled(r.curves["ea50"], 100), 3),
    ("E50, secant, boundaries [MPa]", lambda r: _scaled(r.curves["E50"], 1e-6), 1),
    ("nu50, secant, boundaries", lambda r: r.curves["nu50"], 3),
    ("E50, Love-Weber stress / particle strain [MPa]", lambda r: _scaled(r.curves.get("E50_p"), 1e-6), 1),
    ("nu50, particle strain", lambda r: r.curves.get("nu50_p"), 3),
    ("phi from peak [deg]", lambda r: r.curves["phi_peak"], 2),
    ("psi, max dilation [deg]", lambda r: r.curves["psi"], 2),
    ("eps_v at the end [%] (contraction > 0)", lambda r: _scaled(_ev_end(r), 100), 2),
    ("band inclination, measured [deg from horizontal]", lambda r: _band(r, "angle"), 1),
    ("45 + phi/2 (Mohr-Coulomb) [deg]", lambda r: _plus_half(r.curves["phi_peak"]), 1),
    ("45 + psi/2 (Roscoe) [deg]", lambda r: _plus_half(r.curves["psi"]), 1),
    ("band thickness, measured [mm]", lambda r: _scaled(_band(r, "thickness"), 1e3), 1),
    ("band thickness / D50", _per_d50, 1),
    ("f0 at the end [N]", lambda r: r.curves["f0_end"], 1),
    ("correlation of mean lambda with a", lambda r: r.curves["corr_gsi_a"], 3),
    ("correlation of mean lambda (rattlers as 1) with a", lambda r: r.curves["corr_gsi_all_a"], 3),
    ("max inertial number I", lambda r: r.curves["I_max"], "{:.2e}"),
    ("Love-Weber s_xx / s3 at the end", lambda r: r.curves["lw_check"], 3),
]


def sample_values(samples):
    """{label: {case: [value or NotMeasurable per sample]}}."""
    out = {}
    for label, value, _ in QUANTITIES:
        out[label] = {}
        for case in CASES:
            cells = []
            for s in samples:
                run = s.get(case)
                v = NotMeasurable(f"no {case} run") if run is None else value(run)
                cells.append(NotMeasurable("not computed") if v is None else v)
            out[label][case] = cells
    return out


def _numbers(cells):
    return [float(v) if measured(v) else math.nan for v in cells]


class Row:
    """One quantity: an Interval per case, the paired difference, and why values are missing."""

    def __init__(self, label, fmt, cells):
        self.label, self.fmt, self.cells = label, fmt, cells
        self.n_samples = len(next(iter(cells.values())))
        self.per_case = {c: stats.mean_interval(_numbers(v)) for c, v in cells.items()}
        self.difference = stats.paired_difference(_numbers(cells["rigid"]),
                                                  _numbers(cells["membrane"]))

    def reason(self, case):
        """The first reason a sample could not measure the quantity, or None."""
        return next((str(v) for v in self.cells[case] if not measured(v)), None)

    def missing(self, case, names):
        """[(sample name, reason)] of the samples that could not measure it."""
        return [(name, str(v)) for name, v in zip(names, self.cells[case]) if not measured(v)]


def aggregate(samples):
    """[Row] in table order for the samples (list of {case: Run})."""
    values = sample_values(samples)
    return [Row(label, fmt, values[label]) for label, _, fmt in QUANTITIES]


def _number(x, fmt, sign=False):
    """x in the row's format (decimals or a format string), '+' in front when sign; a
    value that rounds to zero is written without a minus."""
    text = fmt.format(abs(x)) if isinstance(fmt, str) else f"{abs(x):.{fmt}f}"
    negative = x < 0 and float(text) != 0.0
    return ("-" if negative else "+" if sign else "") + text


def interval_text(iv, fmt, n_samples, reason=None, sign=False):
    """'m +- h', 'm' (n = 1), with '(n = k of N)' when samples are missing (their
    reasons: missing_notes); with no value the first sample's reason."""
    if iv.n == 0:
        text = reason or "not measurable"
        if n_samples > 1:
            first = text[len("not measurable "):] if text.startswith("not measurable (") else ""
            text = f"not measurable in any of the {n_samples} samples" + (
                f" (the first: {first[1:-1]})" if first else "")
        return text
    text = _number(iv.mean, fmt, sign)
    if iv.has_interval:
        text += " ± " + _number(iv.half_width, fmt)
    if iv.n < n_samples:
        text += f" (n = {iv.n} of {n_samples})"
    return text


def missing_notes(rows, names):
    """One line per quantity, case and sample left out of a mean that has other samples."""
    notes = []
    for r in rows:
        for c in CASES:
            if 0 < r.per_case[c].n < r.n_samples:
                notes += [f"{r.label}, {c}, {name}: {why}" for name, why in r.missing(c, names)]
    return notes


def significance_text(iv):
    if iv.significant is None:
        return "– (n = 1)" if iv.n == 1 else "–"
    return "yes" if iv.significant else "no"


HEADER = ["quantity", "rigid", "membrane", "rigid − membrane (paired)", "significant"]


def build_table(rows):
    """(header, rows of text) of the Markdown table."""
    out = []
    for r in rows:
        out.append([r.label]
                   + [interval_text(r.per_case[c], r.fmt, r.n_samples, r.reason(c)) for c in CASES]
                   + [interval_text(r.difference, r.fmt, r.n_samples, "not measurable", sign=True),
                      significance_text(r.difference)])
    return HEADER, out


def preamble(names):
    n = len(names)
    if n == 1:
        return (f"n = 1 sample ({names[0]}): single values, no confidence interval "
                "(`./run.sh --samples N` for N >= 2).\n")
    t = stats.t_critical(n)
    return (f"n = {n} samples ({', '.join(names)}), each sheared with both boundaries. "
            f"Cells: mean ± half-width of the {100 * stats.CONFIDENCE:.0f} % confidence "
            f"interval of the mean, t s / sqrt(n) with Student's t_{{0.975, {n - 1}}} = "
            f"{t:.3f} and s the sample standard deviation. rigid − membrane: the difference "
            "paired by sample (both boundaries shear the same prepared sample), mean ± "
            "its interval; significant = the interval excludes 0.\n")


def to_markdown(rows, names):
    header, cells = build_table(rows)
    lines = [preamble(names), "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(c.replace("|", "/") for c in row) + " |" for row in cells]
    missing = missing_notes(rows, names)
    if missing:
        lines += ["", "Left out of a mean (n = k of N):"] + [f"- {m}" for m in missing]
    return "\n".join(lines) + "\n"


def to_csv(rows):
    """Numbers in the unit of the label: mean, half-width (empty when n < 2), n."""
    out = io.StringIO()
    w = csv.writer(out)
    w.writerow(["quantity"] + [f"{c}_{k}" for c in CASES + ("difference",)
                               for k in ("mean", "half_width", "n")] + ["significant"])

    def num(x):
        return "" if not math.isfinite(x) else repr(x)

    for r in rows:
        ivs = [r.per_case[c] for c in CASES] + [r.difference]
        sig = r.difference.significant
        w.writerow([r.label] + [x for iv in ivs for x in (num(iv.mean), num(iv.half_width), iv.n)]
                   + ["" if sig is None else ("yes" if sig else "no")])
    return out.getvalue()


def samples_csv(rows, names):
    """Every sample's value of every quantity (empty: not measurable)."""
    out = io.StringIO()
    w = csv.writer(out)
    w.writerow(["quantity", "case"] + list(names))
    for r in rows:
        for c in CASES:
            w.writerow([r.label, c] + ["" if not math.isfinite(x) else repr(x)
                                       for x in _numbers(r.cells[c])])
    return out.getvalue()
