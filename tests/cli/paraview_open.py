"""ParaView itself (pvbatch) on every method's VTK output: opens a .pvd series as a user would
(OpenDataFile), and for its last frame checks what ParaView shows against the files.

    pvbatch paraview_open.py OUT_DIR LABEL:SERIES.pvd:ARRAY [LABEL:SERIES.pvd:ARRAY ...]

Per series: the times ParaView offers are the .pvd's (to 1e-9 relative); every array of the
frame's file arrives with its centring (PointData as point data, CellData as cell data), its
component count and its units attribute in the file; no value ParaView shows is NaN (a NaN is
allowed only at a point the file blanks with vtkGhostType, which ParaView then hides); the
picture of ARRAY (OUT_DIR/LABEL.png) is not blank. ParaView reads no units: VTK's XML readers
ignore attributes they do not know, so a unit is seen in the file, not in ParaView's panels.
Prints one line per series; exits 1 with each surprise named.
"""
import os
import pathlib
import sys
import xml.etree.ElementTree as ET

from paraview import servermanager
from paraview.simple import (ColorBy, Delete, GetActiveViewOrCreate, Hide, OpenDataFile, Render, ResetCamera,
                             SaveScreenshot, Show)
from paraview.vtk.numpy_interface import dataset_adapter as dsa
import numpy as np

HIDDEN_POINT = 2  # vtkDataSetAttributes::HIDDENPOINT


def pvd_frames(pvd):
    """(time, file) of each DataSet of a .pvd, in order."""
    root = ET.parse(pvd).getroot()
    return [(float(d.get("timestep")), pvd.parent / d.get("file")) for d in root.iter("DataSet")]


def file_arrays(path):
    """{(centring, name): (components, units)} declared by a VTK XML file (a .pvti/.pvtp: its
    PPointData/PCellData), the blanking array left out."""
    text = path.read_bytes().split(b"<AppendedData")[0].decode("utf-8", "replace")
    root = ET.fromstring(text + ("" if "</VTKFile>" in text else "</VTKFile>"))
    arrays = {}
    for centring, tags in (("point", ("PointData", "PPointData")), ("cell", ("CellData", "PCellData"))):
        for tag in tags:
            for block in root.iter(tag):
                for a in [*block.iter("DataArray"), *block.iter("PDataArray")]:
                    if a.get("Name") != "vtkGhostType":
                        arrays[(centring, a.get("Name"))] = (int(a.get("NumberOfComponents", "1")), a.get("units"))
    return arrays


def shown_arrays(data):
    """{(centring, name): values} of the dataset ParaView fetched."""
    wrapped = dsa.WrapDataObject(data)
    arrays = {}
    for centring, attributes in (("point", wrapped.PointData), ("cell", wrapped.CellData)):
        for name in attributes.keys():
            arrays[(centring, name)] = np.asarray(attributes[name])
    return arrays


