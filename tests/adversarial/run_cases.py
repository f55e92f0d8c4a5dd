#!/usr/bin/env python3
"""Table-driven adversarial cases for the four styles, run through liggghts-membrane.

    run_cases.py --exe build/app/liggghts-membrane cases/B_variables.cases [more.cases]
    run_cases.py --exe ... --case band_negative cases/A_membrane.cases   # one case
    run_cases.py --list                                                  # counts per class
    run_cases.py -j 2                                                    # every cases/*.cases

A .cases file is a list of blocks, one per case ('#' at column 0 and blank
lines are comments). A block starts with 'case NAME' and holds directives and
input lines ('|' then the LIGGGHTS command):

    case band_negative
      setup  block n=4 rows=4
      ranks  1, 2 grid 1 2 1
      error  Fix membrane2d: keyword 'band' = -1: must be a positive number
      | fix m all membrane2d pressure 1e5 ylo ${ylo} yhi ${yhi} band -1
      | run 0

Directives:
  setup NAME... [var=value...]  include setups/NAME.inc in order, after
                                'variable var index value' for each var=value
                                (the set-ups read their parameters as index
                                variables); 'setup none': the commands do it all
  ranks CONFIG, CONFIG...       run on each: '1', '2', '2 grid PX PY PZ' (the
                                grid reaches 'processors ${px} ${py} ${pz}' of
                                setups/prelude.inc); default '1'
  error TEXT                    the run must fail (non-zero exit, no signal, no
                                timeout) with TEXT in its output
  output TEXT / no-output TEXT  TEXT must (not) be in the output
  expect NAME VALUE TOL         RESULT NAME within TOL (absolute) of VALUE;
  expect NAME VALUE rel TOL     ... relative; 'expect NAME > V' (or <): a bound
  finite                        every RESULT value is a finite number
  same [RTOL [ATOL]]            every RESULT value equal on all the rank
                                configurations (default rtol 1e-10, atol 0)
  timeout SECONDS               per run (default 120)
  memory MB                     limit each rank's address space (ulimit -v): a
                                run that needs more must fail cleanly, not abort
  note TEXT                     a comment shown with --list -v

Command-line cases (class G: the report, the sample command, run.sh): '$ COMMAND'
lines instead of '|' lines, run as one bash script (set -e -o pipefail) in the case's
fresh temporary folder, with ${repo} (the repository root), ${exe} (the executable),
${python} (/usr/bin/python3) and ${testdir} (setups/) in its environment:

    case report_header_only
      error  no data line after the header
      $ ${python} ${testdir}/report_files.py header out.txt
      $ ${python} ${repo}/scripts/biaxial_report.py out.txt

'error', 'output', 'no-output', 'expect' (RESULT lines it echoes), 'timeout' and 'note'
apply; 'setup', 'ranks', 'prepare', 'memory' and 'same' do not. Besides a signal, a
Python traceback or a bash runtime error (unbound variable, syntax error, integer
expression expected, command not found, bad substitution) counts as a crash.

The input prints values as:  print "RESULT name ${v}"  (or $(f_mem[1])).
A run that is killed by a signal (segfault, abort: exit 134/139, an uncaught
C++ exception), times out, or prints NaN/inf for an expected value fails its
case whatever the expectation. ${testdir} is the setups folder.
Each run works in its own temporary folder (files the case writes go there).
"""
import argparse
import concurrent.futures
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
from collections import OrderedDict

HERE = os.path.dirname(os.path.abspath(__file__))
from liggghts_membrane import run_script

SETUPS = os.path.join(HERE, "setups")
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
PYTHON = "/usr/bin/python3"
DEFAULT_TIMEOUT = 120
CRASH_TEXT = re.compile(r"Segmentation fault|signal 11|exited on signal|terminate called|"
                        r"Aborted \(core dumped\)|Floating point exception|double free|"
                        r"corrupted|stack smashing|std::bad_alloc")
