"""Cells of the .vtp surfaces and .vtu Delaunay meshes shockfield writes (zlib binary), read by VTK's
own XML readers (python3-vtk9), for the Python tests that compare them with the bindings."""

import numpy as np


def read_cells(path, vertices_per_cell):
    """(points, cells) of a .vtp with polygons or a .vtu: Float64 points, int32 cell vertices."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLPolyDataReader() if str(path).endswith(".vtp") else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput()
    cells = data.GetPolys() if str(path).endswith(".vtp") else data.GetCells()
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    return points, vtk_to_numpy(cells.GetConnectivityArray()).astype(np.int32).reshape(-1, vertices_per_cell)
