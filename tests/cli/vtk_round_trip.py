#!/usr/bin/python3
"""VTK files of shockfield runs read by VTK itself (python3-vtk9) and by shockfield.vtk_arrays.

    vtk_round_trip.py REFERENCE_FILE [FILE ...]

Every file is read by VTK's XML reader and by vtk_arrays: the two must give the same arrays,
bit for bit, and every array but the vertex connectivity must carry a units attribute. Each
further FILE (the same frame written in another encoding or precision) must equal REFERENCE_FILE
(ascii, Float64): exactly for Float64, as the nearest float for Float32. The categorical arrays
(material, body, grain, type) must be Int32 in every file. Where an image has VTK's blanking array
vtkGhostType, its points must be hidden (HIDDENPOINT, as VTK's IsPointVisible reports) exactly
where the real arrays that have NaN (mass_density is 0 there) are NaN. Exit 77 when
python3-vtk9 is absent (the test then says it skipped).
"""
import re
import sys

import numpy as np

sys.path.insert(0, sys.argv[0].rsplit("/tests/", 1)[0] + "/python")
from shockfield.vtk_arrays import read_vtk_arrays  # noqa: E402

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("skip: python3-vtk9 is not installed (apt-get install python3-vtk9)")
    sys.exit(77)


CATEGORICAL = {"material", "body", "grain", "type"}


def vtk_arrays(path):
    reader = vtk.vtkXMLImageDataReader() if path.endswith(".vti") else vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode():
        sys.exit(f"FAIL: VTK cannot read {path}")
    data = reader.GetOutput()
    out = {}
    for attrs in (data.GetPointData(), data.GetCellData()):
        for k in range(attrs.GetNumberOfArrays()):
            out[attrs.GetArrayName(k)] = vtk_to_numpy(attrs.GetArray(k))
    if path.endswith(".vtp"):
        out["points"] = vtk_to_numpy(data.GetPoints().GetData())
    elif "vtkGhostType" in out:
        visible = np.array([data.IsPointVisible(i) for i in range(data.GetNumberOfPoints())], dtype=bool)
        for name, values in out.items():
            nan = np.isnan(values) if values.dtype.kind == "f" and values.ndim == 1 else None
            if nan is not None and nan.any() and not np.array_equal(~visible, nan):
                sys.exit(f"FAIL: {path}: VTK hides other points than the NaN ones of {name}")
    return out


def check(path):
    ours, theirs = read_vtk_arrays(path), vtk_arrays(path)
    for name, values in theirs.items():
        if name not in ours or not np.array_equal(ours[name], values, equal_nan=True):
            sys.exit(f"FAIL: {path}: array {name} read by vtk_arrays differs from VTK's")
    text = open(path, "rb").read().split(b"<AppendedData")[0].decode()
    for tag in re.findall(r"<DataArray[^>]*>", text):
        name = re.search(r'Name="([^"]+)"', tag).group(1)
        if name not in ("connectivity", "offsets", "vtkGhostType") and "units=" not in tag:
            sys.exit(f"FAIL: {path}: DataArray {name} has no units")
    for name in CATEGORICAL.intersection(ours):  # labels are integers in every encoding
        if ours[name].dtype != np.int32:
            sys.exit(f"FAIL: {path}: categorical array {name} is {ours[name].dtype}, expected int32")
    return ours


reference = check(sys.argv[1])
for path in sys.argv[2:]:
    arrays = check(path)
    for name, ref in reference.items():
        got = arrays[name]
        want = ref.astype(got.dtype).astype(ref.dtype) if got.dtype == np.float32 else ref
        if got.shape != ref.shape or not np.array_equal(got.astype(ref.dtype), want, equal_nan=True):
            sys.exit(f"FAIL: {path}: array {name} differs from {sys.argv[1]}")
print(f"ok: {len(sys.argv) - 1} files read alike by VTK and vtk_arrays, equal across encodings")
