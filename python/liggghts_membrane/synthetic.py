"""Synthetic runs with known answers, written in the formats of the shear scripts.

Used by the tests (tests/python) and the adversarial report cases
(tests/adversarial/setups/report_files.py).
"""
import math

import numpy as np

from .curves import ratio_from_friction_angle, volume_rate_from_dilatancy

FULL_HEADER = ("step t ea s1 s3 s1/s3 ev el I sxx_int syy_int C_n W H KE "
               "a theta_a an theta_n f0 at Zm gsi sxx_lw syy_lw").split()


def write_out(path, columns, header=None, comment="# synthetic biaxial run"):
    """An OUT table: a comment line, the header line, one line per row."""
    header = header or list(columns)
    data = np.column_stack([columns[c] for c in header])
    with open(path, "w") as f:
        f.write(comment + "\n")
        f.write("# " + " ".join(header) + "\n")
        for row in data:
            f.write(" ".join(repr(float(v)) for v in row) + "\n")


def elastoplastic_curve(E=50e6, nu=0.3, phi=30.0, psi=10.0, s3=1e5, ea_end=0.10,
                        d_ea=0.0005, ea_peak=0.03, ratio_residual=2.5, noise=True, seed=3):
    """ea, s1, s3, ev, el of an elastic-plastic law with known constants.

    q = s1 - s3 is linear (slope E) up to half the peak, then rises as a parabola to
    the peak q_p = s3 (tan^2(45 + phi/2) - 1) at ea_peak with zero slope, then softens
    towards the residual ratio. d ev / d ea is 1 - nu in the elastic range (so that
    el = -nu ea), then goes linearly to the rate of psi (sin psi = -r/(2 - r)) at 2 %,
    stays there to 4.5 % (longer than the 1 % window of the analysis), then returns to
    0 at 8 % (critical state). el follows from the exact area relation
    (1 - ev) = (1 - ea)(1 - el)."""
    ea = np.round(np.arange(0.0, ea_end + d_ea / 2, d_ea), 12)
    q_peak = s3 * (ratio_from_friction_angle(phi) - 1.0)
    q_y = 0.5 * q_peak
    ea_y = q_y / E
    s = np.clip((ea - ea_y) / (ea_peak - ea_y), 0.0, 1.0)
    q = np.where(ea <= ea_y, E * ea, q_y + (q_peak - q_y) * (1.0 - (1.0 - s) ** 2))
    q_res = s3 * (ratio_residual - 1.0)
    post = ea > ea_peak
    q[post] = q_res + (q_peak - q_res) * np.exp(-((ea[post] - ea_peak) / 0.03) ** 2)
    m = volume_rate_from_dilatancy(psi)
    rate = np.interp(ea, [0.0, ea_y, 0.02, 0.045, 0.08, 1.0],
                     [1.0 - nu, 1.0 - nu, m, m, 0.0, 0.0])
    ev = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(ea))])
    s3_arr = np.full_like(ea, s3)
    if noise:
        rng = np.random.default_rng(seed)
        q = q + rng.normal(0.0, 100.0, len(ea))
        ev = ev + rng.normal(0.0, 1e-6, len(ea))
    el = 1.0 - (1.0 - ev) / (1.0 - ea)
    s1 = s3_arr + q
    return {"step": np.arange(len(ea)) * 500.0, "ea": ea, "s1": s1, "s3": s3_arr,
            "s1/s3": s1 / s3_arr, "ev": ev, "el": el}


def full_columns(curve, f0=30.0):
    """Add plausible values for every other column of the full header."""
    n = len(curve["ea"])
    cols = dict(curve)
    ea = curve["ea"]
    extra = {"t": ea / 0.01, "I": np.full(n, 7e-4), "sxx_int": curve["s3"] * 0.99,
             "syy_int": curve["s1"] * 0.99, "C_n": 2.3 - 3 * ea, "W": 0.075 * (1 + ea / 3),
             "H": 0.15 * (1 - ea), "KE": np.full(n, 1e-6), "a": 0.05 + 2 * ea,
             "theta_a": np.full(n, 90.0), "an": 0.1 + 3 * ea, "theta_n": np.full(n, 90.0),
             "f0": f0 * (1 + ea), "at": 0.02 + ea, "Zm": 3.2 - 4 * ea, "gsi": 0.15 + 0.5 * ea,
             "sxx_lw": curve["s3"] * 1.01, "syy_lw": curve["s1"] * 1.01}
    cols.update(extra)
    return cols


def exact_histogram(a, theta_a, n_contacts=4000, nbins=36):
    """(centres_deg, counts) of the rose of E(theta) with anisotropy a, integrated
    exactly over each bin (fabric.md): N_g = (N/2 pi)[dtheta + a sin dtheta cos 2(theta_g - theta_a)],
    N = 2 n_contacts (n and -n)."""
    width = 2 * math.pi / nbins
    centres = (np.arange(nbins) + 0.5) * 360.0 / nbins
    n = 2 * n_contacts
    counts = n / (2 * math.pi) * (width + a * math.sin(width)
                                  * np.cos(2 * np.radians(centres - theta_a)))
    return centres, counts


