#!/usr/bin/python3
"""Files of a biaxial run, good and bad, for the command-line cases (cases/G_report.cases).

    report_files.py KIND PATH

writes PATH (an OUT table; with .rose and .dump for the kinds that say so) of the kind:
  good        201 lines to 10 % strain, a peak at 3 %, every column, PATH.rose, PATH.dump
  table       the same table alone (no .rose, no .dump)
  header      the header line only          empty       an empty file
  one, two    the first 1 or 2 lines         nopeak      the first 40 lines (still rising)
  nan         s1 nan on every line           inf         ev inf on every line
  nan-line    s1 nan on line 53 (step 25000) inf-ratio   s1/s3 inf on line 13
  order       lines 13 and 23 swapped        s3zero      s3 = 0 on every line
  noaxial     ea = 0 on every line           wrongcols   columns step x y
  data-first  a data line before the header
  cut-dump    good, PATH.dump cut inside its last line
  cut-dump-header  good, PATH.dump cut in the header of its 4th frame
  cut-rose    good, PATH.rose cut inside its last block
  rose-garbage  good, PATH.rose with a word in its 3rd block
  dump-cols   good, PATH.dump without the radius column
  sample      PATH is a folder: shear_rigid.txt and shear_membrane.txt (tables only)
The curve is liggghts_membrane.synthetic's elastic-plastic law (known constants).
"""
import os
import sys

import numpy as np

from liggghts_membrane import synthetic


def cut(path, keep):
    with open(path, "rb") as f:
        data = f.read()
    with open(path, "wb") as f:
        f.write(data[:keep] if keep >= 0 else data[:len(data) + keep])


def main(kind, path):
    curve = synthetic.elastoplastic_curve()
    cols = synthetic.full_columns(curve)
    n = len(cols["ea"])
    table = {
        "table": lambda: cols,
        "one": lambda: {k: v[:1] for k, v in cols.items()},
        "two": lambda: {k: v[:2] for k, v in cols.items()},
        "nopeak": lambda: {k: v[:40] for k, v in cols.items()},
        "nan": lambda: dict(cols, s1=np.full(n, np.nan)),
        "inf": lambda: dict(cols, ev=np.full(n, np.inf)),
        "nan-line": lambda: dict(cols, s1=np.where(np.arange(n) == 50, np.nan, cols["s1"])),
        "inf-ratio": lambda: dict(cols, **{"s1/s3": np.where(np.arange(n) == 10, np.inf, cols["s1/s3"])}),
        "order": lambda: {k: v[np.r_[0:10, 20, 11:20, 10, 21:n]] for k, v in cols.items()},
        "s3zero": lambda: dict(cols, s3=0 * cols["s3"]),
        "noaxial": lambda: dict(cols, ea=0 * cols["ea"]),
        "wrongcols": lambda: {"step": cols["step"], "x": cols["ea"], "y": cols["s1"]},
    }
    if kind in table:
        synthetic.write_out(path, table[kind]())
    elif kind == "header":
        with open(path, "w") as f:
            f.write("# a run\n# " + " ".join(cols) + "\n")
    elif kind == "empty":
        open(path, "w").close()
    elif kind == "data-first":
        synthetic.write_out(path, cols)
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write("0 0 1e5\n" + text)
    elif kind == "sample":
        os.makedirs(path, exist_ok=True)
        for case in ("rigid", "membrane"):
            synthetic.write_out(os.path.join(path, f"shear_{case}.txt"), cols)
    elif kind in ("good", "cut-dump", "cut-dump-header", "cut-rose", "rose-garbage", "dump-cols"):
        synthetic.write_band_run(path, curve, n=300, every=20)
        if kind == "cut-dump":
            cut(path + ".dump", -7)
        elif kind == "cut-dump-header":
            with open(path + ".dump", "rb") as f:
                data = f.read()
            starts = [k for k in range(len(data)) if data.startswith(b"ITEM: TIMESTEP", k)]
            cut(path + ".dump", starts[3] + 30)
        elif kind == "cut-rose":
            cut(path + ".rose", -30)
        elif kind == "rose-garbage":
            with open(path + ".rose") as f:
                lines = f.readlines()
            blocks = [k for k, l in enumerate(lines) if len(l.split()) == 2]
            lines[blocks[2] + 2] = "3 oops\n"
            with open(path + ".rose", "w") as f:
                f.writelines(lines)
        elif kind == "dump-cols":
            with open(path + ".dump") as f:
                text = f.read()
            out, drop, atoms = [], None, False
            for line in text.splitlines():
                w = line.split()
                if line.startswith("ITEM: ATOMS"):
                    drop = w.index("radius")
                    out.append(" ".join(w[:drop] + w[drop + 1:]))
                    atoms = True
                elif line.startswith("ITEM"):
                    out.append(line)
                    atoms = False
                else:
                    out.append(" ".join(w[:drop - 2] + w[drop - 1:]) if atoms else line)
            with open(path + ".dump", "w") as f:
                f.write("\n".join(out) + "\n")
    else:
        sys.exit(f"report_files.py: unknown kind '{kind}' (see the head of this file)")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
