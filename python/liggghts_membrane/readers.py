"""Readers for the files written by examples/biaxial/in.shear_rigid and in.shear_membrane
(and by the benchmarks' scripts, bench/in.*): every OUT-table and dump reader of the
project is here, with the key=value lines that the input scripts and fix membrane2d
print for programs (key_value_lines) and the OUT.params file of the shear scripts
(read_params).

The columns of the OUT table are taken by name from its header line (the last
comment line before the data), so that older runs without the fabric columns,
or future runs with extra columns, are still readable.
"""
import os

import numpy as np

# What the shear scripts write; the analysis only needs MECHANICAL_COLUMNS.
MECHANICAL_COLUMNS = ["step", "ea", "s1", "s3", "ev", "el"]
EXPECTED_COLUMNS = ("step t ea s1 s3 s1/s3 ev el I sxx_int syy_int C_n W H KE "
                    "a theta_a an theta_n f0 at Zm gsi sxx_lw syy_lw").split()


class InputError(ValueError):
    """A file the report cannot use, with a message naming the file, what is wrong and
    what to do (the command prints it instead of a traceback)."""


class OutputTable:
    """The OUT table of one run: columns by name, plus what was expected but absent.
    lines: the line number in the file of each row."""

    def __init__(self, path, columns, header, lines=None):
        self.path = path
        self.columns = columns
        self.header = header
        self.lines = lines
        self.missing = [c for c in EXPECTED_COLUMNS if c not in columns]
        self.extra = [c for c in header if c not in EXPECTED_COLUMNS]

    def has(self, name):
        """True when the column exists and holds at least one finite value."""
        return name in self.columns and np.isfinite(self.columns[name]).any()

    def __getitem__(self, name):
        return self.columns[name]

    def __len__(self):
        return len(next(iter(self.columns.values()))) if self.columns else 0


def _read_rows(path):
    """(header, rows, line numbers) of a table (read_columns)."""
    header, rows, lines = None, [], []
    with open(path, errors="replace") as f:
        for lineno, line in enumerate(f, 1):
            text = line.strip()
            if not text:
                continue
            if text.startswith("#"):
                if not rows:  # the last comment line before data is the header
                    header = text.lstrip("#").split()
                continue
            if header is None:
                raise InputError(f"{path}: line {lineno} holds data before any '#' header line "
                                 "naming the columns (doc/report.md, 'The files of a run')")
            words = text.split()
            if len(words) != len(header):
                continue
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                continue
            lines.append(lineno)
    if header is None:
        raise InputError(f"{path}: no header line (a '#' line naming the columns; an empty "
                         "file? doc/report.md, 'The files of a run')")
    return header, rows, lines


def read_columns(path):
    """{name: array} of a table whose columns are named by its header line (the last
    '#' comment line before the data): an OUT table, the pressure table of
    bench/in.stability_pressure, the f0 table of bench/f0_origin.inc. Lines after the
    header that do not have as many numbers as the header has names (an interrupted
    write) are skipped; the header names are returned too, in order."""
    header, rows, _ = _read_rows(path)
    data = np.array(rows, dtype=float).reshape(-1, len(header))
    return {name: data[:, k] for k, name in enumerate(header)}, header


def read_output(path):
    """Read an OUT table (read_columns). Repeated steps (a line printed by both
    `run 1` and `fix print`) keep their first line."""
    header, rows, lines = _read_rows(path)
    data = np.array(rows, dtype=float).reshape(-1, len(header))
    columns = {name: data[:, k] for k, name in enumerate(header)}
    lines = np.array(lines, dtype=int)
    if "step" in columns and len(columns["step"]):
        _, first = np.unique(columns["step"], return_index=True)
        keep = np.sort(first)
        columns = {name: col[keep] for name, col in columns.items()}
        lines = lines[keep]
    if "s1/s3" not in columns and "s1" in columns and "s3" in columns:
        columns["s1/s3"] = columns["s1"] / columns["s3"]
    missing = [c for c in MECHANICAL_COLUMNS if c not in columns]
    if missing:
        raise InputError(f"{path}: the header line lacks the column(s) {' '.join(missing)} "
                         f"(it names: {' '.join(header) or 'nothing'}); the report needs "
                         f"{' '.join(MECHANICAL_COLUMNS)} (doc/report.md, 'The files of a run')")
    return OutputTable(path, columns, header, lines)


