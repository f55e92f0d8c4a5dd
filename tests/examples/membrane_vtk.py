#!/usr/bin/python3
"""fix membrane2d's vtk keyword, read back with VTK's own reader (python3-vtk9).

The hexagonal block of tests/scripts/membrane_block_setup.inc (20 chain disks a
side) under 100 kPa for 100 steps, frames every 50 steps, on NP ranks. Checked
against what the fix itself outputs (f_mem, printed at 15 digits at each frame):
per frame one .vtp with, per side, a polyline of chain + 1 points (contact points
and the two platen ends) as one Line cell and the chain disks as Vertex cells;
the disks' forces summing to the fix's total force of the side and to
p t (Dy, -Dx) on the left, p t (-Dy, Dx) on the right, D the polyline's chord;
the .pvd lists every frame, in order, with its time step. LIGGGHTS' own VTK
dumps of the same run (doc/paraview.md) read back too: the particles with the
membrane flag f_mem (as many 1s and 2s as chain disks) and compute fabric's
per-disk contact counts (summing to 2 N_c), the contact network (N_c lines, as
c_fab[10]). The same run cut at
step 50 by write_restart and continued in a second process (read_restart) leaves
the same .pvd and the same last frame, byte for byte.

    membrane_vtk.py EXE NP
"""
import os
import subprocess
import sys
import tempfile

from example_run import ROOT, Checks, mpi_env
from liggghts_membrane.pvd import read_collection
from liggghts_membrane.vtk_files import point_array, points, read_polydata

PRESSURE, THICKNESS = 1e5, 1.0
BLOCK = """variable a equal 0.002
variable n equal 10
variable rows equal 20
variable testdir string %(dir)s
"""  # the hexagonal block's size
SCRIPT = BLOCK + """include ${testdir}/membrane_block_setup.inc
fix mem all membrane2d pressure %(p)g ylo ${ylo} yhi ${yhi} frictionless 2 vtk 50 post/membrane
compute fab all fabric stability yes
compute cpgl all pair/gran/local pos id force
dump particles all custom/vtk 50 post/particles_*.vtp id type x y z radius f_mem c_fab[1] c_fab[2]
dump contacts all local/gran/vtk 50 post/contacts_*.vtp cpgl
variable nc equal c_fab[10]
variable s equal step
variable n4 equal f_mem[4]
variable n5 equal f_mem[5]
variable f7 equal f_mem[7]
variable f8 equal f_mem[8]
variable f9 equal f_mem[9]
variable f10 equal f_mem[10]
fix out all print 50 "FRAME $s ${n4} ${n5} ${f7} ${f8} ${f9} ${f10} ${nc}" screen yes
run 100
"""
FIRST_HALF = BLOCK + """include ${testdir}/membrane_block_setup.inc
fix mem all membrane2d pressure %(p)g ylo ${ylo} yhi ${yhi} frictionless 2 vtk 50 post/membrane
run 50
write_restart half.restart
"""
SECOND_HALF = BLOCK + """include ${testdir}/membrane_block_atoms.inc
clear
atom_modify map array
read_restart half.restart
communicate single vel yes
include ${testdir}/membrane_block_contacts.inc
fix mem all membrane2d pressure %(p)g ylo ${ylo} yhi ${yhi} frictionless 2 vtk 50 post/membrane
run 50
"""


def run(exe, np_, work, script):
    """`script` (with %(dir)s and %(p)g) run in `work` on np_ ranks: its output."""
    os.makedirs(os.path.join(work, "post"), exist_ok=True)
    with open(os.path.join(work, "in.vtk"), "w") as f:
        f.write(script % {"dir": os.path.join(ROOT, "tests", "scripts"), "p": PRESSURE})
    cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe, "-in", "in.vtk",
           "-log", "none"]
    with mpi_env() as env:
        p = subprocess.run(cmd, cwd=work, capture_output=True, text=True, errors="replace",
                           timeout=300, env=env)
    if p.returncode != 0:
        sys.exit("FAIL: the run exited %d\n%s" % (p.returncode, (p.stdout + p.stderr)[-3000:]))
    return p


