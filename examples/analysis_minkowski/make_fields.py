#!/usr/bin/python3
"""Writes two synthetic 'shocked porous material' temperature processes as CSV grids
(FOLDER/ref_t*.csv and FOLDER/hot_t*.csv, 128 x 128 cells, 6 times): a compaction front moves up
through a random hot-spot pattern; the 'hot' process is the same pattern 40 K hotter with a
faster front. Void cells (pores) are written as `void`. Needs numpy (/usr/bin/python3).
    make_fields.py FOLDER"""
import pathlib
import sys

import numpy as np

def smooth_noise(n, length, rng):
    k = np.fft.fftfreq(n) * 2 * np.pi
    k2 = k[:, None] ** 2 + k[None, :] ** 2
    f = np.fft.ifft2(np.fft.fft2(rng.standard_normal((n, n))) * np.exp(-0.25 * k2 * length**2)).real
    return f / f.std()


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(7)
    n = 128
    noise = smooth_noise(n, 4.0, rng)
    pores = smooth_noise(n, 2.0, rng) > 2.0
    y = np.arange(n)[:, None] * np.ones((1, n))
    for i, t in enumerate(np.linspace(0.0, 1.0, 6)):
        for name, speed, extra in (("ref", 100.0, 0.0), ("hot", 120.0, 40.0)):
            front = 1.0 / (1.0 + np.exp((y - speed * t) / 3.0))
            temp = 300.0 + front * (80.0 + extra + 30.0 * noise)
            with open(out / f"{name}_t{i}.csv", "w") as f:
                f.write("# synthetic temperature, spacing in micrometres\n# spacing = 0.5\n"
                        "# units = K\n# length_units = um\n")
                for row, hole in zip(temp, pores):
                    f.write(",".join("void" if h else f"{v:.3f}" for v, h in zip(row, hole)) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(pathlib.Path(sys.argv[1]))