def _line(table, k):
    return f"line {table.lines[k]}" if table.lines is not None else f"data row {k + 1}"


def check_table(table):
    """Refuse (InputError) a table the analysis would turn into wrong numbers: no data
    line, steps out of order (two runs in one file), a needed column not finite."""
    path = table.path
    if len(table) == 0:
        raise InputError(f"{path}: no data line after the header (the run wrote nothing yet, or "
                         "no line has one number per column of the header)")
    step = table["step"]
    back = np.nonzero(np.diff(step) < 0)[0]
    if len(back):
        k = back[0] + 1
        raise InputError(f"{path}, {_line(table, k)}: step {step[k]:.0f} after step "
                         f"{step[k - 1]:.0f}: the steps must increase (two runs written into "
                         "one file? keep one run per file)")
    for name in MECHANICAL_COLUMNS + ["s1/s3"]:
        col = table[name]
        bad = np.nonzero(~np.isfinite(col))[0]
        if len(bad):
            k = bad[0]
            where = _line(table, k) + ("" if name != "s1/s3" or "s1/s3" in table.header
                                       else " (s1/s3 = s1 / s3)")
            raise InputError(f"{path}, {where}: {name} = {col[k]} at step {step[k]:.0f} "
                             f"({len(bad)} of {len(col)} lines): the columns "
                             f"{' '.join(MECHANICAL_COLUMNS)} must be finite numbers; a run that "
                             "went unstable: report the lines before it (cut the table there)")
    low = np.nonzero(table["s3"] <= 0)[0]
    if len(low):
        k = low[0]
        raise InputError(f"{path}, {_line(table, k)}: s3 = {table['s3'][k]:g} at step {step[k]:.0f}: "
                         "the lateral stress must be positive (compression > 0, doc/report.md, "
                         "'Restrictions'); s1/s3 means nothing without it")


def _lines_of(path):
    """The lines of a text file split into words; a last line without its newline (a
    write cut short) is left out."""
    with open(path, errors="replace") as f:
        text = f.read()
    lines = text.split("\n")
    lines.pop()          # after the last newline: '' or the cut line
    return lines


def read_rose(path, notes=None):
    """Read a `fix ave/time mode vector` file of polar histograms.

    Returns a list of (step, block) with block a dict of arrays: 'centre_deg',
    'count', 'mean_fn', 'mean_ft' (one entry per bin, 0-360 degrees). A block cut
    short or unreadable (an interrupted run) ends the list; `notes` (a list) gets a
    line saying so.
    """
    blocks = []
    lines = [(k, l.split()) for k, l in enumerate(_lines_of(path), 1)
             if l.strip() and not l.lstrip().startswith("#")]
    i = 0
    while i < len(lines):
        lineno, head = lines[i]
        try:
            if len(head) != 2:
                raise ValueError
            step, nrows = int(float(head[0])), int(head[1])
            body = [w for _, w in lines[i + 1:i + 1 + nrows]]
            if nrows <= 0 or len(body) != nrows or any(len(w) < 5 for w in body):
                raise ValueError
            rows = np.array([[float(x) for x in w[:5]] for w in body])
        except ValueError:
            if notes is not None:
                notes.append(f"{path}: the block at line {lineno} is cut short or unreadable "
                             f"(an interrupted run?): {len(blocks)} complete block(s) used")
            break
        blocks.append((step, {"centre_deg": rows[:, 1], "count": rows[:, 2],
                              "mean_fn": rows[:, 3], "mean_ft": rows[:, 4]}))
        i += 1 + nrows
    return blocks


