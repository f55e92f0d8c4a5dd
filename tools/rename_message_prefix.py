#!/usr/bin/env python3
"""Rewrite the expected messages of one style in the tests to the message form of
doc/messages.md: "Fix stability/guard: ..." becomes "Fix stability/guard (id g): ...",
the ID taken from the style's own fix or compute line in the test.

    tools/rename_message_prefix.py --style "Fix stability/guard"           # rewrite
    tools/rename_message_prefix.py --style "Fix membrane2d" --dry-run -v   # show only
    tools/rename_message_prefix.py --style "Compute fabric" FILE...        # these files

Where the ID comes from:
  tests/adversarial/cases/*.cases  the case's own input lines ('|' and '>'), else the
                                   set-ups its 'setup' line names;
  tests/scripts/*.in               for '#@ error TEXT ::: COMMAND' the COMMAND's line
                                   (the last one there), else the script's own lines
                                   (and the files it includes from its folder);
  any other file (Python, C++)     its own lines, else --id.
When a scope defines several IDs of the style, the first defined is taken (the
one whose init speaks first) and the line is listed as ambiguous: check it.
Only the given style's prefix is touched; a line whose ID cannot be found is
left as it is and listed. Exit status 1 when some line was left or ambiguous.
"""
import argparse
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_FILES = ("tests/adversarial/cases/*.cases", "tests/scripts/*.in", "tests/python/*.py",
                 "tests/examples/*.py", "tests/unit/*/*.cpp", "tests/unit/*/*.h")
OWN_TEST = "test_rename_message_prefix.py"  # its fixtures keep the old form


def parse_style(text):
    """'Fix membrane2d' -> ('fix', 'membrane2d', 'Fix membrane2d:')"""
    words = text.split()
    if len(words) != 2 or words[0].lower() not in ("fix", "compute"):
        raise SystemExit("--style must be 'Fix NAME' or 'Compute NAME', not %r" % text)
    kind, name = words[0].lower(), words[1]
    return kind, name, "%s %s:" % (kind.capitalize(), name)


class Style:
    def __init__(self, text):
        self.kind, self.name, self.old = parse_style(text)
        # "fix ID GROUP STYLE" / "compute ID GROUP STYLE"
        self.define = re.compile(r"^\s*%s\s+(\S+)\s+\S+\s+%s(\s|$)" % (self.kind, re.escape(self.name)))
        # the old prefix, followed by a space or the end of the expected text
        self.prefix = re.compile(re.escape(self.old) + r"( |$)")

    def has(self, line):
        return self.prefix.search(line) is not None

    def ids(self, lines):
        """the IDs the input lines define, in order, each once"""
        found = []
        for line in lines:
            for part in line.split("\\n"):
                m = self.define.match(part)
                if m and m.group(1) not in found:
                    found.append(m.group(1))
        return found

    def new(self, ident):
        return "%s %s (id %s):" % (self.kind.capitalize(), self.name, ident)


class Report:
    def __init__(self):
        self.changed, self.left, self.ambiguous = [], [], []


def rewrite_line(line, style, ids, where, report):
    if not style.has(line):
        return line
    if not ids:
        report.left.append(where)
        return line
    if len(ids) > 1:
        report.ambiguous.append("%s (IDs %s; took %s)" % (where, ", ".join(ids), ids[0]))
    report.changed.append(where)
    return style.prefix.sub(lambda m: style.new(ids[0]) + m.group(1), line)


def setup_lines(folder, names):
    lines = []
    for name in names:
        path = os.path.join(folder, name + ".inc")
        if os.path.exists(path):
            with open(path) as f:
                lines += f.read().splitlines()
    return lines