def write_rose(path, blocks):
    """blocks: [(step, centres_deg, counts, mean_fn, mean_ft)] in the ave/time vector format."""
    with open(path, "w") as f:
        f.write("# Time-averaged data for fix rose\n# TimeStep Number-of-rows\n"
                "# Row c_fab[1] c_fab[2] c_fab[3] c_fab[4]\n")
        for step, centres, counts, fn, ft in blocks:
            f.write(f"{step} {len(centres)}\n")
            for k in range(len(centres)):
                f.write(f"{k + 1} {centres[k]} {counts[k]} {fn[k]} {ft[k]}\n")


def write_dump(path, frames, flags=None):
    """frames: [(step, ids, x (n,2), radius)] as a LIGGGHTS dump custom file
    (id x y radius [f_mem])."""
    with open(path, "w") as f:
        for step, ids, x, radius in frames:
            f.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{len(ids)}\n")
            f.write("ITEM: BOX BOUNDS ff ff pp\n-0.01 0.09\n-0.01 0.16\n-0.5 0.5\n")
            f.write("ITEM: ATOMS id x y radius" + (" f_mem" if flags is not None else "") + "\n")
            for k in range(len(ids)):
                line = f"{ids[k]} {x[k, 0]:.9g} {x[k, 1]:.9g} {radius[k]:.6g}"
                if flags is not None:
                    line += f" {flags[k]}"
                f.write(line + "\n")


def random_sample(n=8000, width=0.075, height=0.15, seed=1):
    """Particle centres uniformly at random in the box."""
    rng = np.random.default_rng(seed)
    return rng.uniform([0.0, 0.0], [width, height], (n, 2))


def band_displacement(x, angle_deg=55.0, thickness=0.015, slip=1e-3, centre=None,
                      affine=((5e-4, 0.0), (0.0, -1e-3)), noise=1e-5, seed=2):
    """Displacement of a shear band: slip along a line at angle_deg from the horizontal,
    a smooth step (slip/2) tanh(2 d / thickness) of the distance d across it, plus a
    uniform strain and random non-affine noise. The shear strain across it is
    (slip/thickness) sech^2(2 d/thickness): its FWHM is 0.881 x thickness and its
    equivalent width (slip / peak) is the thickness."""
    rng = np.random.default_rng(seed)
    a = math.radians(angle_deg)
    along = np.array([math.cos(a), math.sin(a)])
    normal = np.array([-math.sin(a), math.cos(a)])
    centre = x.mean(0) if centre is None else np.asarray(centre)
    d = (x - centre) @ normal
    du = 0.5 * slip * np.tanh(2.0 * d / thickness)[:, None] * along[None, :]
    du += x @ np.asarray(affine).T
    return du + rng.normal(0.0, noise, x.shape)


def radii_uniform_by_mass(n, d_min=0.5e-3, d_max=3e-3, seed=7):
    """Radii of disks 'uniform by mass' on [d_min, d_max] (generate_sample.py's law):
    D50 by mass = (d_min + d_max)/2."""
    u = np.random.default_rng(seed).uniform(0.0, 1.0, n)
    return 0.5 / (1.0 / d_min - u * (1.0 / d_min - 1.0 / d_max))


def write_band_run(prefix, curve, n=4000, angle_deg=55.0, thickness=0.015, every=10,
                   slip_per_strain=0.1, seed=11):
    """A full rigid-like run: OUT with every column, OUT.rose and OUT.dump. Before the
    peak the sample deforms uniformly; after it a band at angle_deg slips by
    slip_per_strain x (ea - ea_peak). Dump frames every `every` OUT lines."""
    write_out(prefix, full_columns(curve), FULL_HEADER)
    k_peak = int(np.argmax(curve["s1/s3"]))
    ea_peak = curve["ea"][k_peak]
    centres, counts = exact_histogram(0.2, 90.0)
    fn = 30.0 * (1 + 0.3 * np.cos(2 * np.radians(centres - 90.0)))
    write_rose(prefix + ".rose", [(int(s), centres, counts, fn, 0 * fn)
                                  for s in curve["step"][::every]])
    rng = np.random.default_rng(seed)
    x0 = random_sample(n, seed=seed)
    radius = radii_uniform_by_mass(n)
    a = math.radians(angle_deg)
    along, normal = np.array([math.cos(a), math.sin(a)]), np.array([-math.sin(a), math.cos(a)])
    d = (x0 - x0.mean(0)) @ normal
    frames = []
    for k in range(0, len(curve["ea"]), every):
        ea = curve["ea"][k]
        x = x0 * np.array([1.0 + 0.3 * ea, 1.0 - ea])
        slip = slip_per_strain * max(ea - ea_peak, 0.0)
        x = x + 0.5 * slip * np.tanh(2.0 * d / thickness)[:, None] * along[None, :]
        x = x + rng.normal(0.0, 3e-6, x.shape)
        frames.append((int(curve["step"][k]), np.arange(1, n + 1), x, radius))
    write_dump(prefix + ".dump", frames, flags=np.zeros(n, int))
