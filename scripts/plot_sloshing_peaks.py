"""Peaks and period of the sloshing beam: one extreme per lobe of beam_top_x (lobes under 10 mm,
the start-up, skipped), the zero crossings, and the up-crossings of the measured roll angle.
  /usr/bin/python3 scripts/plot_sloshing_peaks.py RUN_DIR"""
import os
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TABLE = os.path.join(ROOT, "data", "ref", "spheric_sloshing_elastic_beam",
                     "dualsphysics_RollingTankDeepTimeSeries_clean.csv")


def crossings(t, x, upward):
    """Linearly interpolated times where x crosses zero upwards (or downwards)."""
    out = []
    for i in range(1, len(x)):
        if (x[i - 1] < 0 <= x[i]) if upward else (x[i - 1] > 0 >= x[i]):
            out.append(t[i - 1] - x[i - 1] * (t[i] - t[i - 1]) / (x[i] - x[i - 1]))
    return np.round(out, 3)


def main():
    d = np.genfromtxt(os.path.join(sys.argv[1], "probes.csv"), delimiter=",", names=True)
    t, x = d["time"], d["beam_top_x"]
    lobes, start = [], 0
    for i in range(1, len(x) + 1):
        if i == len(x) or np.sign(x[i]) != np.sign(x[start]):
            k = start + int(np.argmax(np.abs(x[start:i])))
            if abs(x[k]) > 0.01:
                lobes.append((round(float(t[k]), 3), round(float(x[k]), 4)))
            start = i
    print("lobe extremes (t s, beam_top_x m):", lobes)
    late = t > 0.4
    up, down = crossings(t[late], x[late], True), crossings(t[late], x[late], False)
    print("beam up-crossings:", up, "down-crossings:", down, "periods:", np.diff(up))
    r = np.genfromtxt(TABLE, delimiter=",", names=True)
    ru = crossings(r["time_s"], r["roll_angle_deg"], True)
    print("roll up-crossings:", ru, "periods:", np.round(np.diff(ru), 3))


if __name__ == "__main__":
    main()
