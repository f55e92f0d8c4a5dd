"""The parameters of the LIGGGHTS input scripts, read from the scripts themselves.

Every tuned number of the biaxial test (contact stiffness, density, time step, servo
gain, confining stress, damping, ...) is defined once, in a `variable NAME index VALUE`
(or `equal` / `string`) line of examples/biaxial/in.* and *.inc or bench/in.*. The
Python side reads it from there instead of keeping a copy:

    >>> p = read_variables("examples/biaxial/in.shear_rigid")   # follows its includes
    >>> number(p, "kn")
    84500000.0
"""
import os
import re

# `variable NAME STYLE VALUE ...` with the styles whose value is one word or a quoted string
_VARIABLE = re.compile(r"variable\s+(\S+)\s+(index|equal|string)\s+(\"[^\"]*\"|'[^']*'|\S+)")
_INCLUDE = re.compile(r"include\s+(\S+)")


def _uncommented(line):
    """A line without its comment: from the first '#' outside quotes on."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            quote = None if c == quote else quote
        elif c in "\"'":
            quote = c
        elif c == "#":
            return line[:i]
    return line


def _lines(path):
    """The command lines of a script: comments cut off, '&' continuations joined."""
    out, pending = [], ""
    with open(path, errors="replace") as f:
        for raw in f:
            line = _uncommented(raw).rstrip()
            if line.endswith("&"):
                pending += line[:-1] + " "
                continue
            out.append((pending + line).strip())
            pending = ""
    if pending.strip():
        out.append(pending.strip())
    return out


def read_variables(path, follow_includes=True):
    """{name: value text} of the variables a script defines, in the order LIGGGHTS sees
    them, `include FILE` lines followed (relative to the script's folder; an include
    whose name holds a ${...} or that does not exist is skipped). As in LIGGGHTS, the
    first definition of an `index` variable wins (later ones are ignored) and a later
    `equal` or `string` definition replaces the earlier one."""
    values, styles = {}, {}
    _collect(os.path.abspath(path), values, styles, follow_includes, set())
    return values


def _collect(path, values, styles, follow_includes, seen):
    if path in seen:
        return
    seen.add(path)
    for line in _lines(path):
        m = _VARIABLE.match(line)
        if m:
            name, style, value = m.group(1), m.group(2), m.group(3).strip("\"'")
            if not (style == "index" and styles.get(name) == "index"):
                values[name], styles[name] = value, style
            continue
        m = _INCLUDE.match(line)
        if m and follow_includes and "$" not in m.group(1):
            inc = os.path.join(os.path.dirname(path), m.group(1))
            if os.path.exists(inc):
                _collect(inc, values, styles, follow_includes, seen)


def number(variables, name):
    """The value of a variable as a float; a KeyError names the variable when a script
    does not define it, a ValueError when its value is not a plain number."""
    if name not in variables:
        raise KeyError(f"the input script defines no variable '{name}'")
    try:
        return float(variables[name])
    except ValueError:
        raise ValueError(f"variable '{name}' = '{variables[name]}' is not a plain number") from None


def numbers(path, *names):
    """The floats of the variables `names` of one script (includes followed)."""
    v = read_variables(path)
    return [number(v, n) for n in names]
