"""Shared by plot.py and plot_paper.py: the radius of a tracked domain and a bridge fit."""
import csv
import math
import tomllib

import numpy as np


def md_radius(tracks_csv, track="1"):
    """Times (ps) and the equivalent radius of the atomic volume (Å) of one track of the tracks.csv
    of analyze atoms --track --timestep-size (columns time_ps, atomic_volume_A3)."""
    rows = [r for r in csv.DictReader(open(tracks_csv)) if r["track"] == track]
    t = np.array([float(r["time_ps"]) for r in rows])
    return t, np.cbrt(3 * np.array([float(r["atomic_volume_A3"]) for r in rows]) / (4 * math.pi))


def fitted(material):
    """[provenance.domain_growth.fit] of a material file and its c0, D (Å/ps, Å²/ps) with errors."""
    fit = tomllib.load(open(material, "rb"))["provenance"]["domain_growth"]["fit"]
    return fit, fit["c0_m_s"] / 100, fit["c0_stderr_m_s"] / 100, fit["D_m2_s"] * 1e8, fit["D_stderr_m2_s"] * 1e8
