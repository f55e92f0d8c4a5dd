"""Macro quantities from the stress-strain table of one run.

Conventions (those of the OUT file): compression and contraction positive.
    ea  = eps_11, axial strain;   el = eps_33 in-plane lateral strain (lateral
    expansion gives el < 0);      ev = volumetric (area) strain.
    q   = s1 - s3 (deviator stress).

Formulas (2D, sigma_3 constant):
    E   = d q / d eps_11                    (slope of a least-squares line)
    nu  = - d el / d eps_11                 (= d eps_lat / d eps_11 with eps_lat = -el,
                                             lateral strain positive in extension)
    phi : s1/s3 = tan^2(45 deg + phi/2)    <=>  sin phi = (R - 1)/(R + 1)
    psi : sin psi = - d eps_v / (d eps_1 - d eps_3),  with d eps_3 = d eps_v - d eps_1,
          so sin psi = - r / (2 - r),   r = d eps_v / d eps_11
          (plane flow: eps_v = eps_1 + eps_3, eps_1 - eps_3 is the shear strain).
"""
import math

import numpy as np


class NotMeasurable:
    """A quantity that could not be measured, with the reason shown in the table."""

    def __init__(self, reason):
        self.reason = reason

    def __str__(self):
        return f"not measurable ({self.reason})"

    __repr__ = __str__


def measured(value):
    """True for a number, False for a NotMeasurable."""
    return not isinstance(value, NotMeasurable)


def friction_angle(ratio):
    """phi [deg] from the principal stress ratio R = s1/s3 (cohesionless Mohr-Coulomb)."""
    return math.degrees(math.asin((ratio - 1.0) / (ratio + 1.0)))


def ratio_from_friction_angle(phi_deg):
    """R = tan^2(45 deg + phi/2)."""
    return math.tan(math.radians(45.0 + phi_deg / 2.0)) ** 2


def dilatancy_angle(rate):
    """psi [deg] from r = d eps_v / d eps_11 (contraction positive): sin psi = -r/(2 - r)."""
    return math.degrees(math.asin(-rate / (2.0 - rate)))


def volume_rate_from_dilatancy(psi_deg):
    """Inverse of dilatancy_angle: r = -2 sin psi / (1 - sin psi)."""
    s = math.sin(math.radians(psi_deg))
    return -2.0 * s / (1.0 - s)


def find_peak(ea, ratio, end_points=2):
    """Index of the maximum of s1/s3, or NotMeasurable when the maximum is among the
    last `end_points` lines: the ratio still rises at the end, no peak was reached."""
    ok = np.isfinite(ratio)
    if ok.sum() < 3:
        return NotMeasurable("fewer than 3 output lines")
    if not np.ptp(ea[ok]) > 0:
        return NotMeasurable("eps_11 does not change: no axial strain")
    k = int(np.nanargmax(np.where(ok, ratio, -np.inf)))
    if k == 0:
        return NotMeasurable("s1/s3 never rises above its value on the first line")
    if k >= len(ratio) - end_points:
        return NotMeasurable(f"s1/s3 still rising at the end, eps_11 = {100 * ea[-1]:.2f} %")
    return k


def line_slope(x, y):
    """Slope of the least-squares line y = a + b x."""
    return float(np.polyfit(x, y, 1)[0])


def initial_window(q, peak_index, fraction=0.3, min_points=4):
    """Indices of the initial response: from the first line up to the last line before
    q - q0 first exceeds `fraction` of the peak deviator rise; at least `min_points`
    lines (output is every 0.05 % strain, a stiff sample reaches 30 % of the peak in
    one or two lines). Why a stress fraction and not a fixed strain: the elastic range
    of a dense DEM sample is a few 0.1 %, any fixed strain window would be wrong
    for one of the two runs."""
    end = len(q) if not measured(peak_index) else peak_index + 1
    rise = q[:end] - q[0]
    limit = fraction * np.nanmax(rise)
    above = np.nonzero(rise > limit)[0]
    n = above[0] if len(above) else end
    return np.arange(max(n, min(min_points, len(q))))


