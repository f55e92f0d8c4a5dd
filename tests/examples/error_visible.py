#!/usr/bin/python3
"""A LIGGGHTS error reaches redirected output (app/main.cpp: line-buffered stdout,
MPI_Abort flushing stdio first).

A script prints a line and then fails in Error::one (read_data of a missing file: proc 0
alone stops, with MPI_Abort).  Before the fix, with stdout redirected to a file, nothing
of the "ERROR on proc 0" line (and on 1 rank nothing at all) reached the file, and the log
file was cut off.  Checked on NP ranks with stdout to a file and to a pipe: the output has
the ERROR line and the printed line, the log file has the printed line, the exit status
is not 0.

    error_visible.py EXE NP
"""
import os
import subprocess
import sys
import tempfile

from example_run import Checks, mpi_env

SCRIPT = """units si
print "BEFORE the error: a line the log must keep"
read_data %s
print "AFTER the error: never printed"
"""


def main():
    exe, np_ = os.path.abspath(sys.argv[1]), sys.argv[2]
    check = Checks()
    failures = check.failures

    with tempfile.TemporaryDirectory() as work:
        inp = os.path.join(work, "in.fail")
        with open(inp, "w") as f:
            f.write(SCRIPT % os.path.join(work, "missing.data"))
        for how in ("file", "pipe"):
            log = os.path.join(work, "log.%s" % how)
            cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe, "-in", inp, "-log", log]
            if how == "file":
                out_path = os.path.join(work, "screen.txt")
                with open(out_path, "w") as f, mpi_env() as env:
                    p = subprocess.run(cmd, stdout=f, stderr=subprocess.DEVNULL, timeout=120,
                                       env=env)
                # errors="replace": with a 1-in-5 chance per error LIGGGHTS 3.8 appends a
                # "Tip of the day" through a dangling std::string (error_special.h,
                # generate_message), i.e. bytes of freed memory that need not be UTF-8
                with open(out_path, errors="replace") as f:
                    out = f.read()
            else:
                with mpi_env() as env:
                    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                       timeout=120, env=env)
                out = p.stdout.decode(errors="replace")
            # a missing log fails the log check below (with what the run printed), not the test
            logtext = open(log, errors="replace").read() if os.path.exists(log) else ""
            if not logtext:
                print("no log file %s; the run printed:\n%s" % (log, out[-2000:]))
            check(p.returncode != 0, "%s, %s ranks: exit status %d (not 0)" % (how, np_, p.returncode))
            check("ERROR on proc 0: Cannot open file" in out,
                  "%s, %s ranks: the ERROR line reached the redirected output" % (how, np_))
            check("BEFORE the error" in out and "AFTER the error" not in out,
                  "%s, %s ranks: the output before the error is there, nothing after it" % (how, np_))
            check("BEFORE the error" in logtext, "%s, %s ranks: the log file is not cut off" % (how, np_))
    if failures:
        sys.exit("FAIL: %d check(s)" % len(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
