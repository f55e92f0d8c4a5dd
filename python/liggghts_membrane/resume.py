"""Resuming an interrupted shear from the restart files it wrote.

A shear run with `-var restartevery N` writes OUT.restart.<step> every N steps. To
resume, the shear script is run again on the latest of them with `-var resume 1` and
its outputs go to OUT.part* (LIGGGHTS opens some output files afresh: fix ave/time,
dump, fix membrane2d polyline). Afterwards each output of the part is spliced into the
matching output of the run: the records of the run up to the restart step, then those of
the part after it. Every output is a sequence of records with a timestep:
  rows      OUT, OUT.ramp: '#' header lines, then one line per output step;
  blocks    OUT.rose (fix ave/time mode vector): '#' header lines, then per output
            step a line 'step nrows' and nrows lines;
  frames    OUT.dump, OUT.polyline: 'ITEM: TIMESTEP' / step / the frame's lines.
A record cut short by the interruption lies after the restart step and is dropped.
"""
import glob
import os
import re

# the outputs of a shear run and how their records are delimited
OUTPUTS = [("", "rows"), (".ramp", "rows"), (".rose", "blocks"), (".dump", "frames"), (".polyline", "frames")]
PART = ".part"


def _int(word):
    try:
        return int(float(word))
    except ValueError:
        return None


def split_records(lines, kind):
    """(header lines, [(step, lines)]) of an output's lines (newlines kept)."""
    header, records, k = [], [], 0
    if kind in ("rows", "blocks"):
        while k < len(lines) and lines[k].startswith("#"):
            header.append(lines[k])
            k += 1
    while k < len(lines):
        line = lines[k]
        if kind == "rows":
            step = _int(line.split()[0]) if line.strip() and line.endswith("\n") else None
            if step is not None:
                records.append((step, [line]))
            k += 1
        elif kind == "blocks":
            words = line.split()
            if len(words) != 2 or _int(words[0]) is None or _int(words[1]) is None:
                k += 1
                continue
            n = _int(words[1])
            block = lines[k:k + 1 + n]
            if len(block) == 1 + n and block[-1].endswith("\n"):
                records.append((_int(words[0]), block))
            k += 1 + n
        else:
            if not line.startswith("ITEM: TIMESTEP"):
                k += 1
                continue
            j = k + 2
            while j < len(lines) and not lines[j].startswith("ITEM: TIMESTEP"):
                j += 1
            if k + 1 < len(lines) and _int(lines[k + 1]) is not None and lines[j - 1].endswith("\n"):
                records.append((_int(lines[k + 1]), lines[k:j]))
            k = j
    return header, records


def splice(path, part_path, step, kind):
    """Rewrite `path` with its records up to `step` and those of `part_path` after it
    (the header of `path`, or of the part when `path` has none)."""
    def read(p):
        if not os.path.exists(p):
            return [], []
        with open(p) as f:
            return split_records(f.readlines(), kind)

    header, records = read(path)
    part_header, part_records = read(part_path)
    lines = list(header or part_header)
    for s, rec in records:
        if s <= step:
            lines += rec
    for s, rec in part_records:
        if s > step:
            lines += rec
    with open(path + ".tmp", "w") as f:
        f.writelines(lines)
    os.replace(path + ".tmp", path)


def restart_steps(out):
    """{step: file} of the restart files OUT.restart.<step>."""
    found = {}
    for p in glob.glob(glob.escape(out) + ".restart.*"):
        m = re.fullmatch(r"\.restart\.(\d+)", p[len(out):])
        if m:
            found[int(m.group(1))] = p
    return found


def finish_part(out):
    """Splice a resumed part OUT.part* into OUT*, move its restart files next to the
    run's, remove the part. The part's base step is in OUT.part.base."""
    base_file = out + PART + ".base"
    if not os.path.exists(base_file):
        return
    with open(base_file) as f:
        base = int(f.read())
    part = out + PART
    for suffix, kind in OUTPUTS:
        if os.path.exists(part + suffix):
            splice(out + suffix, part + suffix, base, kind)
            os.remove(part + suffix)
    if os.path.exists(part + ".params"):   # the same parameters (the shear's start values restored)
        os.replace(part + ".params", out + ".params")
    for s, p in restart_steps(part).items():
        os.replace(p, "%s.restart.%d" % (out, s))
    for p in glob.glob(glob.escape(part) + ".restart.*"):
        os.remove(p)
    os.remove(base_file)


def start_resume(out, walls):
    """Make ready to resume the run of OUT: finish a previous part, take the latest
    restart step S, cut every output after S, give the restart file its walls include.
    Returns the restart file, or None when there is none."""
    finish_part(out)
    steps = restart_steps(out)
    if not steps:
        return None
    step = max(steps)
    for suffix, kind in OUTPUTS:
        if os.path.exists(out + suffix):
            splice(out + suffix, out + PART + suffix + ".none", step, kind)
    with open(walls) as src, open(steps[step] + ".walls", "w") as dst:
        dst.write(src.read())
    with open(out + PART + ".base", "w") as f:
        f.write(str(step))
    return steps[step]


def remove_restarts(out):
    """The restart files of a finished run are no longer needed."""
    for p in list(restart_steps(out).values()):
        os.remove(p)
        if os.path.exists(p + ".walls"):
            os.remove(p + ".walls")