def main():
    exe, np_ = os.path.abspath(sys.argv[1]), sys.argv[2]
    check = Checks()
    with tempfile.TemporaryDirectory() as work:
        p = run(exe, np_, work, SCRIPT)
        frames = {}
        for line in p.stdout.splitlines():
            w = line.split()
            if len(w) == 9 and w[0] == "FRAME":
                frames[int(float(w[1]))] = [float(x) for x in w[2:]]
        check(sorted(frames) == [50, 100], "the fix printed frames 50 and 100: %s" % sorted(frames))

        listed = [(int(d.timestep), os.path.basename(d.path))
                  for d in read_collection(os.path.join(work, "post", "membrane.pvd"))]
        check(listed == [(0, "membrane_0.vtp"), (50, "membrane_50.vtp"), (100, "membrane_100.vtp")],
              "the .pvd lists the frames 0, 50, 100 in order: %s" % listed)
        for step, (n_left, n_right, fxl, fyl, fxr, fyr, n_contacts) in sorted(frames.items()):
            disks = read_polydata(os.path.join(work, "post", "particles_%d.vtp" % step))
            flag = point_array(disks, "f_mem")
            ends = point_array(disks, "c_fab[1]")
            lam = point_array(disks, "c_fab[2]")
            check(disks.GetNumberOfPoints() == 200 and (flag == 1).sum() == n_left and
                  (flag == 2).sum() == n_right,
                  "step %d: particles file: 200 disks, %d flagged 1 and %d flagged 2"
                  % (step, (flag == 1).sum(), (flag == 2).sum()))
            check(ends.sum() == 2 * n_contacts and ((lam >= 0) & (lam <= 1)).all(),
                  "step %d: per-disk contacts sum to 2 x %d, lambda in [0, 1]" % (step, n_contacts))
            network = read_polydata(os.path.join(work, "post", "contacts_%d.vtp" % step))
            check(network.GetNumberOfLines() == n_contacts,
                  "step %d: contacts file: %d lines = c_fab[10]" % (step, network.GetNumberOfLines()))
            data = read_polydata(os.path.join(work, "post", "membrane_%d.vtp" % step))
            side = point_array(data, "side")
            tag = point_array(data, "tag")
            force = point_array(data, "force")
            pts = points(data)
            counts = {k: int(((side == k) & (tag >= 0)).sum()) for k in (1, 2)}
            check(counts == {1: n_left, 2: n_right} and n_left == 20,
                  "step %d: chain disks per side %s = f_mem[4], f_mem[5] (%d, %d)" % (step, counts, n_left, n_right))
            check(data.GetNumberOfVerts() == n_left + n_right and data.GetNumberOfLines() == 2,
                  "step %d: %d vertex cells, %d line cells" % (step, data.GetNumberOfVerts(), data.GetNumberOfLines()))
            for k, (fx, fy) in ((1, (fxl, fyl)), (2, (fxr, fyr))):
                disks = (side == k) & (tag >= 0)
                line = pts[(side == k) & (tag < 0)]
                total = force[disks].sum(axis=0)
                dx, dy = line[-1, 0] - line[0, 0], line[-1, 1] - line[0, 1]
                chord = (dy, -dx) if k == 1 else (-dy, dx)
                scale = PRESSURE * THICKNESS * max(abs(dx), abs(dy))
                check(len(line) == (n_left if k == 1 else n_right) + 1,
                      "step %d side %d: %d polyline points = chain + 1" % (step, k, len(line)))
                check(abs(total[0] - fx) <= 1e-9 * scale and abs(total[1] - fy) <= 1e-9 * scale,
                      "step %d side %d: the disks' forces sum to the fix's total (%.9g, %.9g)" % (step, k, fx, fy))
                check(abs(total[0] - PRESSURE * THICKNESS * chord[0]) <= 1e-9 * scale and
                      abs(total[1] - PRESSURE * THICKNESS * chord[1]) <= 1e-9 * scale,
                      "step %d side %d: ... and to p t times the rotated chord" % (step, k))
        # the same run cut by a restart
        split = os.path.join(work, "split")
        run(exe, np_, split, FIRST_HALF)
        run(exe, np_, split, SECOND_HALF)
        def text(folder, name):
            with open(os.path.join(folder, "post", name)) as f:
                return f.read()
        check(text(split, "membrane.pvd") == text(work, "membrane.pvd"),
              "cut by a restart: the same .pvd as straight through")
        check(text(split, "membrane_100.vtp") == text(work, "membrane_100.vtp"),
              "cut by a restart: the same last frame as straight through")
    if check.failures:
        sys.exit("FAIL: %d check(s)" % len(check.failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