def check(label, pvd, colour, out):
    problems = []
    frames = pvd_frames(pvd)
    reader = OpenDataFile(str(pvd))
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if frames[1:] else [frames[0][0]]
    expected = [t for t, _ in frames]
    if len(times) != len(expected) or any(abs(a - b) > 1e-9 * max(1.0, abs(b)) for a, b in zip(times, expected)):
        problems.append(f"times {times} differ from the .pvd's {expected}")
    last_time, last_file = frames[-1]
    reader.UpdatePipeline(last_time)
    data = servermanager.Fetch(reader)
    declared, shown = file_arrays(last_file), shown_arrays(data)
    for (centring, name), (components, units) in sorted(declared.items()):
        if units is None:
            problems.append(f"{last_file.name}: array {name} has no units attribute")
        if (centring, name) not in shown:
            other = [c for c, n in shown if n == name]
            problems.append(f"array {name} is {centring} data in the file but "
                            f"{other[0] + ' data' if other else 'missing'} in ParaView")
            continue
        values = shown[(centring, name)]
        got = int(np.prod(values.shape[1:]))  # dataset_adapter shows 9 components as 3 x 3
        if got != components:
            problems.append(f"array {name}: {got} components in ParaView, {components} in the file")
    ghosts = shown.get(("point", "vtkGhostType"))
    visible = None if ghosts is None else (np.asarray(ghosts) & HIDDEN_POINT) == 0
    for (centring, name), values in sorted(shown.items()):
        if name == "vtkGhostType" or not np.issubdtype(values.dtype, np.floating):
            continue
        nan = ~np.isfinite(values).reshape(len(values), -1).all(axis=1)
        if centring == "point" and visible is not None:
            nan &= visible
        if nan.any():
            problems.append(f"array {name}: {int(nan.sum())} of {len(nan)} values ParaView shows are NaN")
    hidden = 0 if visible is None else int((~visible).sum())
    view = GetActiveViewOrCreate("RenderView")
    display = Show(reader, view)
    default = str(display.Representation).strip("'")
    pictures = {}
    # ParaView 5.11 shows a 2D image with the Slice representation, which ignores vtkGhostType (the
    # blanked MPM void nodes are painted in the NaN colour, yellow) and draws nothing of cell data
    # on a 2D image (every DBM frame, 1 or more rows); Surface honours both (docs/conventions.md).
    # Particles are drawn as points of 5 pixels (1 pixel by default, too small to check).
    chosen = "Points" if data.IsA("vtkPolyData") else "Surface"
    for representation in ([default] if default != chosen else []) + [chosen]:
        display.SetRepresentationType(representation)
        display.PointSize = 5 if representation == "Points" else 2
        png = out / f"{label}{'' if representation == chosen else '_default_' + representation.lower()}.png"
        picture(display, view, colour, "CELLS" if ("cell", colour) in shown else "POINTS", png, data.GetBounds())
        pictures[representation] = picture_pixels(png)
    covered, yellow = pictures[chosen]
    if covered < 0.003:
        problems.append(f"{label}.png: {covered:.2%} of the picture of {colour} is drawn (blank)")
    if yellow:
        problems.append(f"{label}.png: {yellow} pixels in the NaN colour")
    Hide(reader, view)
    Delete(reader)
    note = "" if default == chosen else (f"; ParaView's default {default}: {pictures[default][0]:.1%} drawn, "
                                         f"{pictures[default][1]} NaN-yellow pixels")
    kinds = sorted({c for c, _ in declared})
    print(f"{label}: {pvd.name}, {len(times)} times (last {last_time:g}), {type(data).__name__}, "
          f"{len(declared)} arrays ({', '.join(kinds)} data) as in {last_file.name}, "
          f"{hidden} hidden points; {chosen} picture of {colour}: {covered:.1%} drawn, {yellow} NaN-yellow pixels{note}")
    return [f"{label}: {p}" for p in problems]


def picture(display, view, colour, centring, png, bounds):
    """A picture of `colour`, looking along the axis of the data's smallest extent (a granular
    chain along z is a dot seen along z, ParaView's default)."""
    ColorBy(display, (centring, colour))
    display.RescaleTransferFunctionToDataRange(True, False)
    extent = [bounds[2 * d + 1] - bounds[2 * d] for d in range(3)]
    along = min(range(3), key=lambda d: extent[d])
    centre = [(bounds[2 * d] + bounds[2 * d + 1]) / 2 for d in range(3)]
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + (1.0 if d == along else 0.0) for d, c in enumerate(centre)]
    view.CameraViewUp = [1.0 if d == (along + 2) % 3 else 0.0 for d in range(3)]
    ResetCamera(view)
    Render(view)
    SaveScreenshot(str(png), view, ImageResolution=[480, 360])


def picture_pixels(png):
    """(share of the pixels drawn, count of pixels in the NaN colour, pure yellow) of a picture;
    drawn: not the background colour (the top-left pixel), the orientation axes' corner left out."""
    from paraview.vtk.vtkIOImage import vtkPNGReader
    from paraview.vtk.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(str(png))
    reader.Update()
    image = reader.GetOutput()
    nx, ny, _ = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].reshape(ny, nx, 3).astype(int)
    rgb = rgb[::-1]  # rows from the top
    drawn = (rgb != rgb[0, 0]).any(axis=2)
    drawn[-ny // 4:, : nx // 5] = False  # the orientation axes, bottom left
    yellow = (rgb[:, :, 0] > 250) & (rgb[:, :, 1] > 250) & (rgb[:, :, 2] < 5)
    return drawn.mean(), int(yellow.sum())


def main():
    out = pathlib.Path(sys.argv[1])
    problems = []
    for spec in sys.argv[2:]:
        label, pvd, colour = spec.split(":")
        problems += check(label, pathlib.Path(pvd), colour, out)
    for p in problems:
        print("SURPRISE:", p)
    sys.stdout.flush()
    # Leave without ParaView's teardown: under Xvfb, Debian's ParaView 5.11 ends every session with
    # "X Error of failed request: GLXBadContext" (X_GLXMakeCurrent) while destroying its render
    # window, which turns exit code 0 into 1 after all the checks above have run.
    os._exit(1 if problems else 0)


if __name__ == "__main__":
    main()
