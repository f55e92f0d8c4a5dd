"""Confidence intervals over replicate samples (numpy and the math module only).

    CONFIDENCE                       the one confidence level of the report (0.95)
    t_quantile(p, df)                Student-t quantile: P(T <= t) = p, df degrees of
                                     freedom (df = math.inf: the normal quantile)
    mean_interval(values)            Interval: mean +- t_{(1+c)/2, n-1} s / sqrt(n)
    paired_difference(a, b)          Interval of a_i - b_i over the pairs where both exist
    common_grid(xs)                  a strain grid every curve covers
    mean_band(xs, ys, grid)          mean and half-width of the interval at each grid point

Student t: the CDF is F(t) = 1 - I_x(df/2, 1/2)/2 for t >= 0, x = df/(df + t^2), with
I the regularized incomplete beta function (continued fraction, modified Lentz, as in
Numerical Recipes, 3rd ed., section 6.4); the quantile is found by bisection to
machine precision. Known values: t_{0.975} = 12.706 (df 1), 2.776 (4), 2.262 (9),
2.045 (29), 1.960 (normal).
"""
import functools
import math

import numpy as np

CONFIDENCE = 0.95


def _beta_continued_fraction(a, b, x, max_terms=100000, eps=1e-15):
    """The continued fraction of I_x(a, b) (converges fast for x < (a + 1)/(a + b + 2))."""
    tiny = 1e-300
    c, d = 1.0, 1.0 - (a + b) * x / (a + 1.0)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, max_terms + 1):
        for num in (m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m)),
                    -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1))):
            d = 1.0 + num * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + num / c
            c = c if abs(c) > tiny else tiny
            h *= d * c
        if abs(d * c - 1.0) < eps:
            return h
    raise ArithmeticError(f"incomplete beta: no convergence for a={a}, b={b}, x={x}")


def regularized_beta(x, a, b):
    """I_x(a, b) = B(x; a, b) / B(a, b) for 0 <= x <= 1, a, b > 0."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    log_front = (math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b)
                 + a * math.log(x) + b * math.log1p(-x))
    if x < (a + 1.0) / (a + b + 2.0):
        return math.exp(log_front) * _beta_continued_fraction(a, b, x) / a
    return 1.0 - math.exp(log_front) * _beta_continued_fraction(b, a, 1.0 - x) / b


def normal_cdf(z):
    return 0.5 * math.erfc(-z / math.sqrt(2.0))


def t_cdf(t, df):
    """P(T <= t) for Student's t with df degrees of freedom (df = inf: normal)."""
    if math.isinf(df):
        return normal_cdf(t)
    tail = 0.5 * regularized_beta(df / (df + t * t), 0.5 * df, 0.5)
    return 1.0 - tail if t > 0 else tail


@functools.lru_cache(maxsize=None)
def t_quantile(p, df):
    """t with P(T <= t) = p (0 < p < 1), df > 0 degrees of freedom (math.inf allowed)."""
    if not 0.0 < p < 1.0:
        raise ValueError(f"t_quantile: p = {p} is not in (0, 1)")
    if not df > 0:
        raise ValueError(f"t_quantile: df = {df} is not positive")
    if p < 0.5:
        return -t_quantile(1.0 - p, df)
    if p == 0.5:
        return 0.0
    lo, hi = 0.0, 1.0
    while t_cdf(hi, df) < p:
        lo, hi = hi, 2.0 * hi
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if t_cdf(mid, df) < p:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def t_critical(n, confidence=CONFIDENCE):
    """The two-sided factor t_{(1+c)/2, n-1} of an interval of the mean of n values."""
    return t_quantile(0.5 + 0.5 * confidence, n - 1)


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
    half = t_critical(n, confidence) * float(v.std(ddof=1)) / math.sqrt(n)
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
