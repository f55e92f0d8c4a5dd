"""Incremental displacement and shear-strain fields, and the shear band in them.

Strain (Delaunay-free): for each particle i, the displacement gradient G_i is the
least-squares fit of  du_j - du_i = G_i (x_j - x_i)  over the neighbours j within
`radius` (default 3 D50) in the configuration at the start of the increment.
The shear measure is the maximum engineering shear strain of the symmetric part,
    gamma = sqrt((e_xx - e_yy)^2 + (2 e_xy)^2),
which is the diameter of the strain Mohr circle and does not depend on the axes.

Band (method stated in the summary):
 0. particles closer than 3 D50 to the sample outline are left out (one-sided
    neighbourhoods, see interior_mask);
 1. band points = particles with gamma > mean + k std (k = 1.5);
 2. coarse line: Hough/Radon search over directions (0.5 deg steps) of the
    strip 2 D50 wide holding the largest gamma excess of the band points;
 3. refined line: total least squares (principal axis) of the band points within
    `strip_half_width` (6 D50) of the current line, three passes; then a line
    through the slice centres of those points (slices 2 D50 along the line,
    weights gamma - threshold, only slices whose whole cross-section is inside
    the analysed region), three passes (see centre_line);
 4. accepted when >= 20 points are in the strip and the band points are
    concentrated there (their fraction in the strip is >= 2 times the fraction
    of all particles in it), and the gamma profile across the line peaks at
    >= 2 times the background (median gamma outside the strip);
 5. thickness = full width at half maximum (above the background, its median
    outside the strip) of the profile across the line of the shear strain resolved
    on the band, 2 s.eps.n (bins D50/2, 3-bin running mean), from the particles in
    the middle 80 % of the band's length. gamma_max is not used there: the uniform
    part of the strain adds to it non-linearly and narrows its peak.
Angle: inclination of the line to the horizontal (the sigma_3 direction), 0-90 deg,
the angle Mohr-Coulomb predicts as 45 + phi/2 and Roscoe as 45 + psi/2.
"""
import math

import numpy as np
from scipy.spatial import cKDTree

from .curves import NotMeasurable


def soil_mask(frame):
    """Particles that belong in the field: membrane chain disks (flag 1, 2) follow the
    boundary and escaped disks (flag 3) are outside the sample, both are left out."""
    flag = next((v for k, v in frame.items() if k.startswith("f_")), None)
    n = len(frame["x"])
    return np.ones(n, bool) if flag is None else (flag == 0)


def increment(frame0, frame1):
    """(ids, x0 (n,2), du (n,2)) of the soil particles present in both frames."""
    ids0 = frame0["id"][soil_mask(frame0)]
    ids1 = frame1["id"][soil_mask(frame1)]
    ids = np.intersect1d(ids0, ids1)
    i0 = np.searchsorted(frame0["id"], ids)
    i1 = np.searchsorted(frame1["id"], ids)
    x0 = np.column_stack([frame0["x"][i0], frame0["y"][i0]])
    x1 = np.column_stack([frame1["x"][i1], frame1["y"][i1]])
    return ids, x0, x1 - x0


def local_gradients(x, du, radius):
    """Least-squares displacement gradient G[i] (2x2, G_ab = d u_a / d x_b) over the
    neighbours within `radius` (scipy.spatial.cKDTree: every pair closer than radius);
    NaN where fewer than 3 neighbours or a degenerate neighbourhood. The sums over the
    neighbours are taken of the differences x_j - x_i, u_j - u_i themselves (each pair
    adds the same products to both of its particles)."""
    n = len(x)
    G = np.full((n, 2, 2), np.nan)
    if n == 0:
        return G, np.zeros(0, int)
    pairs = cKDTree(x).query_pairs(radius, output_type="ndarray")
    i, j = pairs[:, 0], pairs[:, 1]
    dx, du_ = x[j] - x[i], du[j] - du[i]
    xx = (dx[:, :, None] * dx[:, None, :]).reshape(-1, 4)   # (x_j - x_i)(x_j - x_i)^T
    ux = (du_[:, :, None] * dx[:, None, :]).reshape(-1, 4)  # (u_j - u_i)(x_j - x_i)^T
    both = np.concatenate([i, j])
    count = np.bincount(both, minlength=n)
    A = np.stack([np.bincount(both, np.tile(xx[:, k], 2), minlength=n) for k in range(4)], 1).reshape(-1, 2, 2)
    B = np.stack([np.bincount(both, np.tile(ux[:, k], 2), minlength=n) for k in range(4)], 1).reshape(-1, 2, 2)
    det = A[:, 0, 0] * A[:, 1, 1] - A[:, 0, 1] * A[:, 1, 0]
    tr = A[:, 0, 0] + A[:, 1, 1]
    good = (count >= 3) & (det > 1e-3 * tr * tr)
    safe = np.where(good, det, 1.0)
    inv = np.empty_like(A)
    inv[:, 0, 0], inv[:, 1, 1] = A[:, 1, 1] / safe, A[:, 0, 0] / safe
    inv[:, 0, 1], inv[:, 1, 0] = -A[:, 0, 1] / safe, -A[:, 1, 0] / safe
    g = np.einsum("cab,cbd->cad", B, inv)
    G[good] = g[good]
    return G, count