def elastic_constants(ea, s1, s3, el, peak_index, fraction=0.3, min_points=4):
    """(E [Pa], nu, window) from least-squares lines over the initial window.
    window = (first eps_11, last eps_11, number of lines, fraction)."""
    q = s1 - s3
    idx = initial_window(q, peak_index, fraction, min_points)
    if len(idx) < 3 or np.ptp(ea[idx]) <= 0:
        reason = "fewer than 3 lines in the initial response"
        return NotMeasurable(reason), NotMeasurable(reason), None
    E = line_slope(ea[idx], q[idx])
    nu = -line_slope(ea[idx], el[idx])
    return E, nu, (float(ea[idx[0]]), float(ea[idx[-1]]), len(idx), fraction)


def half_rise_strain(ea, q, peak_index):
    """eps_11 at which q - q0 first reaches half its peak rise (linear interpolation
    between output lines): the end of the secant window of E50."""
    if not measured(peak_index):
        return NotMeasurable("no peak: no 50 % point")
    rise = q - q[0]
    half = 0.5 * rise[peak_index]
    k = int(np.nonzero(rise[: peak_index + 1] >= half)[0][0])
    if k == 0 or half <= 0:
        return NotMeasurable("q at its half rise on the first line")
    t = (half - rise[k - 1]) / (rise[k] - rise[k - 1])
    return float(ea[k - 1] + t * (ea[k] - ea[k - 1]))


def secant_constants(ea, q, el, ea50):
    """(E50 [Pa], nu50) of the secant from the first line to eps_11 = ea50:
    E50 = (q(ea50) - q0) / (ea50 - ea0), nu50 = -(el(ea50) - el0) / (ea50 - ea0)."""
    if not measured(ea50):
        return ea50, ea50
    d = ea50 - ea[0]
    return (float(np.interp(ea50, ea, q) - q[0]) / d,
            -float(np.interp(ea50, ea, el) - el[0]) / d)


def sliding_slopes(x, y, width):
    """Slope of y(x) by a least-squares line over every window [x_i, x_i + width]
    (x ascending; only windows fully inside the data, of 3 lines or more, with two
    distinct x); returns (window centres, slopes).

    Linear in the lines: the window sums of x, y, x^2, xy are differences of cumulative
    sums (of x and y less their means, which keeps the cancellation small), and the
    slope is the least-squares one, sum (x - xm)(y - ym) / sum (x - xm)^2 of the window
    (tests/python/test_curves.py checks it against a direct fit of every window)."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = len(x)
    if n == 0:
        return np.array([]), np.array([])
    inside = x[-1] >= x + width - 1e-12            # windows fully inside the data: a prefix
    m = n if inside.all() else int(np.argmin(inside))
    i = np.arange(m)
    j = np.searchsorted(x, x[:m] + width, side="right")
    xc, yc = x - x.mean(), y - y.mean()

    def window_sums(v):
        c = np.concatenate([[0.0], np.cumsum(v)])
        return c[j] - c[i]

    cnt = (j - i).astype(float)
    sx, sy = window_sums(xc), window_sums(yc)
    with np.errstate(divide="ignore", invalid="ignore"):
        sxx = window_sums(xc * xc) - sx * sx / cnt
        sxy = window_sums(xc * yc) - sx * sy / cnt
    keep = (j - i >= 3)
    keep[keep] &= x[j[keep] - 1] > x[i[keep]]      # two distinct x at least
    centres = 0.5 * (x[i[keep]] + x[j[keep] - 1])
    return centres, sxy[keep] / sxx[keep]


def max_dilatancy(ea, ev, width=0.01):
    """(psi [deg], eps_11 where it occurs, rate r) from the maximum dilation rate: the
    most negative slope d ev / d ea of least-squares lines over sliding windows `width`
    wide in eps_11. The window averages the DEM fluctuations of ev (a line every 0.05 %)."""
    order = np.argsort(ea)
    x, y = ea[order], ev[order]
    centres, slopes = sliding_slopes(x, y, width)
    if len(slopes) == 0:
        return NotMeasurable(f"run shorter than the {100 * width:g} % window"), None, None
    k = int(np.argmin(slopes))
    return dilatancy_angle(slopes[k]), float(centres[k]), float(slopes[k])


def correlation(table, x, y):
    """Pearson correlation coefficient of two columns over the output lines."""
    if not (table.has(x) and table.has(y)):
        return NotMeasurable(f"no {x} or {y} column")
    a, b = table[x], table[y]
    ok = np.isfinite(a) & np.isfinite(b)
    if ok.sum() < 3 or np.ptp(a[ok]) == 0 or np.ptp(b[ok]) == 0:
        return NotMeasurable("fewer than 3 lines or a constant column")
    return float(np.corrcoef(a[ok], b[ok])[0, 1])


def last_value(table, name):
    """The column's value on the last line, or NotMeasurable (no column, not finite)."""
    if not table.has(name):
        return NotMeasurable(f"no {name} column")
    v = float(table[name][-1])
    return v if math.isfinite(v) else NotMeasurable(f"{name} = {v} on the last line")


