#!/usr/bin/env python3
"""Run a LIGGGHTS input script through liggghts-membrane and check what it prints.

The script states its own expectations in comment lines starting with '#@':

  #@ expect NAME VALUE TOL         RESULT NAME must equal VALUE within TOL (absolute)
  #@ expect NAME VALUE rel TOL      ... within TOL relative
  #@ expect NAME > VALUE           ... (also <) a bound
  #@ output TEXT                   the output must contain TEXT (e.g. a warning)
  #@ no-output TEXT                the output must not contain TEXT
  #@ output-count N TEXT           the output must contain TEXT exactly N times
  #@ error SUBSTRING ::: COMMAND    replace the line '#@ case' by COMMAND: the run must
                                   fail with SUBSTRING in its output (one line per case;
                                   a literal \n in COMMAND starts a new input line)
  #@ ranks 1 2 4                   --compare: all RESULT values equal on these rank counts
  #@ tolerance RTOL ATOL           ... within this relative/absolute tolerance

  #@ restart                       --restart: the script is restart-checked (see below)
  #@ begin-definitions             --restart: the lines up to '#@ end-definitions' are
  #@ end-definitions                 repeated after read_restart (see below)
  #@ split                         --restart: where the split run is cut
  #@ restart-pre COMMAND           --restart: COMMAND goes between 'clear' and 'read_restart'
  #@ restart-tolerance RTOL ATOL   --restart: RESULTs equal within this tolerance (default 0 0)

The script prints values as:  print "RESULT name ${var}"

--restart runs the script twice. The straight run runs it as it is ('#@ split' is
a comment to LIGGGHTS); the split run runs a copy in which every '#@ split' line is
replaced by

    write_restart split<k>.restart
    clear
    <the '#@ restart-pre' commands; default: atom_modify map array,
     communicate single vel yes>
    read_restart  split<k>.restart
    <the lines of every definitions block above this split and below the
     script's last 'clear' before it>

Definitions are what a restart file does not carry: newton, neighbor, the
property/global contact coefficients, pair_style/pair_coeff, timestep (read_restart
leaves the units' default, 1e-8 s in si), every fix and compute, thermo settings.
Variables survive 'clear' and need no repeating.
LIGGGHTS 3.8 stores neither the atom map nor ghost velocities in restart files,
and 'atom_modify map' is refused once read_restart has made the box: hence the
'#@ restart-pre' default (give '#@ restart-pre' lines to replace it). A script may
hold several cases separated by 'clear', each with its blocks and splits. The blocks
and splits must be in the script itself, not in a file it includes (the block may
hold 'include' lines). Put the split between two runs ('run A' / '#@ split' /
'run B'): LIGGGHTS re-sorts atoms and neighbour lists at the start of every run,
so only then does the straight run follow the same arithmetic as the split one.
'time' is not in restart files: RESULTs must not depend on it.

Every RESULT the straight run prints must be printed by the split run as often,
with the same values (exactly, or within '#@ restart-tolerance': |a - b| <=
RTOL max(|a|, |b|) + ATOL; a NaN never matches); the test fails when no RESULT
was compared. The '#@ expect' / '#@ output' lines are checked on both runs.

--restart --write-np W --np N (W != N): the restart files are written on W ranks
and read on N. The split copy first runs on W ranks (the writer); then the split
run on N ranks reads the writer's split<k>.restart at each split (it still writes
its own, unread). Its RESULTs are compared with the straight run on N ranks within
'#@ tolerance' (the cross-rank tolerance of --compare, default 1e-12 relative):
after the split they come from a state computed on W ranks. The expectations are
checked on all three runs.
tests/README.md lists the restart-checked scripts. Example:

    #@ restart
    include         ${testdir}/setup.inc          # box and atoms
    #@ begin-definitions
    include         ${testdir}/contacts.inc       # pair style, walls, timestep
    fix             g all stability/guard every 10
    #@ end-definitions
    run             100
    #@ split
    run             100
    print           "RESULT x1 $(x[1])"
"""
import argparse
import contextlib
import concurrent.futures
import os
import re
import subprocess
import sys
import tempfile

RESULT = re.compile(r"^RESULT\s+(\S+)\s+(\S+)\s*$", re.M)


def directives(path):
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith("#@"):
                out.append(line[2:].strip())
    return out


