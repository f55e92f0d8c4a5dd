"""Confidence intervals over replicate samples (Student t of scipy.stats).

    CONFIDENCE                       the one confidence level of the report (0.95)
    t_critical(n, c)                 the two-sided factor t_{(1+c)/2, n-1} (scipy.stats.t)
    mean_interval(values)            Interval: mean +- t_{(1+c)/2, n-1} s / sqrt(n)
    paired_difference(a, b)          Interval of a_i - b_i over the pairs where both exist
    common_grid(xs)                  a strain grid every curve covers
    mean_band(xs, ys, grid)          mean and half-width of the interval at each grid point

Known values of t_{0.975}: 12.706 (df 1), 2.776 (4), 2.262 (9), 2.045 (29), 1.960 (normal).
"""
import math

import numpy as np
from scipy import stats as scipy_stats

CONFIDENCE = 0.95


def t_critical(n, confidence=CONFIDENCE):
    """The two-sided factor t_{(1+c)/2, n-1} of an interval of the mean of n >= 2 values
    (n = math.inf: the normal quantile)."""
    if not n >= 2:
        raise ValueError(f"t_critical: n = {n} values give no interval (needs n >= 2)")
    if not 0.0 < confidence < 1.0:
        raise ValueError(f"t_critical: confidence = {confidence} is not in (0, 1)")
    if math.isinf(n):
        return float(scipy_stats.norm.ppf(0.5 + 0.5 * confidence))
    return float(scipy_stats.t.ppf(0.5 + 0.5 * confidence, n - 1))


class Interval:
    """mean +- half_width over n values (half_width is nan when n < 2)."""

    def __init__(self, mean, half_width, n, confidence=CONFIDENCE):
        self.mean, self.half_width, self.n, self.confidence = mean, half_width, n, confidence

    @property
    def low(self):
        return self.mean - self.half_width

    @property
    def high(self):
        return self.mean + self.half_width

    @property
    def has_interval(self):
        return self.n >= 2 and math.isfinite(self.half_width)

    def covers(self, value):
        return self.has_interval and self.low <= value <= self.high

    @property
    def significant(self):
        """True when the interval excludes 0, False when it covers 0, None without one."""
        return None if not self.has_interval else not self.covers(0.0)

    def __repr__(self):
        return f"Interval({self.mean!r} +- {self.half_width!r}, n={self.n})"


def mean_interval(values, confidence=CONFIDENCE):
    """Interval of the mean of the finite values (Student t, n - 1 degrees of freedom)."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    n = len(v)
    if n == 0:
        return Interval(math.nan, math.nan, 0, confidence)
    mean = float(v.mean())
    if n < 2:
        return Interval(mean, math.nan, n, confidence)
    half = t_critical(n, confidence) * float(scipy_stats.sem(v))
    return Interval(mean, half, n, confidence)


def paired_difference(a, b, confidence=CONFIDENCE):
    """Interval of the mean of a_i - b_i over the samples i where both are finite."""
    d = np.asarray(a, dtype=float) - np.asarray(b, dtype=float)
    return mean_interval(d, confidence)


def common_grid(xs, points=None):
    """An increasing grid over the range every curve covers, [max of the starts, min of
    the ends], with as many points as the longest curve (or `points`)."""
    lo = max(float(np.min(x)) for x in xs)
    hi = min(float(np.max(x)) for x in xs)
    if not hi > lo:
        raise ValueError("the curves have no common range")
    return np.linspace(lo, hi, points or max(len(x) for x in xs))


def mean_band(xs, ys, grid, confidence=CONFIDENCE):
    """(mean, half_width, n) on the grid of the curves y_k(x_k), each interpolated
    linearly; half_width is nan where fewer than 2 curves reach the point."""
    grid = np.asarray(grid, dtype=float)
    stack = np.full((len(xs), len(grid)), np.nan)
    for k, (x, y) in enumerate(zip(xs, ys)):
        order = np.argsort(x)
        x, y = np.asarray(x, dtype=float)[order], np.asarray(y, dtype=float)[order]
        inside = (grid >= x[0]) & (grid <= x[-1])
        stack[k, inside] = np.interp(grid[inside], x, y)
    n = np.isfinite(stack).sum(axis=0)
    mean = np.full(len(grid), np.nan)
    half = np.full(len(grid), np.nan)
    for j in np.nonzero(n > 0)[0]:
        iv = mean_interval(stack[:, j], confidence)
        mean[j], half[j] = iv.mean, iv.half_width
    return mean, half, n