def dump_steps(path, notes=None):
    """Timesteps present in a LIGGGHTS text dump, with the byte offset of each frame,
    so that only the frames used are parsed (a full-size run has ~8 400 disks a frame).
    Only complete frames are listed: a frame with fewer atom lines than it announces, or
    whose last line is cut (an interrupted run), is left out and `notes` (a list) gets
    a line saying so."""
    index, cut = [], []
    frame = None

    def close(fr):
        if fr is None:
            return
        ok = (fr["step"] is not None and fr["natoms"] is not None and fr["ncols"] is not None
              and fr["count"] == fr["natoms"]
              and (fr["natoms"] == 0 or (fr["last"].endswith(b"\n")
                                         and len(fr["last"].split()) == fr["ncols"])))
        (index if ok else cut).append((fr["step"], fr["offset"]))

    with open(path, "rb") as f:
        expect = None
        while True:
            pos = f.tell()
            line = f.readline()
            if not line:
                break
            if line.startswith(b"ITEM:"):
                expect = None
                if line.startswith(b"ITEM: TIMESTEP"):
                    close(frame)
                    frame = {"offset": pos, "step": None, "natoms": None, "ncols": None,
                             "count": 0, "last": b""}
                    expect = "step"
                elif frame is None:
                    continue
                elif line.startswith(b"ITEM: NUMBER OF ATOMS"):
                    expect = "natoms"
                elif line.startswith(b"ITEM: ATOMS"):
                    frame["ncols"] = len(line.split()) - 2
                    expect = "atoms"
                continue
            if frame is None:
                continue
            if expect in ("step", "natoms"):
                try:
                    frame[expect] = int(line)
                except ValueError:
                    pass
                expect = None
            elif expect == "atoms":
                frame["count"] += 1
                frame["last"] = line
    close(frame)
    if cut and notes is not None:
        steps = ", ".join("?" if s is None else str(s) for s, _ in cut)
        notes.append(f"{path}: frame(s) of step {steps} cut short or unreadable (an interrupted "
                     f"run?): left out, {len(index)} complete frame(s) used")
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
        names = f.readline().decode(errors="replace").split()[2:]
        text = b"".join(f.readline() for _ in range(natoms))
    try:
        values = np.array(text.split(), dtype=float).reshape(natoms, len(names))
    except ValueError:
        raise InputError(f"{path}: the frame of step {step} (byte {offset}) does not hold "
                         f"{natoms} lines of {len(names)} numbers ({' '.join(names)})") from None
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


def key_value_lines(text, tag):
    """[{key: value}] of the lines of `text` whose first word is `tag`, each followed by
    key=value words (what the input scripts and fix membrane2d print for programs, e.g.
    'membrane_counts escaped=2 chain_failures=0'); a value is a float when it reads as
    one, else the text."""
    out = []
    for line in text.splitlines():
        words = line.split()
        if not words or words[0] != tag:
            continue
        d = {}
        for w in words[1:]:
            key, eq, value = w.partition("=")
            if not eq:
                continue
            try:
                d[key] = float(value)
            except ValueError:
                d[key] = value
        out.append(d)
    return out


def read_params(path):
    """{key: value} of a parameters file (OUT.params of the shear scripts: lines of
    key=value words after a tag, shear_loading.inc), every line merged in order (a later
    key replaces an earlier one); {} when there is no such file."""
    if not os.path.exists(path):
        return {}
    with open(path, errors="replace") as f:
        text = f.read()
    out = {}
    for line in text.splitlines():
        words = line.split()
        if words:
            for d in key_value_lines(line, words[0]):
                out.update(d)
    return out


def read_data_atoms(path):
    """The Atoms section of a LAMMPS data file of atom style sphere (the sample command's,
    liggghts_membrane.sample): {id, type, diameter, density, x, y, z: array}."""
    rows, inside = [], False
    with open(path) as f:
        for line in f:
            t = line.split("#")[0].split()
            if not t:
                continue
            if t[0] == "Atoms":
                inside = True
                continue
            if inside:
                if not t[0].isdigit():
                    break
                rows.append([float(w) for w in t[:7]])
    data = np.array(rows, dtype=float).reshape(-1, 7)
    return {name: data[:, k] for k, name in enumerate(("id", "type", "diameter", "density", "x", "y", "z"))}


def read_data_diameters(path):
    """The diameters of the Atoms section of a LAMMPS data file (read_data_atoms)."""
    return read_data_atoms(path)["diameter"]
