"""The VTK XML polydata files of a run (.vtp: LIGGGHTS' dumps and fix membrane2d's
frames, doc/paraview.md) read with VTK's own reader, and their points and point arrays
as numpy arrays."""
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read_polydata(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def points(poly):
    return vtk_to_numpy(poly.GetPoints().GetData()).astype(float)


def point_array(poly, name):
    return vtk_to_numpy(poly.GetPointData().GetArray(name))
