"""Speed of the elastic front of a PD impact bar run (shockfield run, method = "pd", 1D): the
position where the particle velocity crosses a quarter of the impact speed (half of the jump
v/2 that runs into the resting half), interpolated between points, fitted against time over the
profiles after the first (start-up of the impact). Prints the speed in m/s.
Usage: pd_front_speed.py RUN_FOLDER IMPACT_SPEED_M_S"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402  (the shared run-folder reader)


def front_speed(run, impact_speed):
    t, front = [], []
    for profile in Run.open(run).frames(kind="profiles"):
        time, x, v = profile.time, profile.data["x_m"], profile.data["vx_m_s"]
        level = 0.25 * impact_speed
        i = np.where(v > level)[0][-1]
        if time <= 0 or i >= len(v) - 2:
            continue  # before the impact, or the front has reached the end
        front.append(x[i] + (v[i] - level) / (v[i] - v[i + 1]) * (x[i + 1] - x[i]))
        t.append(time)
    return np.polyfit(np.array(t[1:]), np.array(front[1:]), 1)[0]


if __name__ == "__main__":
    print(front_speed(sys.argv[1], float(sys.argv[2])))