def analyse_curves(table, elastic_fraction=0.3, dilatancy_window=0.01):
    """All macro quantities of one run as a dict (numbers or NotMeasurable)."""
    ea, s1, s3 = table["ea"], table["s1"], table["s3"]
    ratio = table["s1/s3"]
    res = {}
    peak = find_peak(ea, ratio)
    res["peak_index"] = peak
    if measured(peak):
        res["peak_ratio"] = float(ratio[peak])
        res["ea_peak"] = float(ea[peak])
        res["phi_peak"] = friction_angle(ratio[peak])
    else:
        res["peak_ratio"] = res["ea_peak"] = res["phi_peak"] = peak
    res["ratio_end"] = float(ratio[-1])
    res["ea_end"] = float(ea[-1])
    E, nu, window = elastic_constants(ea, s1, s3, table["el"], peak, elastic_fraction)
    res["E"], res["nu"], res["elastic_window"] = E, nu, window
    # the same moduli from the stress inside (Love-Weber over the sample, no wall contacts)
    if table.has("syy_lw") and window is not None:
        E_lw, _, _ = elastic_constants(ea, table["syy_lw"], table["sxx_lw"], table["el"], peak, elastic_fraction)
        res["E_lw"] = E_lw
    else:
        res["E_lw"] = NotMeasurable("no Love-Weber columns" if window is None else "no syy_lw column")
    q = s1 - s3
    res["ea50"] = half_rise_strain(ea, q, peak)
    res["E50"], res["nu50"] = secant_constants(ea, q, table["el"], res["ea50"])
    if table.has("syy_lw"):
        res["E50_lw"], _ = secant_constants(ea, table["syy_lw"] - table["sxx_lw"], table["el"], res["ea50"])
    else:
        res["E50_lw"] = NotMeasurable("no syy_lw column")
    psi, ea_psi, rate = max_dilatancy(ea, table["ev"], dilatancy_window)
    res["psi"], res["ea_psi"], res["dilatancy_rate"] = psi, ea_psi, rate
    res["dilatancy_window"] = dilatancy_window
    res["I_max"] = float(np.nanmax(table["I"])) if table.has("I") else NotMeasurable("no I column")
    res["f0_end"] = last_value(table, "f0")
    for key, column in (("corr_gsi_a", "gsi"), ("corr_gsi_all_a", "gsi_all")):
        res[key] = correlation(table, column, "a")
    lw = last_value(table, "sxx_lw")
    res["lw_check"] = float(lw / s3[-1]) if measured(lw) and s3[-1] != 0 else \
        (lw if not measured(lw) else NotMeasurable("s3 = 0 on the last line"))
    return res
