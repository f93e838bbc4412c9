#!/usr/bin/python3
"""A run's VTK frames written as parallel pieces ([output] vtk_pieces) read by VTK's own parallel
readers give what the single files of the same run give.

    vtk_pieces.py SINGLE_RUN PIECES_RUN PIECES PVD [PVD ...]

For each .pvd (relative to the run folders): the same times; each frame of PIECES_RUN is a .pvti
or .pvtp where SINGLE_RUN has a .vti or .vtp of the same name. vtkXMLPImageDataReader /
vtkXMLPPolyDataReader read it; vtkXMLImageDataReader / vtkXMLPolyDataReader read the single
file; the two datasets must have the same extent, origin and spacing (images), the same number of
points and cells, and the same arrays (point, cell, positions): names, VTK types, components and
values bit for bit (both are the same floats cut into pieces; pieces do not overlap for particles,
and the shared boundary points of image pieces hold the same values). Units: each summary
<PDataArray> carries the units="..." of the single file's <DataArray> of that name, and so does
each piece file's. Pieces: a .pvti has min(PIECES, cells along its longest axis) pieces, a .pvtp
PIECES, and every piece file VTK's serial reader opens without error (an empty one included).
shockfield's Python reader (shockfield.vtk_arrays, numpy only) reads each .pvtp as the .vtp, and
shockfield.Run's particle frames of the two runs are equal. Exit 77 when python3-vtk9 is absent
(the test then says it skipped).
"""
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, sys.argv[0].rsplit("/tests/", 1)[0] + "/python")
from shockfield.run import Run  # noqa: E402
from shockfield.vtk_arrays import read_vtk_arrays  # noqa: E402

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("skip: python3-vtk9 is not installed (apt-get install python3-vtk9)")
    sys.exit(77)

READERS = {".vti": vtk.vtkXMLImageDataReader, ".vtp": vtk.vtkXMLPolyDataReader,
           ".pvti": vtk.vtkXMLPImageDataReader, ".pvtp": vtk.vtkXMLPPolyDataReader}


def fail(message):
    sys.exit(f"FAIL: {message}")


def read(path):
    reader = READERS[os.path.splitext(path)[1]]()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode():
        fail(f"VTK cannot read {path}")
    return reader.GetOutput()


def arrays(data):
    """name -> (VTK type name, components, values) of every point and cell array and the points."""
    out = {}
    for where, attrs in (("point", data.GetPointData()), ("cell", data.GetCellData())):
        for k in range(attrs.GetNumberOfArrays()):
            a = attrs.GetArray(k)
            out[(where, a.GetName())] = (a.GetDataTypeAsString(), a.GetNumberOfComponents(), vtk_to_numpy(a))
    if isinstance(data, vtk.vtkPolyData):
        p = data.GetPoints().GetData()
        out[("points", "points")] = (p.GetDataTypeAsString(), 3, vtk_to_numpy(p))
    return out


def units(path, tag):
    """name -> units attribute of the <tag> elements of an XML file, but the vertex cells'."""
    head = open(path, "rb").read().split(b"<AppendedData")[0].decode()
    if "</VTKFile>" not in head:
        head += "</VTKFile>"
    return {e.get("Name"): e.get("units") for e in ET.fromstring(head).iter(tag)
            if e.get("Name") not in ("connectivity", "offsets")}


