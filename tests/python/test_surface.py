"""shockfield.analysis.surface against the command line and the sphere (ctest python.test_surface).

- 1500 points on the unit sphere (a Fibonacci lattice, radii jittered by ±0.1% so that no five
  points are on a common sphere): each method — rolling ball on the Delaunay division (r = 0.3),
  pivoting ball (r = 0.3), packing-sculpting (depth 0.3) — gives a closed, edge-manifold surface of
  χ = 2 with area and volume within 1% of 4π and 4π/3, the tolerance of the C++ tests
  (tests/unit/geometry/test_rolling_ball.cpp: the inscribed polyhedron's deficit is O(h²), here
  h ≈ 0.09 gives about 0.3%).
- The same points as a CSV file through `shockfield analyze geometry --surface-method ...`:
  surface.vtp's points (Float64, so exact; read with VTK's own reader) and connectivity equal the
  Python result exactly; summary.txt's area, volume (12 digits), triangle count, Euler
  characteristic and manifold flag equal it.
- The GIL is released: while another thread computes the surface of 6000 points (0.13-0.3 s),
  this thread's Python loop never pauses for half the call (measured: longest pause 0.016 s in a
  0.234 s call; sorted() of 10^6 floats, a C call that holds the GIL, pauses it 0.39 s of 0.42 s).
- Bad arrays raise TypeError / ValueError, bad options ValueError, a ball that falls through the
  points InputError with the command line's message.
"""

import os
import pathlib
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import shockfield
from shockfield import analysis
from vtk_files import read_cells

SF = os.environ["SHOCKFIELD_BIN"]


def fibonacci_sphere(n=1500, jitter=1e-3, seed=7):
    k = np.arange(n) + 0.5
    z = 1.0 - 2.0 * k / n
    phi = np.pi * (1.0 + 5.0 ** 0.5) * k
    rho = np.sqrt(1.0 - z * z)
    r = 1.0 + jitter * (np.random.default_rng(seed).random(n) - 0.5) * 2.0
    return np.ascontiguousarray(np.column_stack((rho * np.cos(phi), rho * np.sin(phi), z)) * r[:, None])


METHODS = (("delaunay", ["--ball-radius", "0.3"], {"radius": 0.3}),
           ("pivot", ["--ball-radius", "0.3"], {"radius": 0.3}),
           ("packing", ["--sculpt-depth", "0.3"], {"depth": 0.3}))


class Surface(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_sphere_and_command_line(self):
        points = fibonacci_sphere()
        csv = self.dir / "sphere.csv"
        csv.write_text("x,y,z\n" + "".join(",".join(repr(v) for v in p) + "\n" for p in points))
        for method, options, length in METHODS:
            with self.subTest(method=method):
                s = analysis.surface(points, method=method, **length)
                self.assertTrue(s["manifold"])
                self.assertEqual(s["euler_characteristic"], 2)
                self.assertAlmostEqual(s["area"] / (4 * np.pi), 1.0, delta=0.01)
                self.assertAlmostEqual(s["volume"] / (4 * np.pi / 3), 1.0, delta=0.01)
                np.testing.assert_array_equal(s["points"], points[s["point_index"]])
                out = self.dir / method
                process = subprocess.run([SF, "analyze", "geometry", str(csv), "--no-mesh", "--surface-method", method,
                                          *options, "--length-units", "m", "-o", str(out)], capture_output=True, text=True)
                self.assertEqual(process.returncode, 0, process.stderr)
                vtp_points, vtp_triangles = read_cells(out / "surface.vtp", 3)
                np.testing.assert_array_equal(s["points"], vtp_points)
                np.testing.assert_array_equal(s["triangles"], vtp_triangles)
                summary = dict(line.split() for line in (out / "summary.txt").read_text().splitlines())
                self.assertEqual(f"{s['area']:.12g}", summary["surface_area_m2"])  # --length-units m
                self.assertEqual(f"{s['volume']:.12g}", summary["surface_volume_m3"])
                self.assertEqual(len(s["triangles"]), int(summary["surface_triangles"]))
                self.assertEqual(s["euler_characteristic"], int(summary["surface_euler_characteristic"]))
                self.assertEqual("yes" if s["manifold"] else "no", summary["surface_manifold"])

    def test_the_gil_is_released(self):
        # Held for the C++ part, the GIL would stop this thread's loop for the whole call: its
        # longest pause would be about the call's length. Released, the pauses are the OS's
        # time slices (the machine is shared), far shorter.
        points, call = fibonacci_sphere(6000), {}

        def work():
            start = time.perf_counter()
            analysis.surface(points, 0.3)
            call["seconds"] = time.perf_counter() - start

        worker = threading.Thread(target=work)
        last, longest = time.perf_counter(), 0.0
        worker.start()
        while worker.is_alive():
            now = time.perf_counter()
            longest, last = max(longest, now - last), now
        worker.join()
        self.assertLess(longest, 0.5 * call["seconds"], f"longest pause {longest:.3f} s in a {call['seconds']:.3f} s call")

    def test_bad_input_raises(self):
        points = fibonacci_sphere(200)
        with self.assertRaisesRegex(TypeError, "points: expected dtype float64"):
            analysis.surface(points.astype(np.float32), 0.3)
        with self.assertRaisesRegex(ValueError, r"points: expected an \(n, 3\) array"):
            analysis.surface(np.ascontiguousarray(points[:, :2]), 0.3)
        with self.assertRaisesRegex(ValueError, "not C-contiguous"):
            analysis.surface(np.asfortranarray(points), 0.3)
        with self.assertRaisesRegex(ValueError, "method: expected"):
            analysis.surface(points, 0.3, method="alpha")
        with self.assertRaisesRegex(ValueError, "takes depth"):
            analysis.surface(points, 0.3, method="packing")
        with self.assertRaisesRegex(ValueError, "takes radius"):
            analysis.surface(points, depth=0.3)
        # A ball far smaller than the spacing falls through: the command line's InputError.
        with self.assertRaisesRegex(shockfield.InputError, "radius"):
            analysis.surface(points, 1e-3)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
