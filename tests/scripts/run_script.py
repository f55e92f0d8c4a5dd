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

The script prints values as:  print "RESULT name ${var}"
"""
import argparse
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


def run(exe, np_, script, workdir, timeout, testdir=None):
    """Run one script; 'testdir' (the original script's folder) is passed as ${testdir}."""
    testdir = testdir or os.path.dirname(os.path.abspath(script))
    cmd = [exe, "-in", script, "-log", "none", "-echo", "none", "-var", "testdir", testdir]
    if np_ > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
    try:
        p = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, errors="replace",
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return 124, "TIMEOUT after %d s" % timeout
    return p.returncode, p.stdout + p.stderr


def results(output):
    return {k: float(v) for k, v in RESULT.findall(output)}


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
    ap.add_argument("--timeout", type=int, default=600)
    ap.add_argument("script")
    a = ap.parse_args()
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
        elif a.compare:
            ranks = [int(x) for d in dirs if d.startswith("ranks ") for x in d.split()[1:]]
            rtol, atol = 1e-12, 0.0
            for d in dirs:
                if d.startswith("tolerance "):
                    rtol, atol = (float(x) for x in d.split()[1:3])
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