# what a command-line tool must never print: its own crash instead of a message
SHELL_CRASH_TEXT = re.compile(r"Traceback \(most recent call last\)|unbound variable|"
                              r"syntax error|integer expression expected|command not found|"
                              r"bad substitution|value too great for base|invalid arithmetic")
DIRECTIVES = ("setup", "ranks", "error", "output", "no-output", "expect", "finite", "same",
              "timeout", "memory", "note", "prepare")


class Case:
    def __init__(self, name, path, line):
        self.name, self.path, self.line = name, path, line
        self.cls = os.path.basename(path).split("_")[0].split(".")[0]
        self.setups, self.vars = [], []
        self.ranks = None
        self.errors, self.outputs, self.no_outputs, self.expects = [], [], [], []
        self.finite = False
        self.same = None
        self.timeout = DEFAULT_TIMEOUT
        self.memory_mb = None
        self.notes = []
        self.commands = []
        self.prepare_np = None     # 'prepare NP': the set-ups and the '>' lines run first,
        self.prepare_commands = []  # on NP ranks in the same folder (e.g. to write a restart)
        self.shell = []            # '$' lines: a command-line case (bash, no LIGGGHTS input)

    def configs(self):
        return self.ranks or [(1, None)]


def parse_ranks(text, where):
    out = []
    for item in text.split(","):
        w = item.split()
        if len(w) == 1 and w[0].isdigit():
            out.append((int(w[0]), None))
        elif len(w) == 5 and w[0].isdigit() and w[1] == "grid":
            out.append((int(w[0]), tuple(w[2:])))
        else:
            raise SystemExit("%s: bad rank configuration '%s' (want N or N grid PX PY PZ)"
                             % (where, item.strip()))
    return out


def parse_file(path):
    cases, case = [], None
    with open(path) as f:
        for lineno, raw in enumerate(f, 1):
            where = "%s:%d" % (path, lineno)
            line = raw.rstrip("\n")
            stripped = line.strip()
            if not stripped or line.startswith("#"):
                continue
            if stripped.startswith("$"):
                if case is None:
                    raise SystemExit("%s: command line outside a case" % where)
                case.shell.append(stripped[1:].strip())
                continue
            if stripped.startswith(">"):
                if case is None:
                    raise SystemExit("%s: input line outside a case" % where)
                case.prepare_commands.append(stripped[1:].lstrip())
                continue
            if stripped.startswith("|"):
                if case is None:
                    raise SystemExit("%s: input line outside a case" % where)
                case.commands.append(stripped[1:].lstrip() if stripped != "|" else "")
                continue
            word, _, rest = stripped.partition(" ")
            rest = rest.strip()
            if word == "case":
                if not rest or " " in rest:
                    raise SystemExit("%s: 'case NAME' (one word)" % where)
                case = Case(rest, path, lineno)
                cases.append(case)
                continue
            if case is None or word not in DIRECTIVES:
                raise SystemExit("%s: unknown line '%s'" % (where, stripped))
            if word == "setup":
                for w in rest.split():
                    if "=" in w:
                        case.vars.append(tuple(w.split("=", 1)))
                    elif w != "none":
                        if not os.path.exists(os.path.join(SETUPS, w + ".inc")):
                            raise SystemExit("%s: no set-up setups/%s.inc" % (where, w))
                        case.setups.append(w)
            elif word == "ranks":
                case.ranks = (case.ranks or []) + parse_ranks(rest, where)
            elif word == "error":
                case.errors.append(rest)
            elif word == "output":
                case.outputs.append(rest)
            elif word == "no-output":
                case.no_outputs.append(rest)
            elif word == "expect":
                w = rest.split()
                if not (len(w) == 3 or (len(w) == 4 and w[2] == "rel")):
                    raise SystemExit("%s: expect NAME VALUE TOL | NAME VALUE rel TOL | NAME > V" % where)
                case.expects.append(w)
            elif word == "finite":
                case.finite = True
            elif word == "same":
                w = [float(x) for x in rest.split()]
                case.same = (w + [1e-10, 0.0][len(w):])[:2]
            elif word == "timeout":
                case.timeout = int(rest)
            elif word == "memory":
                case.memory_mb = int(rest)
            elif word == "note":
                case.notes.append(rest)
            elif word == "prepare":
                case.prepare_np = int(rest)
    names = [c.name for c in cases]
    for c in cases:
        if names.count(c.name) > 1:
            raise SystemExit("%s: case '%s' is defined twice" % (path, c.name))
        if c.shell and (c.commands or c.prepare_commands or c.setups or c.vars or c.ranks
                        or c.prepare_np or c.memory_mb or c.same):
            raise SystemExit("%s:%d: case '%s': '$' command lines go with error, output, "
                             "no-output, expect, finite, timeout, note only" % (path, c.line, c.name))
        if not c.commands and not c.shell:
            raise SystemExit("%s:%d: case '%s' has no input lines" % (path, c.line, c.name))
        if not (c.errors or c.outputs or c.no_outputs or c.expects or c.finite or c.same):
            raise SystemExit("%s:%d: case '%s' has no expectation" % (path, c.line, c.name))
        if c.errors and (c.expects or c.finite or c.same):
            raise SystemExit("%s:%d: case '%s': 'error' cannot go with values" % (path, c.line, c.name))
        if c.same and len(c.configs()) < 2:
            raise SystemExit("%s:%d: case '%s': 'same' needs two rank configurations"
                             % (path, c.line, c.name))
    return cases


