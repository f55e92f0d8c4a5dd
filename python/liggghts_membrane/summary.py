"""The rigid-vs-membrane table: rows = quantities, columns = runs.

Every cell is computed from the run's files; a cell that cannot be measured
holds 'not measurable (reason)'.
"""
import csv
import io

from .curves import NotMeasurable, measured


def _value(x, scale=1.0, fmt="{:.3g}"):
    """A number scaled and formatted, or the NotMeasurable text."""
    if x is None:
        return "not measurable (not computed)"
    if not measured(x):
        return str(x)
    if isinstance(x, str):
        return x
    return fmt.format(x * scale)


def _combine(f, *values):
    """f(values) when all are measured, else the first NotMeasurable."""
    for v in values:
        if not measured(v):
            return v
    return f(*values)


def _band(run, key):
    if run.band is None:
        return run.band_reason or NotMeasurable("no displacement field")
    return run.band["field"]["band"][key]


def _window_text(run):
    w = run.curves["elastic_window"]
    if w is None:
        return run.curves["E"]
    return (f"eps_11 {100 * w[0]:.3f}-{100 * w[1]:.3f} %, {w[2]} lines "
            f"(q - q0 <= {100 * w[3]:.0f} % of the peak rise, >= 4 lines)")


def _band_increment(run):
    if run.band is None:
        return run.band_reason or NotMeasurable("no displacement field")
    a, b = run.band["ea"]
    return f"eps_11 {100 * a:.2f}-{100 * b:.2f} % ({run.band['label'].split(':')[0]})"


def rows_for(run):
    """[(quantity, text)] for one run, in table order."""
    c = run.curves
    phi, psi = c["phi_peak"], c["psi"]
    angle, thick = _band(run, "angle"), _band(run, "thickness")
    d50 = run.d50
    return [
        ("peak s1/s3", _value(c["peak_ratio"], fmt="{:.4f}")),
        ("eps_11 at peak [%]", _value(c["ea_peak"], 100, "{:.3f}")),
        ("s1/s3 at the end", _value(c["ratio_end"], fmt="{:.4f}")),
        ("eps_11 at the end [%]", _value(c["ea_end"], 100, "{:.3f}")),
        ("E, initial [MPa]", _value(c["E"], 1e-6, "{:.2f}")),
        ("nu, initial", _value(c["nu"], fmt="{:.3f}")),
        ("window for E and nu", _value(_window_text(run))),
        ("E, initial, Love-Weber stress inside [MPa]", _value(c["E_lw"], 1e-6, "{:.2f}")),
        ("E50 window: eps_11 from the start to [%]", _value(c["ea50"], 100, "{:.3f}")),
        ("E50, secant, boundaries [MPa]", _value(c["E50"], 1e-6, "{:.2f}")),
        ("nu50, secant, boundaries", _value(c["nu50"], fmt="{:.3f}")),
        ("E50, Love-Weber stress / particle strain [MPa]", _value(c.get("E50_p"), 1e-6, "{:.2f}")),
        ("nu50, particle strain", _value(c.get("nu50_p"), fmt="{:.3f}")),
        ("phi from peak [deg]", _value(phi, fmt="{:.2f}")),
        ("psi, max dilation [deg]", _value(psi, fmt="{:.2f}")),
        ("eps_11 at max dilation [%]", _value(c["ea_psi"] if measured(psi) else psi, 100, "{:.2f}")),
        ("d eps_v / d eps_11 at max dilation",
         _value(c["dilatancy_rate"] if measured(psi) else psi, fmt="{:.4f}")),
        ("band inclination, measured [deg from horizontal]", _value(angle, fmt="{:.1f}")),
        ("band increment", _value(_band_increment(run))),
        ("45 + phi/2 (Mohr-Coulomb) [deg]", _value(_combine(lambda p: 45 + p / 2, phi), fmt="{:.1f}")),
        ("45 + psi/2 (Roscoe) [deg]", _value(_combine(lambda p: 45 + p / 2, psi), fmt="{:.1f}")),
        ("45 + (phi + psi)/4 (Arthur) [deg]",
         _value(_combine(lambda p, q: 45 + (p + q) / 4, phi, psi), fmt="{:.1f}")),
        ("band thickness, measured [mm]", _value(thick, 1e3, "{:.1f}")),
        ("band thickness / D50", _value(_combine(lambda t: t / d50, thick), fmt="{:.1f}")),
        ("D50 [mm]", f"{1e3 * d50:.3f} ({run.d50_source})"),
        ("10-11 x D50 [mm]", f"{1e4 * d50:.1f}-{1.1e4 * d50:.1f}"),
        ("f0 at the end [N]", _value(c["f0_end"], fmt="{:.4g}")),
        ("correlation of mean lambda with a", _value(c["corr_gsi_a"], fmt="{:.3f}")),
        ("correlation of mean lambda (rattlers as 1) with a", _value(c["corr_gsi_all_a"], fmt="{:.3f}")),
        ("max inertial number I", _value(c["I_max"], fmt="{:.2e}")),
        ("Love-Weber s_xx / s3 at the end", _value(c["lw_check"], fmt="{:.3f}")),
    ]