def max_shear_strain(G):
    """Maximum engineering shear strain sqrt((e_xx - e_yy)^2 + (2 e_xy)^2) of sym(G)."""
    exx, eyy = G[:, 0, 0], G[:, 1, 1]
    gxy = G[:, 0, 1] + G[:, 1, 0]
    return np.sqrt((exx - eyy) ** 2 + gxy ** 2)


def interior_mask(x, margin):
    """Particles at least `margin` from the sample outline, the outline being the
    extreme particles of each row and each column (bins `margin` wide), which follows
    a bulging membrane as well as rigid walls. Why: a particle near the outline has a
    one-sided neighbourhood whose gradient fit amplifies the non-affine noise, and a
    noisy field would otherwise show a false 'band' along the side walls."""
    inside = np.ones(len(x), bool)
    for a in (0, 1):
        b = 1 - a
        rows = np.floor((x[:, b] - x[:, b].min()) / margin).astype(int)
        lo = np.full(rows.max() + 1, np.inf)
        hi = np.full(rows.max() + 1, -np.inf)
        np.minimum.at(lo, rows, x[:, a])
        np.maximum.at(hi, rows, x[:, a])
        inside &= (x[:, a] - lo[rows] >= margin) & (hi[rows] - x[:, a] >= margin)
        # the first and last rows are themselves on the outline
        inside &= (x[:, b] - x[:, b].min() >= margin) & (x[:, b].max() - x[:, b] >= margin)
    return inside


def _unit(alpha_deg):
    a = math.radians(alpha_deg)
    return np.array([math.cos(a), math.sin(a)]), np.array([-math.sin(a), math.cos(a)])


def hough_line(points, weights, bin_width, step_deg=0.5):
    """(direction alpha [deg, 0-180), offset p along the normal) of the straight strip
    `2 bin_width` wide holding the largest total weight: a coarse line that one
    conjugate band or stray points cannot pull off, unlike a plain fit."""
    best = (-1.0, 0.0, 0.0)
    for alpha in np.arange(0.0, 180.0, step_deg):
        _, normal = _unit(alpha)
        p = points @ normal
        edges = np.arange(p.min() - bin_width, p.max() + 2 * bin_width, bin_width)
        h, _ = np.histogram(p, edges, weights=weights)
        pair = h[:-1] + h[1:]
        k = int(np.argmax(pair))
        if pair[k] > best[0]:
            best = (pair[k], alpha, edges[k + 1])
    return best[1], best[2]


def total_least_squares(points):
    """(centroid, direction alpha [deg, 0-180), std along, std across) of a point set."""
    c = points.mean(0)
    w, v = np.linalg.eigh(np.cov((points - c).T))
    major = v[:, 1]
    alpha = math.degrees(math.atan2(major[1], major[0])) % 180.0
    return c, alpha, math.sqrt(max(w[1], 0.0)), math.sqrt(max(w[0], 0.0))