def script_text(case, grid, stage="main"):
    """The input of a rank configuration; with 'prepare', the set-ups go to the
    prepare stage and the main stage has only its own lines."""
    lines = ["# case %s (%s:%d)" % (case.name, os.path.basename(case.path), case.line)]
    if grid:
        lines += ["variable        %s index %s" % (p, n) for p, n in zip(("px", "py", "pz"), grid)]
    lines += ["variable        %s index %s" % kv for kv in case.vars]
    if stage == "prepare" or case.prepare_np is None:
        lines += ["include         ${testdir}/%s.inc" % s for s in case.setups]
    lines += case.prepare_commands if stage == "prepare" else case.commands
    return "\n".join(lines) + "\n"


def crashed(rc, out):
    """A signal (segfault, abort, uncaught exception), directly or through mpirun."""
    return rc < 0 or rc in (134, 136, 139) or (rc != 0 and CRASH_TEXT.search(out) is not None)


def error_line(out):
    for line in out.splitlines():
        if "ERROR" in line:
            return line.strip()
    lines = [l.strip() for l in out.strip().splitlines() if l.strip()]
    return lines[-1] if lines else "(no output)"


def parse_results(out):
    vals = OrderedDict()
    for name, text in run_script.RESULT.findall(out):
        try:
            vals[name] = float(text)
        except ValueError:
            vals[name] = float("nan")   # unparsable ('${v}', garbage): counts as not finite
    return vals


def check_values(case, vals, label):
    fails = []
    for w in case.expects:
        name = w[0]
        if name not in vals:
            fails.append("%s: RESULT %s not printed" % (label, name))
            continue
        v = vals[name]
        if not math.isfinite(v):
            fails.append("%s: %s = %r (not finite)" % (label, name, v))
            continue
        if w[1] in ("<", ">"):
            bound = float(w[2])
            ok = v > bound if w[1] == ">" else v < bound
            want = "%s %s" % (w[1], w[2])
        else:
            target = float(w[1])
            tol = float(w[3]) * abs(target) if w[2] == "rel" else float(w[2])
            ok = abs(v - target) <= tol
            want = "%r +- %g" % (target, tol)
        if not ok:
            fails.append("%s: %s = %r, want %s" % (label, name, v, want))
    if case.finite:
        if not vals:
            fails.append("%s: no RESULT printed" % label)
        bad = ["%s = %r" % (k, v) for k, v in vals.items() if not math.isfinite(v)]
        if bad:
            fails.append("%s: not finite: %s" % (label, ", ".join(bad)))
    return fails


