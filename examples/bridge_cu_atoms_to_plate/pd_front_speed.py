"""Speed of the elastic front of a PD impact bar run (shockfield run, method = "pd", 1D): the
position where the particle velocity crosses a quarter of the impact speed (half of the jump
v/2 that runs into the resting half), interpolated between points, fitted against time over the
profiles after the first (start-up of the impact). Prints the speed in m/s.
Usage: pd_front_speed.py RUN_FOLDER IMPACT_SPEED_M_S"""
import csv
import sys

import numpy as np


def front_speed(run, impact_speed):
    t, front = [], []
    for row in csv.DictReader(open(f"{run}/profiles/index.csv")):
        time = float(row["time_s"])
        d = np.genfromtxt(f"{run}/profiles/profile_{row['profile']}.csv", delimiter=",", names=True)
        x, v = d["x_m"], d["vx_m_s"]
        level = 0.25 * impact_speed
        i = np.where(v > level)[0][-1]
        if time <= 0 or i >= len(v) - 2:
            continue  # before the impact, or the front has reached the end
        front.append(x[i] + (v[i] - level) / (v[i] - v[i + 1]) * (x[i + 1] - x[i]))
        t.append(time)
    return np.polyfit(np.array(t[1:]), np.array(front[1:]), 1)[0]


if __name__ == "__main__":
    print(front_speed(sys.argv[1], float(sys.argv[2])))