@contextlib.contextmanager
def mpi_env():
    """The environment for mpirun with an Open MPI session directory of its own:
    concurrent mpiruns sharing one under /tmp race when one removes it while another
    creates its own ("ORTE_ERROR_LOG: Error in file .../orte/util/session_dir.c
    at line 107", seen under ctest -j2)."""
    with tempfile.TemporaryDirectory(prefix="ompi-") as tmp:
        yield dict(os.environ, OMPI_MCA_orte_tmpdir_base=tmp)


def run(exe, np_, script, workdir, timeout, testdir=None):
    """Run one script; 'testdir' (the original script's folder) is passed as ${testdir}."""
    testdir = testdir or os.path.dirname(os.path.abspath(script))
    cmd = [exe, "-in", script, "-log", "none", "-echo", "none", "-var", "testdir", testdir]
    if np_ > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
    try:
        with mpi_env() as env:
            p = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, errors="replace",
                               timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return 124, "TIMEOUT after %d s" % timeout
    return p.returncode, p.stdout + p.stderr


def results(output):
    return {k: float(v) for k, v in RESULT.findall(output)}


def result_lists(output):
    """Every printed value of each RESULT name, in the order printed."""
    out = {}
    for k, v in RESULT.findall(output):
        out.setdefault(k, []).append(float(v))
    return out


DEFAULT_RESTART_PRE = ["atom_modify map array", "communicate single vel yes"]


def split_script(text, dirs, read_dir=None):
    """The split-run copy of a '#@ restart' script (see the docstring), or raise ValueError.
    With read_dir, read_restart reads the split<k>.restart that a run in read_dir wrote
    (--write-np); write_restart still writes the run's own."""
    pre = [d[len("restart-pre"):].strip() for d in dirs if d.startswith("restart-pre ")]
    pre = pre or DEFAULT_RESTART_PRE
    out, definitions, block, nsplit = [], [], None, 0
    for line in text.splitlines(keepends=True):
        d = line[2:].strip() if line.startswith("#@") else None
        if d == "begin-definitions":
            if block is not None:
                raise ValueError("'#@ begin-definitions' inside a definitions block")
            block = []
        elif d == "end-definitions":
            if block is None:
                raise ValueError("'#@ end-definitions' without '#@ begin-definitions'")
            definitions += block
            block = None
        elif d == "split":
            if block is not None:
                raise ValueError("'#@ split' inside a definitions block")
            nsplit += 1
            name = "split%d.restart" % nsplit
            out.append("# --- '#@ split' %d (run_script.py --restart)\n" % nsplit)
            out.append("write_restart   %s\nclear\n" % name)
            out += [c + "\n" for c in pre]
            out.append("read_restart    %s\n" % (os.path.join(read_dir, name) if read_dir else name))
            out += definitions
            out.append("# --- end of '#@ split' %d\n" % nsplit)
            continue
        elif block is not None:
            block.append(line if line.endswith("\n") else line + "\n")
        elif d is None and line.split()[:1] == ["clear"]:
            definitions = []  # a new case: the definitions above are gone with it
        out.append(line)
    if block is not None:
        raise ValueError("'#@ begin-definitions' without '#@ end-definitions'")
    if nsplit == 0:
        raise ValueError("no '#@ split' line")
    if not definitions:
        raise ValueError("no '#@ begin-definitions' ... '#@ end-definitions' block above the split")
    return "".join(out)


def compare_restart(straight_out, split_out, rtol, atol):
    """(number of values compared, failures): every RESULT of the straight run's output,
    each time printed, against the split run's."""
    straight, split = result_lists(straight_out), result_lists(split_out)
    compared, failures = 0, []
    for name, values in straight.items():
        got = split.get(name, [])
        if len(got) != len(values):
            failures.append("RESULT %s printed %d times by the straight run, %d times by the split run"
                            % (name, len(values), len(got)))
            continue
        for i, (a, b) in enumerate(zip(values, got)):
            compared += 1
            tag = name if len(values) == 1 else "%s[%d]" % (name, i + 1)
            if not abs(a - b) <= rtol * max(abs(a), abs(b)) + atol:
                failures.append("RESULT %s = %r straight, %r split (difference %g)" % (tag, a, b, b - a))
    return compared, failures