def rewrite_cases(path, lines, style, report):
    """a .cases file: blocks from one 'case NAME' line to the next"""
    setups = os.path.join(os.path.dirname(os.path.dirname(path)), "setups")
    out, block = [], []
    starts = [k for k, l in enumerate(lines) if re.match(r"^case\s", l)] + [len(lines)]
    out = lines[:starts[0]]  # the file's head: comments, no ID
    for k, l in enumerate(out):
        if style.has(l):
            report.left.append("%s:%d (outside every case)" % (path, k + 1))
    for a, b in zip(starts, starts[1:]):
        block = lines[a:b]
        inputs = [re.sub(r"^\s*[|>]\s?", "", l) for l in block if re.match(r"^\s*[|>]", l)]
        ids = style.ids(inputs)
        if not ids:
            names = [w for l in block if re.match(r"^\s*setup\s", l)
                     for w in l.split()[1:] if "=" not in w]
            ids = style.ids(setup_lines(setups, names))
        for k, l in enumerate(block):
            if re.match(r"^\s*[|>$]", l):
                out.append(l)  # input lines are left alone
                continue
            out.append(rewrite_line(l, style, ids, "%s:%d" % (path, a + k + 1), report))
    return out


def included(path, lines):
    """the lines of the files a script includes from its own folder (${testdir}/NAME)"""
    more = []
    for l in lines:
        m = re.match(r"^\s*include\s+\$\{testdir\}/(\S+)", l)
        if m and os.path.exists(os.path.join(os.path.dirname(path), m.group(1))):
            with open(os.path.join(os.path.dirname(path), m.group(1))) as f:
                more += f.read().splitlines()
    return more


def rewrite_script(path, lines, style, report):
    """an input script of tests/scripts: '#@' lines; COMMANDs of '#@ error' first"""
    body = [l for l in lines if not l.lstrip().startswith("#")]
    body_ids = style.ids(body) or style.ids(included(path, body))
    out = []
    for k, l in enumerate(lines):
        where = "%s:%d" % (path, k + 1)
        if not l.startswith("#@") or not style.has(l):
            if style.has(l):
                l = rewrite_line(l, style, body_ids, where, report)
            out.append(l)
            continue
        ids = body_ids
        if l.startswith("#@ error") and " ::: " in l:
            text, command = l.split(" ::: ", 1)
            own = style.ids([command])
            if own:
                ids = own[-1:]
            out.append(rewrite_line(text, style, ids, where, report) + " ::: " + command)
            continue
        out.append(rewrite_line(l, style, ids, where, report))
    return out


def rewrite_other(path, lines, style, fallback, report):
    ids = style.ids(lines) or ([fallback] if fallback else [])
    return [rewrite_line(l, style, ids, "%s:%d" % (path, k + 1), report)
            for k, l in enumerate(lines)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--style", required=True, help="'Fix NAME' or 'Compute NAME'")
    ap.add_argument("--id", help="the ID for files without a line of the style (fixtures)")
    ap.add_argument("--dry-run", action="store_true", help="change no file")
    ap.add_argument("-v", "--verbose", action="store_true", help="list every changed line")
    ap.add_argument("files", nargs="*", help="default: the tests (%s)" % ", ".join(DEFAULT_FILES))
    args = ap.parse_args()
    style = Style(args.style)
    files = args.files or sorted(f for pattern in DEFAULT_FILES
                                 for f in glob.glob(os.path.join(ROOT, pattern))
                                 if os.path.basename(f) != OWN_TEST)
    report = Report()
    touched = 0
    for path in files:
        with open(path) as f:
            text = f.read()
        if style.old not in text:  # a quick test; has() decides per line
            continue
        lines = text.split("\n")
        if path.endswith(".cases"):
            new = rewrite_cases(path, lines, style, report)
        elif path.endswith(".in"):
            new = rewrite_script(path, lines, style, report)
        else:
            new = rewrite_other(path, lines, style, args.id, report)
        if new != lines:
            touched += 1
            if not args.dry_run:
                with open(path, "w") as f:
                    f.write("\n".join(new))
    rel = lambda w: os.path.relpath(w, ROOT) if os.path.isabs(w) else w  # noqa: E731
    if args.verbose:
        for w in report.changed:
            print("changed   " + rel(w))
    for w in report.ambiguous:
        print("ambiguous " + rel(w))
    for w in report.left:
        print("left      " + rel(w) + " (no ID found)")
    print("%s: %d line(s) in %d file(s) %s, %d ambiguous, %d left" %
          (style.old.rstrip(":"), len(report.changed), touched,
           "to change" if args.dry_run else "changed", len(report.ambiguous), len(report.left)))
    return 1 if report.left or report.ambiguous else 0


if __name__ == "__main__":
    sys.exit(main())
