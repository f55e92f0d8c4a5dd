"""The ParaView files of a biaxial shear (examples/biaxial/paraview.inc, -var vtkstrain)
read back with VTK's own XML reader (python3-vtk9) through the run.pvd that
scripts/paraview_collection.py writes, and checked against the run: the particle count,
the displacement since the start of shear against the positions, the contact lines
against compute fabric's per-disk counts, the wall meshes against the OUT table's W and
H, the membrane frames against the particles' chain flag; and the picture of the last
frame (scripts/render_paraview.py, under xvfb-run) has the sample and its chain forces."""
import os
import subprocess
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

from example_run import EXAMPLE, ROOT
from liggghts_membrane.pvd import read_collection
from liggghts_membrane.vtk_files import point_array, points, read_polydata as read

TRIANGLES = {"wb": "bottom", "wt": "top", "wl": "left", "wr": "right"}  # wall -> meshes/<name>.stl


def stl_triangles(wall):
    with open(os.path.join(EXAMPLE, "meshes", TRIANGLES[wall] + ".stl")) as f:
        return f.read().count("facet normal")


def check_run(check, case, folder, table, natoms, walls):
    """Checks of one shear's folder; `table` is its OUT table ({column: values})."""
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "paraview_collection.py"), folder],
                   check=True)
    sets = read_collection(os.path.join(folder, "run.pvd"))
    steps = sorted({int(d.timestep) for d in sets})
    kinds = ["particles", "contacts", "walls"] + (["membrane"] if case == "membrane" else [])
    check(len(steps) >= 2 and len(sets) == len(steps) * len(kinds),
          "%s: run.pvd has %d steps of %s (%d data sets)" % (case, len(steps), "+".join(kinds), len(sets)))
    frame = {}
    for d in sets:
        frame[(int(d.timestep), d.name)] = read(d.path)

    first = None
    for step in steps:
        part = frame[(step, "particles")]
        ids = point_array(part, "id").astype(int)
        order = np.argsort(ids)
        x, disp = points(part)[order], point_array(part, "c_dsp[1-4]")[order]
        check(part.GetNumberOfPoints() == natoms and np.all(x[:, 2] == 0),
              "%s, step %d: %d particles in z = 0" % (case, step, part.GetNumberOfPoints()))
        check(np.allclose(np.hypot(disp[:, 0], disp[:, 1]), disp[:, 2], rtol=0, atol=1e-12),
              "%s, step %d: displacement magnitude = |(dx, dy)|" % (case, step))
        if first is None:
            first = (x, disp)
        else:   # both frames measure from the start of shear: their difference is the motion between them
            moved = np.abs((x[:, :2] - first[0][:, :2]) - (disp[:, :2] - first[1][:, :2])).max()
            check(moved < 1e-8 and np.abs(disp[:, :2] - first[1][:, :2]).max() > 1e-6,
                  "%s, step %d: displacement since the start of shear - that of step %d = the motion "
                  "between them (worst %.1e m, float32 positions)" % (case, step, steps[0], moved))
        contacts = frame[(step, "contacts")]
        counts = point_array(part, "c_fab[1]")
        check(contacts.GetNumberOfCells() == counts.sum() / 2 and contacts.GetNumberOfCells() > natoms,
              "%s, step %d: %d contact lines = half the disks' contact counts (c_fab[1])"
              % (case, step, contacts.GetNumberOfCells()))
        wall = frame[(step, "walls")]
        triangles = vtk_to_numpy(wall.GetPolys().GetConnectivityArray()).reshape(-1, 3)
        sizes = [stl_triangles(w) for w in walls]
        check(len(triangles) == sum(sizes), "%s, step %d: %d wall triangles, as in the meshes %s"
              % (case, step, len(triangles), " ".join(walls)))
        wp = points(wall)
        ys = [wp[triangles[sum(sizes[:k]):sum(sizes[:k + 1])].ravel(), 1] for k in range(2)]
        row = table["step"].index(step)
        height = ys[1].min() - ys[0].max()
        check(abs(height / table["H"][row] - 1) < 1e-6 and np.ptp(ys[0]) == 0 and np.ptp(ys[1]) == 0,
              "%s, step %d: platens %.7f m apart, H of the OUT table %.7f m" % (case, step, height, table["H"][row]))
        if case == "membrane":
            mem = frame[(step, "membrane")]
            side, tag = point_array(mem, "side"), point_array(mem, "tag")
            flag = point_array(part, "f_mem")
            chains = [set(tag[(side == s) & (tag >= 0)].astype(int)) for s in (1, 2)]
            check(all(chains[s - 1] == set(ids[flag == s]) and chains[s - 1] for s in (1, 2)),
                  "%s, step %d: membrane chains of %d and %d disks, the disks flagged 1 and 2 in the particles"
                  % (case, step, len(chains[0]), len(chains[1])))


def check_picture(check, case, folder, png):
    """The rendered last frame: its size, the sample covering a good part of it in colour,
    and (membrane) the chain forces' red arrows."""
    width, height = 300, 400
    p = subprocess.run(["xvfb-run", "-a", "/usr/bin/python3", os.path.join(ROOT, "scripts", "render_paraview.py"),
                        folder, png, "--size", str(width), str(height)],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
    check(p.returncode == 0 and os.path.exists(png), "%s: render_paraview.py wrote %s (%s)"
          % (case, os.path.basename(png), p.stdout.decode(errors="replace")[-300:].strip()))
    if p.returncode != 0:
        return
    reader = vtk.vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    coloured = np.mean(rgb.max(axis=1) - rgb.min(axis=1) > 60)
    red = np.mean((rgb[:, 0] > 150) & (rgb[:, 1] < 40) & (rgb[:, 2] < 40))
    check(image.GetDimensions()[:2] == (width, height) and coloured > 0.3,
          "%s: picture %dx%d, %.0f %% of it coloured (the disks)" % (case, width, height, 100 * coloured))
    if case == "membrane":
        check(red > 0.002, "%s: the chain forces drawn (%.1f %% dark red pixels)" % (case, 100 * red))