def compare(single_file, pieces_file, pieces):
    one, many = read(single_file), read(pieces_file)
    if one.GetNumberOfPoints() != many.GetNumberOfPoints() or one.GetNumberOfCells() != many.GetNumberOfCells():
        fail(f"{pieces_file}: {many.GetNumberOfPoints()} points, {many.GetNumberOfCells()} cells; "
             f"{single_file}: {one.GetNumberOfPoints()}, {one.GetNumberOfCells()}")
    if isinstance(one, vtk.vtkImageData):
        for what in ("GetExtent", "GetOrigin", "GetSpacing"):
            if getattr(one, what)() != getattr(many, what)():
                fail(f"{pieces_file}: {what} {getattr(many, what)()} against {getattr(one, what)()}")
    a, b = arrays(one), arrays(many)
    if a.keys() != b.keys():
        fail(f"{pieces_file}: arrays {sorted(b)} against {sorted(a)}")
    for key, (vtk_type, components, values) in a.items():
        other_type, other_components, other = b[key]
        if (vtk_type, components) != (other_type, other_components):
            fail(f"{pieces_file}: {key} is {other_type}×{other_components}, the single file's {vtk_type}×{components}")
        if not np.array_equal(values, other, equal_nan=True):
            fail(f"{pieces_file}: {key} values differ from {single_file}")
    if pieces_file.endswith(".pvtp"):
        ours, reference = read_vtk_arrays(pieces_file), read_vtk_arrays(single_file)
        if ours.keys() != reference.keys() or not all(np.array_equal(ours[k], reference[k]) for k in ours):
            fail(f"{pieces_file}: shockfield.vtk_arrays reads other arrays than from {single_file}")
    # Units: the summary's declarations and every piece's arrays carry the single file's.
    reference = units(single_file, "DataArray")
    declared = units(pieces_file, "PDataArray")
    if declared != reference:
        fail(f"{pieces_file}: declared units {declared} against {reference}")
    sources = [e.get("Source") for e in ET.parse(pieces_file).getroot().iter("Piece")]
    if isinstance(one, vtk.vtkImageData):
        expected = max(1, min(pieces, max(one.GetDimensions()) - 1))
    else:
        expected = pieces
    if len(sources) != expected:
        fail(f"{pieces_file}: {len(sources)} pieces, expected {expected}")
    empty = 0
    for source in sources:
        path = os.path.join(os.path.dirname(pieces_file), source)
        piece = read(path)
        empty += piece.GetNumberOfPoints() == 0
        piece_units = units(path, "DataArray")
        if piece_units != reference:
            fail(f"{path}: units {piece_units} against {reference}")
    return len(sources), empty


def pvd_entries(path):
    return [(float(e.get("timestep")), e.get("file")) for e in ET.parse(path).getroot().iter("DataSet")]


def main():
    single_run, pieces_run, pieces = sys.argv[1], sys.argv[2], int(sys.argv[3])
    for pvd in sys.argv[4:]:
        one, many = pvd_entries(os.path.join(single_run, pvd)), pvd_entries(os.path.join(pieces_run, pvd))
        if [t for t, _ in one] != [t for t, _ in many] or not one:
            fail(f"{pvd}: times {[t for t, _ in many]} against {[t for t, _ in one]}")
        counts, empty = set(), 0
        for (_, single), (_, parallel) in zip(one, many):
            if re.sub(r"\.(vti|vtp)$", r".p\1", single) != parallel:
                fail(f"{pvd}: {parallel} where the single run has {single}")
            folder = os.path.dirname(pvd)
            n, e = compare(os.path.join(single_run, folder, single), os.path.join(pieces_run, folder, parallel), pieces)
            counts.add(n)
            empty += e
        print(f"ok: {pvd}: {len(one)} frames in {sorted(counts)} pieces ({empty} empty) read by VTK as the single files")
        if one[0][1].endswith(".vtp"):  # shockfield.Run's particle frames (its first .pvd of particles)
            a, b = list(Run(single_run).frames(kind="particles")), list(Run(pieces_run).frames(kind="particles"))
            if [f.time for f in a] != [f.time for f in b] or any(
                    not np.array_equal(x.data[name], y.data[name]) for x, y in zip(a, b) for name in x.data.dtype.names):
                fail(f"{pieces_run}: shockfield.Run's particle frames differ from the single files'")
            print(f"ok: {pvd}: shockfield.Run reads the .pvtp frames as the .vtp")


main()
