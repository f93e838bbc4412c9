#!/usr/bin/python3
"""scikit-image side of bench/minkowski_bench.cpp: the same Minkowski work done the usual way, one
threshold at a time (area = mask mean, euler_number, and in 2D perimeter).

    /usr/bin/python3 bench/minkowski_skimage.py FIELD.f64 NX NY NZ T_LO T_HI N_THRESHOLDS STRIDE

FIELD.f64 holds NX*NY*NZ float64 values, x fastest. Thresholds are N_THRESHOLDS values evenly
spaced over [T_LO, T_HI]; every STRIDE-th one is timed (STRIDE = 1: all of them). Prints one line
`seconds_per_threshold thresholds_timed` (the median over the timed thresholds is not used: the
mean per threshold times N_THRESHOLDS is the full loop's time).
"""
import sys
import time

import numpy as np
from skimage.measure import euler_number, perimeter


def main():
    path, nx, ny, nz = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
    lo, hi, count, stride = float(sys.argv[5]), float(sys.argv[6]), int(sys.argv[7]), int(sys.argv[8])
    field = np.fromfile(path, dtype=np.float64)
    field = field.reshape((ny, nx)) if nz == 1 else field.reshape((nz, ny, nx))
    thresholds = np.linspace(lo, hi, count)[::stride]
    start = time.perf_counter()
    for t in thresholds:
        mask = field >= t
        area = mask.mean()
        if field.ndim == 2:
            chi = euler_number(mask, connectivity=2)
            length = perimeter(mask, neighbourhood=8)
        else:
            chi = euler_number(mask, connectivity=3)
        del area, chi
    elapsed = time.perf_counter() - start
    print(f"{elapsed / len(thresholds):.6f} {len(thresholds)}")


if __name__ == "__main__":
    main()