def centre_line(points, weights, centre, alpha, slice_length, half_width, interior,
                min_per_slice=3):
    """Refit the line through the weighted centres of slices across the strip: in
    each slice `slice_length` long along the line, the weighted mean offset across
    it; a least-squares line through these centres gives the new (centre, alpha).
    Only slices whose whole cross-section lies in the analysed region (interior
    particles within 20 % of both strip edges) are used: a band cut obliquely at
    the sample edge has its end slices on one side only, which would tilt the fit
    (as it tilts a plain principal-axis fit). Unchanged if < 3 slices."""
    along, normal = _unit(alpha)
    s = (points - centre) @ along
    d = (points - centre) @ normal
    s_all = (interior - centre) @ along
    d_all = (interior - centre) @ normal
    s0 = min(s.min(), s_all.min())
    k = np.floor((s - s0) / slice_length).astype(int)
    k_all = np.floor((s_all - s0) / slice_length).astype(int)
    nbins = max(k.max(), k_all.max()) + 1
    low = np.bincount(k_all, (d_all < -0.8 * half_width) & (d_all >= -half_width), nbins)
    high = np.bincount(k_all, (d_all > 0.8 * half_width) & (d_all <= half_width), nbins)
    sw = np.bincount(k, weights, nbins)
    n = np.bincount(k, None, nbins)
    good = (n >= min_per_slice) & (sw > 0) & (low > 0) & (high > 0)
    if good.sum() < 3:
        return centre, alpha
    s_c = np.bincount(k, weights * s, nbins)[good] / sw[good]
    d_c = np.bincount(k, weights * d, nbins)[good] / sw[good]
    slope, intercept = np.polyfit(s_c, d_c, 1)
    mid = s_c.mean()
    new_centre = centre + mid * along + (intercept + slope * mid) * normal
    return new_centre, (alpha + math.degrees(math.atan(slope))) % 180.0


def inclination_from_horizontal(alpha_deg):
    """Acute angle between a line of direction alpha and the horizontal, 0-90 deg."""
    a = alpha_deg % 180.0
    return a if a <= 90.0 else 180.0 - a


def shear_profile(x, gamma, centre, alpha, d50, half_range):
    """(bin centres, mean gamma) across the line, 3-bin running mean, bins D50/2,
    from the particles in the middle 80 % of the line's extent in the sample."""
    along, normal = _unit(alpha)
    s = (x - centre) @ along
    d = (x - centre) @ normal
    lo, hi = np.percentile(s[np.abs(d) <= half_range], [10, 90])
    keep = (s >= lo) & (s <= hi) & np.isfinite(gamma)
    edges = np.arange(-half_range, half_range + 1e-12, d50 / 2.0)
    total, _ = np.histogram(d[keep], edges, weights=gamma[keep])
    count, _ = np.histogram(d[keep], edges)
    mean = np.where(count > 0, total / np.maximum(count, 1), np.nan)
    kernel = np.ones(3)
    ok = np.isfinite(mean)
    smooth = np.convolve(np.where(ok, mean, 0.0), kernel, "same") / np.maximum(
        np.convolve(ok.astype(float), kernel, "same"), 1e-300)
    smooth[np.convolve(ok.astype(float), kernel, "same") == 0] = np.nan
    return 0.5 * (edges[1:] + edges[:-1]), smooth


def full_width_half_maximum(centres, profile, background, search_half_width):
    """FWHM above `background` of the profile's maximum within +-search_half_width of 0,
    with linear interpolation of the half-maximum crossings; None when the profile
    does not fall to half on both sides."""
    inside = np.nonzero(np.abs(centres) <= search_half_width)[0]
    k = inside[np.nanargmax(profile[inside])]
    half = background + 0.5 * (profile[k] - background)

    def crossing(direction):
        j = k
        while 0 <= j + direction < len(profile):
            nxt = j + direction
            if np.isfinite(profile[nxt]) and profile[nxt] < half:
                f = (profile[j] - half) / (profile[j] - profile[nxt])
                return centres[j] + f * (centres[nxt] - centres[j])
            j = nxt
        return None

    left, right = crossing(-1), crossing(+1)
    if left is None or right is None:
        return None, profile[k]
    return right - left, profile[k]


def resolved_shear_strain(G, alpha_deg):
    """Engineering shear strain on a plane of direction alpha: 2 s.sym(G).n (s along,
    n across). Unlike gamma_max it is linear in G, so that a uniform strain only adds
    a constant to the profile across a band instead of reshaping it."""
    s, n = _unit(alpha_deg)
    eps = 0.5 * (G + np.transpose(G, (0, 2, 1)))
    return 2.0 * np.einsum("a,iab,b->i", s, eps, n)