def compare_tolerance(dirs):
    """'#@ tolerance RTOL ATOL': the cross-rank tolerance (default 1e-12 relative)."""
    rtol, atol = 1e-12, 0.0
    for d in dirs:
        if d.startswith("tolerance "):
            rtol, atol = (float(x) for x in d.split()[1:3])
    return rtol, atol


def restart_tolerance(dirs, cross_ranks=False):
    """The tolerance of a restart check: '#@ restart-tolerance' (default exact), or for
    a restart read on another rank count than it was written on, '#@ tolerance'."""
    if cross_ranks:
        return compare_tolerance(dirs)
    rtol, atol = 0.0, 0.0
    for d in dirs:
        if d.startswith("restart-tolerance "):
            rtol, atol = (float(x) for x in d.split()[1:3])
    return rtol, atol


def restart_check(exe, np_, script, dirs, work, timeout, write_np=None):
    """--restart: the straight and the split run print the same RESULTs; with write_np
    (!= np_) the split run reads restart files written on write_np ranks. Returns failures."""
    if "restart" not in dirs:
        return ["%s has no '#@ restart' line" % script]
    cross = write_np is not None and write_np != np_
    rtol, atol = restart_tolerance(dirs, cross)
    with open(script) as f:
        text = f.read()
    writer = os.path.join(work, "write")
    try:
        split_text = split_script(text, dirs)
        read_text = split_script(text, dirs, writer) if cross else split_text
    except ValueError as e:
        return ["%s: %s" % (script, e)]
    testdir = os.path.dirname(script)
    runs = [("straight", np_, None), ("split", np_, read_text)]
    if cross:
        runs.insert(0, ("write", write_np, split_text))
    outputs, failures = {}, []
    for label, n, copy in runs:
        folder = os.path.join(work, label)
        os.makedirs(folder)
        path = script
        if copy is not None:
            path = os.path.join(folder, "split.in")
            with open(path, "w") as f:
                f.write(copy)
        rc, out = run(exe, n, path, folder, timeout, testdir)
        if rc != 0:
            failures.append("%s run on np=%d failed (rc=%d):\n%s" % (label, n, rc, out[-3000:]))
            if label == "write":
                return failures
            continue
        outputs[label] = out
        failures += check_expectations(dirs, out, "%s np=%d" % (label, n))
    if "straight" not in outputs or "split" not in outputs:
        return failures
    tag = "np=%d" % np_ if not cross else "np=%d read from np=%d" % (np_, write_np)
    compared, bad = compare_restart(outputs["straight"], outputs["split"], rtol, atol)
    for line in bad:
        print("FAIL restart %s %s" % (tag, line))
    failures += ["%s: %s" % (tag, line) for line in bad]
    if compared == 0:
        failures.append("no RESULT compared between the straight and the split run")
    print("compared %d RESULT values of the straight and the split run on %s (rtol %g, atol %g)"
          % (compared, tag, rtol, atol))
    return failures


