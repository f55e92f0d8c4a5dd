"""One run from its files to everything the report shows (no plotting, no printing)."""
import os

import numpy as np

from . import curves, field, particle_strain, readers
from .curves import NotMeasurable, measured
from .grains import d50_by_mass


DUMP_COLUMNS = ("id", "x", "y", "radius")   # what the field and D50 need of OUT.dump


class Run:
    """A run (rigid or membrane): its table, curve analysis, roses, fields and band."""

    def __init__(self, name, prefix):
        self.name = name
        self.prefix = prefix
        self.colour = None        # of its curves (plots.assign_colours); None: by its name
        self.table = None
        self.curves = {}
        self.roses = []
        self.fields = []          # [{'label', 'ea': (ea0, ea1), 'field': analyse_increment(...)}]
        self.band = None          # the increment whose band goes in the table
        self.band_reason = None   # NotMeasurable when there is no such increment
        self.d50 = None
        self.d50_source = ""
        self.notes = []


def frame_strains(table, dump_index):
    """eps_11 of each dump frame, interpolated in step from the OUT table."""
    steps = np.array([s for s, _ in dump_index], dtype=float)
    return np.interp(steps, table["step"], table["ea"])


def choose_increments(table, peak_index, dump_index):
    """The increments drawn, as [(label, frame i, frame j, used_in_table)]:
    0-peak, peak-mid, mid-end and the whole post-peak peak-end (the one measured
    in the table: the band forms around the peak and carries the post-peak slip).
    Without a peak: 0-mid, mid-end, and the second half (mid-end) in the table."""
    ea = frame_strains(table, dump_index)
    first, last = 0, len(ea) - 1

    def nearest(target):
        return int(np.argmin(np.abs(ea - target)))

    if measured(peak_index):
        pk = nearest(table["ea"][peak_index])
        mid = nearest(0.5 * (ea[pk] + ea[last]))
        plan = [("0 – peak", first, pk, False), ("peak – mid", pk, mid, False),
                ("mid – end", mid, last, False), ("peak – end: table", pk, last, True)]
    else:
        mid = nearest(0.5 * (ea[first] + ea[last]))
        plan = [("0 – mid", first, mid, False), ("second half (no peak): table", mid, last, True)]
    return [p for p in plan if p[1] < p[2]], ea


def load_run(name, prefix, d50_default):
    """Read and analyse the files of one run; missing rose/dump files are noted."""
    run = Run(name, prefix)
    run.table = readers.read_output(prefix)
    readers.check_table(run.table)
    if len(run.table) < 3:
        run.notes.append(f"{os.path.basename(prefix)} has {len(run.table)} data line(s): the peak, "
                         "the moduli and the angles need 3 or more (a longer shear)")
    if run.table.missing:
        run.notes.append(f"columns missing in {os.path.basename(prefix)}: "
                         + " ".join(run.table.missing))
    run.curves = curves.analyse_curves(run.table)
    if os.path.exists(prefix + ".rose"):
        run.roses = readers.read_rose(prefix + ".rose", run.notes)
    else:
        run.notes.append(f"no {os.path.basename(prefix)}.rose: no rose diagrams")
    params = readers.read_params(prefix + ".params")
    if isinstance(params.get("d50"), float) and params["d50"] > 0:
        run.d50, run.d50_source = params["d50"], f"{os.path.basename(prefix)}.params (no dump)"
    else:
        run.d50, run.d50_source = d50_default, "--d50 (no dump)"
    run.curves["E50_p"] = run.curves["nu50_p"] = NotMeasurable("no dump file")
    if not os.path.exists(prefix + ".dump"):
        run.band_reason = NotMeasurable("no dump file")
        run.notes.append(f"no {os.path.basename(prefix)}.dump: no displacement field")
        return run
    index = readers.dump_steps(prefix + ".dump", run.notes)
    if len(index) < 2:
        run.band_reason = NotMeasurable("fewer than 2 complete dump frames")
        return run
    frames = {}

    def frame(i):
        if i not in frames:
            frames[i] = readers.read_dump_frame(prefix + ".dump", index[i][1])
        return frames[i]

    first = frame(0)
    lacking = [c for c in DUMP_COLUMNS if c not in first]
    if lacking:
        run.band_reason = NotMeasurable("the dump lacks " + " ".join(lacking))
        run.notes.append(f"{os.path.basename(prefix)}.dump lacks the column(s) {' '.join(lacking)} "
                         f"(needs {' '.join(DUMP_COLUMNS)}): no displacement field")
        return run
    run.d50 = d50_by_mass(2.0 * first["radius"][field.soil_mask(first)], 2)
    run.d50_source = "by mass, from the first dump frame"
    plan, ea = choose_increments(run.table, run.curves["peak_index"], index)
    run.curves["E50_p"], run.curves["nu50_p"] = particle_strain.particle_secant(
        run.table, run.curves, frame, ea, run.d50)
    for label, i, j, in_table in plan:
        inc = {"label": label, "ea": (float(ea[i]), float(ea[j])),
               "field": field.analyse_increment(frame(i), frame(j), run.d50)}
        run.fields.append(inc)
        if in_table:
            run.band = inc
    if run.band is None and run.band_reason is None:
        run.band_reason = NotMeasurable("no dump frame between the peak and the end")
    return run