def detect_band(x, gamma, d50, G=None, k_std=1.5, strip_half_width=6.0, min_points=20,
                min_concentration=2.0, min_contrast=2.0, margin=3.0):
    """Find one shear band in a shear-strain field (G, the gradients, gives the
    thickness from the resolved shear strain; without it from gamma). Returns a dict:
    'angle' (deg from horizontal) and 'thickness' (m), numbers or NotMeasurable,
    plus what the plots draw ('centre', 'alpha', 'band', 'profile', 'threshold')."""
    ok = np.isfinite(gamma) & interior_mask(x, margin * d50)
    res = {"angle": None, "thickness": None, "centre": None, "alpha": None, "interior": ok,
           "band": np.zeros(len(gamma), bool), "profile": None, "threshold": None}
    g = gamma[ok]
    if len(g) < min_points:
        res["angle"] = res["thickness"] = NotMeasurable("fewer than 20 particles with a strain")
        return res
    mean, std = float(g.mean()), float(g.std())
    thr = mean + k_std * std
    band = ok & (gamma > thr)
    res["threshold"], res["band"] = thr, band
    if std <= 1e-3 * abs(mean) or band.sum() < min_points:
        why = (f"uniform shear strain, std/mean = {std / mean:.2g}" if std <= 0.05 * abs(mean)
               else f"{band.sum()} strongly shearing points < {min_points}")
        res["angle"] = res["thickness"] = NotMeasurable(why)
        return res
    pts, w = x[band], gamma[band] - thr
    alpha, offset = hough_line(pts, w, 2.0 * d50)
    normal = _unit(alpha)[1]
    centre = pts.mean(0)
    centre = centre + (offset - centre @ normal) * normal
    half = strip_half_width * d50
    for _ in range(3):
        normal = _unit(alpha)[1]
        near = np.abs((pts - centre) @ normal) <= half
        if near.sum() < min_points:
            break
        centre, alpha, _, _ = total_least_squares(pts[near])
    for _ in range(3):
        normal = _unit(alpha)[1]
        near = np.abs((pts - centre) @ normal) <= half
        if near.sum() < min_points:
            break
        centre, alpha = centre_line(pts[near], w[near], centre, alpha, 2.0 * d50,
                                    half, x[ok])
    normal = _unit(alpha)[1]
    res["centre"], res["alpha"] = centre, alpha
    near = np.abs((pts - centre) @ normal) <= half
    all_near = np.abs((x[ok] - centre) @ normal) <= half
    concentration = (near.mean() / max(all_near.mean(), 1e-300))
    res["concentration"] = concentration
    if near.sum() < min_points:
        res["angle"] = res["thickness"] = NotMeasurable(
            f"only {near.sum()} strongly shearing points along the best line")
        return res
    background = float(np.median(gamma[ok][~all_near])) if (~all_near).any() else 0.0
    centres, profile = shear_profile(x[ok], gamma[ok], centre, alpha, d50, 4.0 * half)
    res["profile"], res["background"] = (centres, profile), background
    width, peak = full_width_half_maximum(centres, profile, background, half)
    contrast = peak / background if background > 0 else math.inf
    res["contrast"] = contrast
    if concentration < min_concentration:
        res["angle"] = res["thickness"] = NotMeasurable(
            f"poor line fit: strongly shearing points only {concentration:.2f} x "
            f"more frequent near the line than elsewhere (< {min_concentration:g})")
        return res
    if contrast < min_contrast:
        res["angle"] = res["thickness"] = NotMeasurable(
            f"no localisation: shear strain on the line {contrast:.2f} x background (< {min_contrast:g})")
        return res
    if G is not None:
        resolved = resolved_shear_strain(G[ok], alpha)
        outside = resolved[~all_near] if (~all_near).any() else np.zeros(1)
        if np.median(resolved[all_near]) < np.median(outside):
            resolved, outside = -resolved, -outside          # the band's slip sense
        background = float(np.median(outside))
        centres, profile = shear_profile(x[ok], resolved, centre, alpha, d50, 4.0 * half)
        res["profile"], res["background"] = (centres, profile), background
        width, _ = full_width_half_maximum(centres, profile, background, half)
    res["angle"] = inclination_from_horizontal(alpha)
    res["thickness"] = (width if width is not None else NotMeasurable(
        "shear-strain profile does not fall to half maximum"))
    return res


def analyse_increment(frame0, frame1, d50, radius_d50=3.0, **band_options):
    """Field of one increment: positions, displacements, gamma and the band."""
    ids, x0, du = increment(frame0, frame1)
    G, count = local_gradients(x0, du, radius_d50 * d50)
    gamma = max_shear_strain(G)
    band = detect_band(x0, gamma, d50, G, **band_options)
    return {"x": x0, "du": du, "gamma": gamma, "band": band,
            "steps": (frame0["step"], frame1["step"])}
