"""The VTK files of a run, read with VTK's own readers (python3-vtk9): XML polydata
(.vtp: LIGGGHTS' dumps, the frames of fix membrane2d and fix membrane3d,
doc/paraview.md) and legacy polydata (.vtk); their points and point arrays as numpy
arrays. The one reader of these files in the project (no regular expressions)."""
import locale
import os

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

_READERS = {".vtp": vtk.vtkXMLPolyDataReader, ".vtk": vtk.vtkPolyDataReader}


def read_polydata(path):
    """The vtkPolyData of a .vtp or .vtk file. OSError: no such file; ValueError: not a
    polydata file of that kind (VTK's reader found no Points in it)."""
    ext = os.path.splitext(path)[1].lower()
    if ext not in _READERS:
        raise ValueError(f"{path}: not a VTK polydata file (.vtp or .vtk)")
    if not os.path.isfile(path):
        raise FileNotFoundError(f"no file {path}")
    reader = _READERS[ext]()
    reader.SetFileName(path)
    previous = vtk.vtkObject.GetGlobalWarningDisplay()
    vtk.vtkObject.GlobalWarningDisplayOff()      # a broken file: our message, not VTK's
    # VTK 9.1's legacy reader leaves the process locale at "C" (then Python's text I/O,
    # subprocess output included, turns ASCII): the locale is put back after reading
    kept = locale.setlocale(locale.LC_ALL)
    try:
        reader.Update()
    finally:
        vtk.vtkObject.SetGlobalWarningDisplay(previous)
        locale.setlocale(locale.LC_ALL, kept)
    poly = reader.GetOutput()
    if poly is None or poly.GetPoints() is None:   # a valid file, even of 0 points, has Points
        raise ValueError(f"{path}: VTK's reader found no polydata in it (cut, empty or "
                         "another kind of file?)")
    return poly


def points(poly):
    """(n, 3) float array of the points (empty (0, 3) without any)."""
    if poly.GetPoints() is None:
        return np.zeros((0, 3))
    return vtk_to_numpy(poly.GetPoints().GetData()).astype(float).reshape(-1, 3)


def point_array(poly, name):
    """The point data array `name` as a numpy array; KeyError when the file has none."""
    array = poly.GetPointData().GetArray(name)
    if array is None:
        raise KeyError(f"no point data array '{name}'")
    return vtk_to_numpy(array)


def has_point_array(poly, name):
    return poly.GetPointData().GetArray(name) is not None


def polydata_points(path, corners_only=False):
    """The (n, 3) points of a polydata file; with corners_only, those whose point data
    'escaped' is 0 (fix membrane3d's frames: the membrane's corners without the escaped
    spheres; every point when the file has no such array)."""
    poly = read_polydata(path)
    pts = points(poly)
    if corners_only and has_point_array(poly, "escaped"):
        pts = pts[np.asarray(point_array(poly, "escaped"), dtype=float) == 0]
    return pts


def polygon_point_ids(poly):
    """The sorted ids of the points that the polygons (Polys) use."""
    polys = poly.GetPolys()
    if polys is None or polys.GetNumberOfCells() == 0:
        return np.zeros(0, dtype=int)
    return np.unique(vtk_to_numpy(polys.GetConnectivityArray()).astype(int))
