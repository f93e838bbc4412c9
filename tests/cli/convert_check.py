#!/usr/bin/python3
"""Checks what `shockfield convert` wrote against the checkpoint it read (tests/cli/convert.sh).

    convert_check.py CHECKPOINT CONVERTED.vtp|.vti

Reads the checkpoint with h5py and the VTK file with VTK itself (python3-vtk9):
- .vtp: one point per particle at the checkpoint's positions (for granular: depth + displacement
  below z = 0, along z), and every per-particle dataset as a point array with the same units and
  values;
- .vti of DBM: rho, velocity, T recomputed here from f independently of the C++ code, by Xu et
  al. (2015) eqs. 20-22: rho = sum f_k, rho u = sum f_k v_k, rho (b T + u^2) = sum f_k (v_k^2 +
  eta_k^2);
- .vti of the phase field: xi point for point.
Values are compared to float32 rounding (relative 2^-24 of the array's largest magnitude, the
default --vtk-precision) or exactly when the file is Float64. Exits 1 naming each mismatch.
"""
import sys

import h5py
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader

problems = []


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def same(name, expected, got, array=None):
    expected = numpy.asarray(expected, dtype=float).ravel()
    got = numpy.asarray(got, dtype=float).ravel()
    if expected.shape != got.shape:
        problems.append(f"{name}: {got.size} values, expected {expected.size}")
        return
    exact = array is not None and array.GetDataType() == 11  # VTK_DOUBLE
    scale = numpy.max(numpy.abs(expected)) if expected.size else 0.0
    tolerance = 0.0 if exact else 2.0**-24 * scale  # float32 rounding of the largest value
    error = numpy.max(numpy.abs(expected - got)) if expected.size else 0.0
    if error > tolerance:
        problems.append(f"{name}: largest difference {error:.3g} > {tolerance:.3g}")


def check_vtp(h5, path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    points = vtk_to_numpy(poly.GetPoints().GetData())
    method = text(h5.attrs["method"])
    if method == "granular":
        z = -(h5["depth"][()] + h5["displacement"][()])
        same("points", numpy.column_stack([0 * z, 0 * z, z]), points)
        n = z.size
    else:
        key = "domain_centre" if method == "phasefield.sharp_front" else "position"
        same("points", h5[key][()], points)
        n = h5[key].shape[0]
    data = poly.GetPointData()
    names = {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())}
    header = open(path, "rb").read().split(b"<AppendedData")[0].decode()
    for name, d in h5.items():
        if d.shape[:1] != (n,) or name in ("position", "domain_centre"):
            continue
        if name not in names:
            problems.append(f"{path}: no point array '{name}'")
            continue
        same(f"{path}: {name}", d[()], vtk_to_numpy(data.GetArray(name)), data.GetArray(name))
        if f'Name="{name}"' in header and f'units="{text(d.attrs["units"])}"' not in header.split(f'Name="{name}"')[1].split(">")[0]:
            problems.append(f"{path}: array '{name}' does not carry units=\"{text(d.attrs['units'])}\"")
    return n


def check_vti(h5, path):
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if text(h5.attrs["method"]) == "phasefield":
        array = image.GetPointData().GetArray("xi")
        same(f"{path}: xi", h5["xi"][()], vtk_to_numpy(array), array)
        return h5["xi"].size
    g, nx, ny, b = int(h5.attrs["ghosts"]), int(h5.attrs["nx"]), int(h5.attrs["ny"]), float(h5.attrs["b"])
    f = h5["f"][()][:, g:g + ny, g:g + nx]  # the interior cells
    vx, vy, eta = h5["velocity_x"][()], h5["velocity_y"][()], h5["eta"][()]
    rho = f.sum(axis=0)
    ux = numpy.tensordot(vx, f, 1) / rho
    uy = numpy.tensordot(vy, f, 1) / rho
    T = (numpy.tensordot(vx**2 + vy**2 + eta**2, f, 1) / rho - ux**2 - uy**2) / b
    cells = image.GetCellData()
    same(f"{path}: rho", rho, vtk_to_numpy(cells.GetArray("rho")), cells.GetArray("rho"))
    u = vtk_to_numpy(cells.GetArray("velocity"))
    same(f"{path}: velocity x", ux, u[:, 0], cells.GetArray("velocity"))
    same(f"{path}: velocity y", uy, u[:, 1], cells.GetArray("velocity"))
    same(f"{path}: T", T, vtk_to_numpy(cells.GetArray("T")), cells.GetArray("T"))
    return rho.size


def main():
    checkpoint, converted = sys.argv[1], sys.argv[2]
    with h5py.File(checkpoint, "r") as h5:
        n = check_vtp(h5, converted) if converted.endswith(".vtp") else check_vti(h5, converted)
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    print(f"ok: {converted}: {n} values match {checkpoint}")


if __name__ == "__main__":
    main()
