#!/usr/bin/env python3
"""Render one frame of a biaxial shear's ParaView files to a PNG with VTK, off-screen:
the disks coloured by their displacement since the start of shear, the walls in grey,
and (membrane case) the membrane polylines with the chain forces as arrows.

    render_paraview.py FOLDER OUT.png [--step N] [--size W H]

FOLDER is a shear's folder of ParaView files (-var vtkstrain, doc/paraview.md); the frame
is the last step of its particle files unless --step is given. VTK needs a display to
render, even off-screen: on a machine without one, run it under xvfb-run (Debian xvfb)."""
import argparse
import os
import sys

import vtk

from liggghts_membrane.vtk_files import read_polydata as read
from liggghts_membrane.pvd import frames

CIRCLE_SIDES = 24
ARROW_LENGTH = 0.06   # the largest chain force drawn as this fraction of the sample height


def actor(source_output, colour=None, width=None):
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(source_output)
    mapper.ScalarVisibilityOff()
    a = vtk.vtkActor()
    a.SetMapper(mapper)
    if colour:
        a.GetProperty().SetColor(*colour)
    if width:
        a.GetProperty().SetLineWidth(width)
    return a


def disks(particles):
    """Each particle as a filled circle of its radius, coloured by |displacement|."""
    circle = vtk.vtkRegularPolygonSource()
    circle.SetNumberOfSides(CIRCLE_SIDES)
    circle.SetRadius(1.0)
    glyph = vtk.vtkGlyph3D()
    glyph.SetInputData(particles)
    glyph.SetSourceConnection(circle.GetOutputPort())
    glyph.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "radius")
    glyph.SetScaleModeToScaleByScalar()
    glyph.SetScaleFactor(1.0)
    glyph.Update()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(glyph.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.ColorByArrayComponent("c_dsp[1-4]", 2)
    d = particles.GetPointData().GetArray("c_dsp[1-4]")
    mapper.SetScalarRange(0.0, max(d.GetRange(2)[1], 1e-30))
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.Build()
    mapper.SetLookupTable(lut)
    a = vtk.vtkActor()
    a.SetMapper(mapper)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("displacement [m]")
    bar.SetNumberOfLabels(4)
    bar.SetLabelFormat("%.1e")
    bar.SetWidth(0.12)
    bar.SetPosition(0.86, 0.1)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    return a, bar


def force_arrows(membrane, height):
    """The chain forces of the membrane file as arrows at the chain disks."""
    chain = vtk.vtkThresholdPoints()   # chain disks have tag >= 0, polyline points -1
    chain.SetInputData(membrane)
    chain.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "tag")
    chain.ThresholdByUpper(0.0)
    chain.Update()
    out = chain.GetOutput()
    out.GetPointData().SetActiveVectors("force")
    fmax = max(out.GetPointData().GetArray("force").GetMaxNorm(), 1e-30)
    arrow = vtk.vtkArrowSource()
    glyph = vtk.vtkGlyph3D()
    glyph.SetInputData(out)
    glyph.SetSourceConnection(arrow.GetOutputPort())
    glyph.SetVectorModeToUseVector()
    glyph.SetScaleModeToScaleByVector()
    glyph.SetScaleFactor(ARROW_LENGTH * height / fmax)
    glyph.Update()
    return actor(glyph.GetOutput(), colour=(0.8, 0.0, 0.0))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("folder")
    ap.add_argument("png")
    ap.add_argument("--step", type=int)
    ap.add_argument("--size", type=int, nargs=2, default=(900, 1200), metavar=("W", "H"))
    a = ap.parse_args(argv[1:])
    found = frames(os.listdir(a.folder))
    if not found["particles"]:
        sys.exit("render_paraview.py: no particles_<step>.vtp in %s" % a.folder)
    step = max(found["particles"]) if a.step is None else a.step
    if step not in found["particles"]:
        sys.exit("render_paraview.py: no particle file of step %d in %s (steps: %s)"
                 % (step, a.folder, " ".join(map(str, sorted(found["particles"])))))

    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    particles = read(os.path.join(a.folder, found["particles"][step]))
    disk_actor, bar = disks(particles)
    ren.AddActor(disk_actor)
    ren.AddActor2D(bar)
    ymin, ymax = particles.GetBounds()[2:4]
    if step in found["walls"]:
        walls = actor(read(os.path.join(a.folder, found["walls"][step])), colour=(0.5, 0.5, 0.5))
        walls.GetProperty().SetRepresentationToWireframe()   # the platens are seen edge-on
        walls.GetProperty().SetLineWidth(4)
        ren.AddActor(walls)
    if step in found["membrane"]:
        membrane = read(os.path.join(a.folder, found["membrane"][step]))
        line = vtk.vtkPolyData()
        line.SetPoints(membrane.GetPoints())
        line.SetLines(membrane.GetLines())
        ren.AddActor(actor(line, colour=(0.0, 0.0, 0.0), width=3))
        ren.AddActor(force_arrows(membrane, ymax - ymin))
    title = vtk.vtkTextActor()
    title.SetInput("step %d" % step)
    title.GetTextProperty().SetColor(0, 0, 0)
    title.GetTextProperty().SetFontSize(20)
    ren.AddActor2D(title)

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(ren)
    window.SetSize(*a.size)
    cam = ren.GetActiveCamera()
    cam.ParallelProjectionOn()
    ren.ResetCamera(particles.GetBounds())
    cam.SetParallelScale(0.55 * (ymax - ymin))
    window.Render()
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(a.png)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
