#!/usr/bin/python3
"""Print the progress of a running shear test from its output table.

    progress.py OUT TARGET_STRAIN PID LABEL

Polls OUT (columns named in its last '#' header line, 'ea' = axial strain)
every few seconds while process PID runs, and prints the strain reached, the
elapsed time and an estimate of the time left.
"""
import os
import sys
import time


def last_strain(path):
    try:
        with open(path) as f:
            lines = f.read().splitlines()
    except OSError:
        return None
    header = [l for l in lines if l.startswith("#")]
    data = [l for l in lines if l and not l.startswith("#")]
    if not header or not data:
        return None
    cols = header[-1].lstrip("#").split()
    try:
        return float(data[-1].split()[cols.index("ea")])
    except (ValueError, IndexError):
        return None


def running(pid):
    try:
        os.kill(pid, 0)
        return True
    except OSError:
        return False


def main():
    out, target, pid, label = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    start = time.time()
    while running(pid):
        time.sleep(5)
        ea = last_strain(out)
        elapsed = time.time() - start
        if ea is None or ea <= 0:
            print("  %s: starting (%.0f s)" % (label, elapsed), flush=True)
            continue
        left = elapsed * (target - ea) / ea
        print("  %s: axial strain %.2f %% of %.1f %%, %.0f s elapsed, about %.0f s left"
              % (label, 100 * ea, 100 * target, elapsed, max(left, 0)), flush=True)


if __name__ == "__main__":
    main()
