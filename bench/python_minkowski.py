#!/usr/bin/python3
"""shockfield.analysis.minkowski from Python against minkowski_bench's C++ call on the same field.

The field and thresholds are minkowski_bench's 2D case: analysis::gaussian_random_field(4096,
4096, 1, ℓ = 8, seed 1) and 256 thresholds evenly spaced over [-3, 3]. Prints the median of
--repeats calls (the boundary included: argument checks, the view of the array, the result arrays).

    OMP_NUM_THREADS=2 PYTHONPATH=build/release/python /usr/bin/python3 bench/python_minkowski.py
    OMP_NUM_THREADS=2 build/release/bench/minkowski_bench --repeats 5 --stride2d 256 --stride3d 64
"""

import argparse
import os
import statistics
import time

import numpy as np

import shockfield

parser = argparse.ArgumentParser()
parser.add_argument("--repeats", type=int, default=5)
args = parser.parse_args()
field = shockfield.analysis.gaussian_random_field((4096, 4096), 8.0, seed=1)
thresholds = [-3.0 + 6.0 * k / 255 for k in range(256)]  # minkowski_bench's formula, bit for bit
times = []
for _ in range(args.repeats):
    t0 = time.perf_counter()
    shockfield.analysis.minkowski(field, thresholds=thresholds)
    times.append(time.perf_counter() - t0)
print(f"python 2D 4096^2, 256 thresholds  threads {os.environ.get('OMP_NUM_THREADS', 'all')}  "
      f"median {statistics.median(times):.3f} s (min {min(times):.3f}, {args.repeats} runs)")