def check_expectations(dirs, output, label):
    vals = results(output)
    failures = []
    for d in dirs:
        for key, must in (("output ", True), ("no-output ", False)):
            if d.startswith(key):
                text = d[len(key):].strip()
                ok = (text in output) == must
                print("%s %s %s '%s'" % ("ok  " if ok else "FAIL", label,
                                         "output has" if must else "output lacks", text))
                if not ok:
                    failures.append("%s: output %s '%s'" % (label, "lacks" if must else "has", text))
        if d.startswith("output-count "):
            _, n, text = d.split(None, 2)
            seen = output.count(text)
            ok = seen == int(n)
            print("%s %s output has '%s' %d times (want %s)" % ("ok  " if ok else "FAIL", label, text, seen, n))
            if not ok:
                failures.append("%s: output has '%s' %d times, want %s" % (label, text, seen, n))
        w = d.split()
        if not w or w[0] != "expect":
            continue
        name = w[1]
        if name not in vals:
            failures.append("%s: RESULT %s not printed" % (label, name))
            continue
        v = vals[name]
        if w[2] in (">", "<"):
            bound = float(w[3])
            ok = v > bound if w[2] == ">" else v < bound
            desc = "%s %s" % (w[2], bound)
        else:
            want = float(w[2])
            if w[3] == "rel":
                tol = float(w[4]) * abs(want)
            else:
                tol = float(w[3])
            ok = abs(v - want) <= tol
            desc = "%r +- %g" % (want, tol)
        status = "ok  " if ok else "FAIL"
        print("%s %s %s = %r (want %s)" % (status, label, name, v, desc))
        if not ok:
            failures.append("%s: %s = %r, want %s" % (label, name, v, desc))
    return failures


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--compare", action="store_true", help="compare RESULTs across '#@ ranks'")
    ap.add_argument("--errors", action="store_true", help="run the '#@ error' cases")
    ap.add_argument("--restart", action="store_true",
                    help="'#@ restart': a run split at '#@ split' by write_restart / read_restart "
                         "prints the RESULTs of the straight run")
    ap.add_argument("--write-np", type=int, default=None,
                    help="with --restart: write the restart files on this many ranks, read "
                         "them on --np (RESULTs within '#@ tolerance')")
    ap.add_argument("--timeout", type=int, default=600)
    ap.add_argument("script")
    a = ap.parse_args()
    if a.write_np is not None and (not a.restart or a.write_np < 1):
        ap.error("--write-np needs --restart and a rank count >= 1")
    a.exe = os.path.abspath(a.exe)

    script = os.path.abspath(a.script)
    dirs = directives(script)
    failures = []
    with tempfile.TemporaryDirectory() as work:
        if a.errors:
            with open(script) as f:
                text = f.read()
            cases = [d[len("error"):].split(":::") for d in dirs if d.startswith("error ")]
            if not cases:
                failures.append("no '#@ error' cases in %s" % script)
            def run_case(i, command):
                # each case in its own folder: cases run two at a time (a run mostly
                # waits for MPI start-up)
                folder = os.path.join(work, "case%d" % i)
                os.makedirs(folder)
                case = os.path.join(folder, "case.in")
                with open(case, "w") as f:
                    f.write(text.replace("#@ case\n", command.replace("\\n", "\n") + "\n"))
                return run(a.exe, a.np, case, folder, a.timeout, os.path.dirname(script))

            with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
                outcomes = list(pool.map(lambda ic: run_case(ic[0], ic[1][1].strip()), enumerate(cases)))
            for (expect, command), (rc, out) in zip(cases, outcomes):
                expect, command = expect.strip(), command.strip()
                ok = rc != 0 and expect in out and "TIMEOUT" not in out
                print("%s error case '%s' -> '%s'" % ("ok  " if ok else "FAIL", command, expect))
                if not ok:
                    tail = "\n".join(out.strip().splitlines()[-5:])
                    failures.append("case '%s': rc=%d, wanted '%s' in output; got:\n%s"
                                    % (command, rc, expect, tail))
        elif a.restart:
            failures += restart_check(a.exe, a.np, script, dirs, work, a.timeout, a.write_np)
        elif a.compare:
            ranks = [int(x) for d in dirs if d.startswith("ranks ") for x in d.split()[1:]]
            rtol, atol = compare_tolerance(dirs)
            runs = {}
            for n in ranks:
                rc, out = run(a.exe, n, script, work, a.timeout)
                if rc != 0:
                    failures.append("np=%d failed (rc=%d):\n%s" % (n, rc, out[-2000:]))
                    continue
                runs[n] = results(out)
            if len(runs) >= 2:
                base_n = ranks[0]
                base = runs.get(base_n, {})
                if not base:
                    failures.append("no RESULT lines on np=%d" % base_n)
                for n, vals in runs.items():
                    for k, v in base.items():
                        w = vals.get(k)
                        if w is None:
                            failures.append("np=%d: RESULT %s missing" % (n, k))
                        elif abs(w - v) > rtol * max(abs(v), abs(w)) + atol:
                            failures.append("np=%d vs np=%d: %s = %r vs %r" % (n, base_n, k, w, v))
                print("compared %d values on ranks %s (rtol %g, atol %g)"
                      % (len(base), ranks, rtol, atol))
        else:
            rc, out = run(a.exe, a.np, script, work, a.timeout)
            if rc != 0:
                failures.append("run failed (rc=%d):\n%s" % (rc, out[-3000:]))
            else:
                failures += check_expectations(dirs, out, "np=%d" % a.np)
                if not any(d.startswith(("expect ", "output ")) for d in dirs):
                    failures.append("script has no '#@ expect' lines")
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
