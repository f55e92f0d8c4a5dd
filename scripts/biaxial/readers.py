"""Readers for the files written by examples/biaxial/in.shear_rigid and in.shear_membrane
(and by the benchmarks' scripts, bench/in.*): every OUT-table and dump reader of the
project is here.

The columns of the OUT table are taken by name from its header line (the last
comment line before the data), so that older runs without the fabric columns,
or future runs with extra columns, are still readable.
"""
import numpy as np

# What the shear scripts write; the analysis only needs MECHANICAL_COLUMNS.
MECHANICAL_COLUMNS = ["step", "ea", "s1", "s3", "ev", "el"]
EXPECTED_COLUMNS = ("step t ea s1 s3 s1/s3 ev el I sxx_int syy_int C_n W H KE "
                    "a theta_a an theta_n f0 at Zm gsi sxx_lw syy_lw").split()


class OutputTable:
    """The OUT table of one run: columns by name, plus what was expected but absent."""

    def __init__(self, path, columns, header):
        self.path = path
        self.columns = columns
        self.header = header
        self.missing = [c for c in EXPECTED_COLUMNS if c not in columns]
        self.extra = [c for c in header if c not in EXPECTED_COLUMNS]

    def has(self, name):
        """True when the column exists and holds at least one finite value."""
        return name in self.columns and np.isfinite(self.columns[name]).any()

    def __getitem__(self, name):
        return self.columns[name]

    def __len__(self):
        return len(next(iter(self.columns.values()))) if self.columns else 0


def read_columns(path):
    """{name: array} of a table whose columns are named by its header line (the last
    '#' comment line before the data): an OUT table, the pressure table of
    bench/in.stability_pressure, the f0 table of bench/f0_origin.inc. Lines after the
    header that do not have as many numbers as the header has names (an interrupted
    write) are skipped; the header names are returned too, in order."""
    header, rows = None, []
    with open(path, errors="replace") as f:
        for line in f:
            text = line.strip()
            if not text:
                continue
            if text.startswith("#"):
                if not rows:  # the last comment line before data is the header
                    header = text.lstrip("#").split()
                continue
            if header is None:
                raise ValueError(f"{path}: data before any '#' header line")
            words = text.split()
            if len(words) != len(header):
                continue
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                continue
    if header is None:
        raise ValueError(f"{path}: no header line")
    data = np.array(rows, dtype=float).reshape(-1, len(header))
    return {name: data[:, k] for k, name in enumerate(header)}, header


def read_output(path):
    """Read an OUT table (read_columns). Repeated steps (a line printed by both
    `run 1` and `fix print`) keep their first line."""
    columns, header = read_columns(path)
    if "step" in columns and len(columns["step"]):
        _, first = np.unique(columns["step"], return_index=True)
        keep = np.sort(first)
        columns = {name: col[keep] for name, col in columns.items()}
    if "s1/s3" not in columns and "s1" in columns and "s3" in columns:
        columns["s1/s3"] = columns["s1"] / columns["s3"]
    missing = [c for c in MECHANICAL_COLUMNS if c not in columns]
    if missing:
        raise ValueError(f"{path}: header lacks {' '.join(missing)}")
    return OutputTable(path, columns, header)


def read_rose(path):
    """Read a `fix ave/time mode vector` file of polar histograms.

    Returns a list of (step, block) with block a dict of arrays: 'centre_deg',
    'count', 'mean_fn', 'mean_ft' (one entry per bin, 0-360 degrees).
    """
    blocks = []
    with open(path) as f:
        lines = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]
    i = 0
    while i < len(lines):
        step, nrows = int(float(lines[i][0])), int(lines[i][1])
        rows = np.array([[float(w) for w in l[:5]] for l in lines[i + 1:i + 1 + nrows]])
        if rows.shape != (nrows, 5):
            break  # truncated last block
        blocks.append((step, {"centre_deg": rows[:, 1], "count": rows[:, 2],
                              "mean_fn": rows[:, 3], "mean_ft": rows[:, 4]}))
        i += 1 + nrows
    return blocks


def dump_steps(path):
    """Timesteps present in a LIGGGHTS text dump, with the byte offset of each frame,
    so that only the frames used are parsed (a full-size run has ~8 400 disks a frame)."""
    index = []
    with open(path, "rb") as f:
        while True:
            pos = f.tell()
            line = f.readline()
            if not line:
                break
            if line.startswith(b"ITEM: TIMESTEP"):
                index.append((int(f.readline()), pos))
    return index


def read_dump_frame(path, offset):
    """One dump frame at a byte offset from dump_steps: {column: array}, rows sorted by id."""
    with open(path, "rb") as f:
        f.seek(offset)
        f.readline()                      # ITEM: TIMESTEP
        step = int(f.readline())
        f.readline()                      # ITEM: NUMBER OF ATOMS
        natoms = int(f.readline())
        line = f.readline()               # ITEM: BOX BOUNDS
        for _ in range(3 if line.startswith(b"ITEM: BOX") else 0):
            f.readline()
        names = f.readline().decode().split()[2:]
        text = b"".join(f.readline() for _ in range(natoms))
    values = np.array(text.split(), dtype=float).reshape(natoms, len(names))
    frame = {name: values[:, k] for k, name in enumerate(names)}
    if "id" in frame:
        order = np.argsort(frame["id"])
        frame = {k: v[order] for k, v in frame.items()}
    frame["step"] = step
    return frame


def read_dump(path, steps=None):
    """{step: frame} for the steps asked (all when None)."""
    wanted = None if steps is None else set(steps)
    return {s: read_dump_frame(path, off) for s, off in dump_steps(path)
            if wanted is None or s in wanted}


def read_polylines(path):
    """The polyline file of fix membrane2d (keyword `polyline N file`):
    {step: {side: {'polyline': (n, 2) x y, 'chain': (m, 6) tag x y r fx fy}}}."""
    frames, step = {}, None
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        w = lines[i].split()
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            frames[step] = {}
            i += 2
        elif w[:2] in (["ITEM:", "POLYLINE"], ["ITEM:", "CHAIN"]):
            side, n = w[2], int(w[3])
            block = np.array([[float(x) for x in l.split()] for l in lines[i + 1:i + 1 + n]])
            frames[step].setdefault(side, {})["polyline" if w[1] == "POLYLINE" else "chain"] = block
            i += 1 + n
        else:
            i += 1
    return frames


def read_data_diameters(path):
    """The diameters of the Atoms section of a LAMMPS data file of
    scripts/generate_sample.py (id type diameter density x y z)."""
    d, inside = [], False
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "Atoms":
                inside = True
                continue
            if inside:
                if not t[0].isdigit():
                    break
                d.append(float(t[2]))
    return np.array(d)