def build_table(runs):
    """(header, rows) with header = ['quantity', run names...]."""
    per_run = [rows_for(r) for r in runs]
    names = [q for q, _ in per_run[0]]
    rows = [[q] + [pr[i][1] for pr in per_run] for i, q in enumerate(names)]
    return ["quantity"] + [r.name for r in runs], rows


NOTES = """\
Notes (conventions of the OUT file: compression and contraction positive; q = s1 - s3):
- E = dq/d eps_11 and nu = -d el/d eps_11 (el = eps_3, lateral strain, contraction > 0;
  i.e. nu = d eps_lat/d eps_11 with eps_lat = -el positive in extension), slopes of
  least-squares lines over the window stated (from the first line to the last one
  with q - q0 <= 30 % of the rise to the peak, at least 4 lines). 2D values, no
  plane-strain conversion. "Love-Weber stress inside": the same slope with q from the
  Love-Weber stress of the disk-disk contacts (syy_lw - sxx_lw) instead of the boundaries.
- E50 = (q(eps50) - q0)/eps50 and nu50 = -el(eps50)/eps50, secants from the first line to
  eps50, the axial strain where q - q0 first reaches half its rise to the peak
  (interpolated). "Love-Weber stress / particle strain": the secant of the internal
  deviator against the particle strain, the best-fit affine deformation (least squares,
  displacement against position) of the disks at least 2 D50 inside the sample outline
  from the first dump frame, interpolated between frames to eps50; nu50 = -eps_xx/eps_yy
  of that fit.
- Correlation of mean lambda with a: Pearson coefficient over the output lines.
- phi from the peak ratio R: R = tan^2(45 + phi/2), i.e. sin phi = (R - 1)/(R + 1).
- psi: sin psi = -d eps_v/(d eps_1 - d eps_3) with eps_v = eps_1 + eps_3 (2D), so
  sin psi = -r/(2 - r), r = d eps_v/d eps_11 (eps_v contraction positive); r is the most
  negative slope of least-squares lines of eps_v(eps_11) over sliding 1 % windows.
- Peak: the maximum of s1/s3 over the output lines; not measurable if it is among the
  last 2 lines (still rising at the end).
- Band: incremental displacements between two dump frames; displacement gradient by
  least squares over the neighbours within 3 D50 (reference: first frame); gamma =
  sqrt((e_xx - e_yy)^2 + (2 e_xy)^2); particles within 3 D50 of the sample outline left
  out; band points: gamma > mean + 1.5 std; line: Hough search (strip 2 x 2 D50) then
  total least squares and a line through slice centres (strip +-6 D50); accepted when
  the band points are >= 2 x more frequent in the strip than all particles, >= 20 of
  them, and the gamma profile across the line peaks at >= 2 x the median gamma outside
  the strip. Inclination: acute angle between the line and the horizontal (sigma_3
  direction), to compare with 45 + phi/2 (Mohr-Coulomb), 45 + psi/2 (Roscoe) and
  45 + (phi + psi)/4 (Arthur). Thickness: full width at half maximum (above its median
  outside the strip) of the profile across the line of the shear strain resolved on the
  band, 2 s.eps.n (s along, n across; bins D50/2, 3-bin running mean, middle 80 % of the
  band's length). The fields are drawn for 0-peak, peak-mid, mid-end and peak-end; the
  table uses peak-end (without a peak: the second half of the run).
- f0: mean normal contact force of the last line (compute fabric); I: largest inertial
  number of the run; Love-Weber s_xx / s3: internal stress check of the last line.
"""


def to_markdown(header, rows, notes=()):
    """A Markdown table, then the notes."""
    esc = [[cell.replace("|", "/") for cell in row] for row in rows]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in esc]
    text = "\n".join(lines) + "\n\n" + NOTES
    if notes:
        text += "\nRun notes:\n" + "".join(f"- {n}\n" for n in notes)
    return text


def to_csv(header, rows):
    out = io.StringIO()
    writer = csv.writer(out)
    writer.writerow(header)
    writer.writerows(rows)
    return out.getvalue()