def shell_text(case):
    return ("# case %s (%s:%d)\nset -e -o pipefail\n" % (case.name, os.path.basename(case.path), case.line)
            + "\n".join(case.shell) + "\n")


def run_shell(case, exe, keep=None):
    """Run the '$' lines of a command-line case: (exit status, output); 124 and
    'TIMEOUT' for a timeout."""
    with tempfile.TemporaryDirectory(prefix="adv_") as work:
        text = shell_text(case)
        script = os.path.join(work, "case.sh")
        with open(script, "w") as f:
            f.write(text)
        if keep:
            os.makedirs(keep, exist_ok=True)
            with open(os.path.join(keep, case.name + ".sh"), "w") as f:
                f.write(text)
        env = dict(os.environ, repo=ROOT, exe=exe, python=PYTHON, testdir=SETUPS)
        p = subprocess.Popen(["bash", script], cwd=work, env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, errors="replace",
                             start_new_session=True)    # its own group: a timeout ends it all
        try:
            out, _ = p.communicate(timeout=case.timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.communicate()
            return 124, "TIMEOUT after %d s" % case.timeout
        return p.returncode, out


def judge(case, label, rc, out, fails, shell=False):
    """Check one run's exit status and output against the case; appends to fails and
    returns the RESULT values (None when the run crashed, hung or failed)."""
    if rc == 124 and out.startswith("TIMEOUT"):
        fails.append("%s: hangs (timeout after %d s)" % (label, case.timeout))
        return None
    if crashed(rc, out):
        fails.append("%s: crash (exit %d): %s" % (label, rc, error_line(out)))
        return None
    if shell and SHELL_CRASH_TEXT.search(out):
        line = next(l for l in out.splitlines() if SHELL_CRASH_TEXT.search(l))
        fails.append("%s: crash (exit %d, a traceback or shell error): %s" % (label, rc, line.strip()))
        return None
    if case.errors:
        if rc == 0:
            fails.append("%s: no error (exit 0), wanted '%s'" % (label, case.errors[0]))
        for e in case.errors:
            if rc != 0 and e not in out:
                fails.append("%s: wanted '%s', got: %s" % (label, e, error_line(out)))
    elif rc != 0:
        fails.append("%s: failed (exit %d): %s" % (label, rc, error_line(out)))
        return None
    for t in case.outputs:
        if t not in out:
            fails.append("%s: output lacks '%s'" % (label, t))
    for t in case.no_outputs:
        if t in out:
            fails.append("%s: output has '%s'" % (label, t))
    if case.errors:
        return None
    vals = parse_results(out)
    fails += check_values(case, vals, label)
    return vals


def run_case(case, exe, keep=None):
    """Returns (ok, list of failure texts)."""
    fails, runs = [], []
    if case.shell:
        rc, out = run_shell(case, exe, keep)
        judge(case, "shell", rc, out, fails, shell=True)
        return not fails, fails
    for np_, grid in case.configs():
        label = "np=%d%s" % (np_, " grid %s" % " ".join(grid) if grid else "")
        with tempfile.TemporaryDirectory(prefix="adv_") as work:
            script = os.path.join(work, "case.in")
            text = script_text(case, grid)
            with open(script, "w") as f:
                f.write(text)
            if keep:
                os.makedirs(keep, exist_ok=True)
                tag = "%s.np%d%s.in" % (case.name, np_, "".join(grid) if grid else "")
                with open(os.path.join(keep, tag), "w") as f:
                    f.write(text)
            run_exe = exe
            if case.memory_mb:
                # each rank runs through this wrapper (run_script.run takes the executable only)
                run_exe = os.path.join(work, "limited.sh")
                with open(run_exe, "w") as f:
                    f.write('#!/bin/sh\nulimit -v %d\nexec "%s" "$@"\n' % (case.memory_mb * 1024, exe))
                os.chmod(run_exe, 0o755)
            if case.prepare_np:
                prepare = os.path.join(work, "prepare.in")
                with open(prepare, "w") as f:
                    f.write(script_text(case, None, "prepare"))
                rc, out = run_script.run(exe, case.prepare_np, prepare, work, case.timeout, SETUPS)
                if rc != 0:
                    fails.append("%s: the prepare stage (np=%d) failed (exit %d): %s"
                                 % (label, case.prepare_np, rc, error_line(out)))
                    continue
            rc, out = run_script.run(run_exe, np_, script, work, case.timeout, SETUPS)
        vals = judge(case, label, rc, out, fails)
        if vals is not None:
            runs.append((label, vals))
    if case.same and len(runs) == len(case.configs()):
        rtol, atol = case.same
        base_label, base = runs[0]
        if not base:
            fails.append("same: no RESULT printed")
        for label, vals in runs[1:]:
            for k, v in base.items():
                w = vals.get(k)
                if w is None:
                    fails.append("same: %s missing on %s" % (k, label))
                elif not (math.isfinite(v) and math.isfinite(w)):
                    fails.append("same: %s = %r (%s), %r (%s)" % (k, v, base_label, w, label))
                elif abs(w - v) > rtol * max(abs(v), abs(w)) + atol:
                    fails.append("same: %s = %r (%s) vs %r (%s)" % (k, v, base_label, w, label))
            for k in vals:
                if k not in base:
                    fails.append("same: %s printed on %s only" % (k, label))
    return not fails, fails


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", help="liggghts-membrane (default: build/app/liggghts-membrane)")
    ap.add_argument("--case", action="append", help="run only the case(s) of this name")
    ap.add_argument("--list", action="store_true", help="print the case count per class")
    ap.add_argument("-v", "--verbose", action="store_true", help="with --list: every case")
    ap.add_argument("--keep", help="also write each generated input script into this folder")
    ap.add_argument("-j", "--jobs", type=int, default=1,
                    help="cases run at the same time (runs mostly wait for MPI start-up)")
    ap.add_argument("files", nargs="*", help=".cases files (default: cases/*.cases)")
    a = ap.parse_args()
    files = a.files or sorted(os.path.join(HERE, "cases", f)
                              for f in os.listdir(os.path.join(HERE, "cases")) if f.endswith(".cases"))
    cases = [c for f in files for c in parse_file(f)]

    if a.list:
        per_class, per_file = OrderedDict(), OrderedDict()
        for c in cases:
            per_class[c.cls] = per_class.get(c.cls, 0) + 1
            per_file[os.path.basename(c.path)] = per_file.get(os.path.basename(c.path), 0) + 1
        for f, n in per_file.items():
            print("%-32s %4d" % (f, n))
            if a.verbose:
                for c in cases:
                    if os.path.basename(c.path) == f:
                        cfg = "shell" if c.shell else ", ".join(
                            "%d%s" % (n_, " grid " + " ".join(g) if g else "") for n_, g in c.configs())
                        print("    %-36s [%s] %s" % (c.name, cfg, "; ".join(c.notes)))
        print("-" * 37)
        for k in sorted(per_class):
            print("class %-26s %4d" % (k, per_class[k]))
        print("%-32s %4d" % ("total", len(cases)))
        return 0

    if a.case:
        cases = [c for c in cases if c.name in a.case]
        if not cases:
            print("no case named %s" % ", ".join(a.case))
            return 1
    exe = os.path.abspath(a.exe or os.path.join(HERE, "..", "..", "build", "app", "liggghts-membrane"))
    if not os.access(exe, os.X_OK):
        print("no executable %s (build first: tools/build.sh)" % exe)
        return 1
    nfail = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        futures = [pool.submit(run_case, c, exe, a.keep) for c in cases]
        for c, fut in zip(cases, futures):   # reported in file order
            ok, fails = fut.result()
            print("%s %s %s" % ("ok  " if ok else "FAIL", c.cls, c.name), flush=True)
            for f in fails:
                print("       " + f)
            nfail += 0 if ok else 1
    print("%d cases: %d passed, %d failed" % (len(cases), len(cases) - nfail, nfail))
    return 1 if nfail else 0


if __name__ == "__main__":
    sys.exit(main())
