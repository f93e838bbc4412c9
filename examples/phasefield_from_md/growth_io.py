"""Shared by plot.py and plot_paper.py: the radius of a tracked domain and a bridge fit."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import read_csv, read_toml  # noqa: E402  (the shared readers)


def md_radius(tracks_csv, track=1):
    """Times (ps) and the equivalent radius of the atomic volume (Å) of one track of the tracks.csv
    of analyze atoms --track --timestep-size (columns time_ps, atomic_volume_A3)."""
    tracks = read_csv(tracks_csv)
    rows = tracks[tracks["track"] == track]
    return rows["time_ps"], np.cbrt(3 * rows["atomic_volume_A3"] / (4 * math.pi))


def fitted(material):
    """[provenance.domain_growth.fit] of a material file and its c0, D (Å/ps, Å²/ps) with errors."""
    fit = read_toml(material)["provenance"]["domain_growth"]["fit"]
    return fit, fit["c0_m_s"] / 100, fit["c0_stderr_m_s"] / 100, fit["D_m2_s"] * 1e8, fit["D_stderr_m2_s"] * 1e8
