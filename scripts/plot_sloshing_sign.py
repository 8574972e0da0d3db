"""Sign check of the sloshing scene: the oil and the beam at t = 0 and at the first positive
extreme of the measured roll angle (table convention: + = clockwise, right wall down), from a
run's fields.h5, with the tank outline rotated by the scene's angle (-table) about (0.3045, 0).
  /usr/bin/python3 scripts/plot_sloshing_sign.py RUN_DIR OUT.png [TIME]"""
import csv
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TABLE = os.path.join(ROOT, "data", "ref", "spheric_sloshing_elastic_beam",
                     "dualsphysics_RollingTankDeepTimeSeries_clean.csv")
PIVOT = (0.3045, 0.0)
TANK = [(0.0, 0.3445), (0.0, 0.0), (0.609, 0.0), (0.609, 0.3445), (0.0, 0.3445)]


def table_angle(t):
    with open(TABLE) as f:
        rows = [(float(a), float(b)) for a, b in list(csv.reader(f))[1:]]
    return min(rows, key=lambda r: abs(r[0] - t))[1]


def frame_at(f, t):
    frames = f["frames"]
    return frames[min(frames, key=lambda k: abs(frames[k].attrs["time"] - t))]


def main():
    run, out = sys.argv[1], sys.argv[2]
    t_peak = float(sys.argv[3]) if len(sys.argv) > 3 else 0.55
    f = h5py.File(os.path.join(run, "fields.h5"), "r")
    fig, axes = plt.subplots(1, 2, figsize=(11, 3.6), sharey=True)
    for ax, t in zip(axes, [0.0, t_peak]):
        g = frame_at(f, t)
        time = g.attrs["time"]
        deg = table_angle(time)
        a = -math.radians(deg)  # the scene's counter-clockwise angle (scale: -1)
        c, s = math.cos(a), math.sin(a)
        tank = [(PIVOT[0] + c * (x - PIVOT[0]) - s * y, PIVOT[1] + s * (x - PIVOT[0]) + c * y)
                for x, y in TANK]
        ax.plot(*zip(*tank), "k-", lw=1.5, label="tank (table angle, scale -1)")
        p = g["particles/position"][:].reshape(-1, 2)
        ax.plot(p[:, 0], p[:, 1], ",", color="tab:blue")
        b = g["beam/position"][:].reshape(-1, 2)
        ax.plot(b[:, 0], b[:, 1], ".", ms=2, color="tab:red", label="beam nodes")
        ax.set_title(f"t = {time:.2f} s, table angle {deg:+.2f} deg", fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
        ax.legend(fontsize=7, loc="upper left")
    axes[0].set_ylabel("y (m)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"plot: {out}")


if __name__ == "__main__":
    main()
