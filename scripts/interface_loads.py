"""The fluid's load on a box obstacle's faces, from coupled runs' interface.h5 (2-D or 3-D).

usage: scripts/interface_loads DIR [DIR ...] [--window T0 T1]...
The interface nodes are sorted by their position at t = 0 into the obstacle's upstream face
(left, x = x_min, below the top), top (y = y_max, between the sides), downstream face (right,
x = x_max) and the two top edges the faces share (top-left, top-right; a nodal load there is the
sum of both faces' parts). A 3-D run's loads (N) are divided by the obstacle's depth (z extent
of its interface: a slab), so every run is in N per metre of depth. For each window [T0, T1]
(default 0.12-0.25, 0.12-0.18, 0.18-0.25 s) it prints each part's x and y impulse (N s/m) and
its moment impulse about the base's centre (N s m/m, positive bending towards +x: `moment`, of
which `moment fx` is the x load's part, y f_x, and `moment fy` the y load's, -(x - x_c) f_y),
one column per run, and the later runs' difference from the first in % of the first run's total.
"""
import argparse
import os

import h5py
import numpy as np

PARTS = ("left", "top-left", "top", "top-right", "right")


def read(path):
    """time [N], loads per metre [N x n x 2 (x, y)], reference positions [n x D], parts [n]."""
    with h5py.File(os.path.join(path, "interface.h5") if os.path.isdir(path) else path, "r") as f:
        time = f["time"][:]
        load = f["load"][:]
        x = f["position"][:]
    x0 = x[0]
    dim = x0.shape[1]
    depth = float(np.ptp(x0[:, 2])) if dim == 3 else 1.0
    return time, load[:, :, :2] / depth, x[:, :, :2], parts_of(x0[:, :2])


def parts_of(x0):
    """The part of each node by its reference position (x, y)."""
    lo, hi, top = x0[:, 0].min(), x0[:, 0].max(), x0[:, 1].max()
    tol = 1e-9 * max(hi - lo, top - x0[:, 1].min())
    left, right = np.abs(x0[:, 0] - lo) <= tol, np.abs(x0[:, 0] - hi) <= tol
    up = np.abs(x0[:, 1] - top) <= tol
    part = np.full(len(x0), "", dtype=object)
    part[left & ~up], part[right & ~up] = "left", "right"
    part[up & ~left & ~right] = "top"
    part[left & up], part[right & up] = "top-left", "top-right"
    if (part == "").any():
        raise SystemExit(f"{np.count_nonzero(part == '')} interface nodes are on no face of a box")
    return part


def impulses(run, t0, t1):
    """{part: (x, y, moment, moment fx, moment fy)} impulse over the steps inside [t0, t1], and
    'total'."""
    time, load, x, part = run
    dt = np.diff(time)  # row k >= 1 is the step from time[k - 1] to time[k]
    inside = (time[:-1] >= t0 - 1e-12) & (time[1:] <= t1 + 1e-12)
    base = np.array([0.5 * (x[0, :, 0].min() + x[0, :, 0].max()), x[0, :, 1].min()])
    arm = x[1:] - base  # the step's wall position (the motion the fluid used)
    f = load[1:]
    moment_x, moment_y = arm[:, :, 1] * f[:, :, 0], -arm[:, :, 0] * f[:, :, 1]  # -(r x f)_z
    w = (dt * inside)[:, None]
    out = {}
    for p in PARTS + ("total",):
        m = np.ones(len(part), bool) if p == "total" else part == p
        out[p] = tuple(float((w * q[:, m]).sum())
                       for q in (f[:, :, 0], f[:, :, 1], moment_x + moment_y, moment_x, moment_y))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("dirs", nargs="+", help="run folders (or interface.h5 files)")
    p.add_argument("--window", nargs=2, type=float, action="append", metavar=("T0", "T1"))
    a = p.parse_args()
    runs = [read(d) for d in a.dirs]
    for t0, t1 in a.window or [(0.12, 0.25), (0.12, 0.18), (0.18, 0.25)]:
        table = [impulses(r, t0, t1) for r in runs]
        print(f"impulse over {t0}-{t1} s per metre of depth (x, y: N s/m; moment: N s m/m)")
        for c, name in enumerate(("x", "y", "moment", "moment fx", "moment fy")):
            for part in PARTS + ("total",):
                cells = [f"{t[part][c]:+11.5f}" for t in table]
                ref = table[0]["total"][c]
                diffs = [f"{100 * (t[part][c] - table[0][part][c]) / ref:+6.1f} %" if ref else ""
                         for t in table[1:]]
                print(f"  {name:9s} {part:9s} " + " ".join(cells) + "  " + " ".join(diffs))


if __name__ == "__main__":
    main()
