"""Still-water criteria of a hydrostatic-tank run from DIR/probes.csv
(the same criteria as data/ref/hydrostatic_tank/acceptance.yaml).

usage: scripts/hydrostatic_check DIR [--depth 0.5] [--l0 0.0125] [--rho 1000] [--g 9.81]
                                     [--damping 2.0] [--window 1.0]
Prints the bottom-row pressure averaged over the last second against rho g H and
rho g (H - l0/2), the mean particle speed at the end against sqrt(g H), and whether the kinetic
energy grows after the damping phase.
Exits 1 when a criterion fails: pressure within 1 % of rho g H, mean speed below 1 % of
sqrt(g H), and the kinetic energy never above its value at the end of the damping phase (every
sample of probes.csv). Also printed, not judged: the largest kinetic energy in each window of
--window seconds after the damping phase (its envelope), and, where DIR holds fields.h5 with
positions, velocities and pressures, the energy budget after the damping phase
(energy_budget): whether a rise of the kinetic energy is the column still settling (gravity's
potential released) or energy the scheme adds.
"""
import argparse
import csv
import json
import math
import os
import sys

import h5py
import numpy as np


def measure(rows, depth=0.5, l0=0.0125, rho=1000.0, g=9.81, damping=2.0, window=1.0):
    """The still-water figures of probes.csv's rows (csv.DictReader dicts): a dict with end,
    p_bottom (mean over the last 1 s), rho_g_h, row (rho g (H - l0/2)), speed (mean speed at the
    end), scale (sqrt(g H)), growth (largest kinetic energy after the damping phase over its value
    there) and envelope (the largest in each window after it)."""
    t = [float(r["time"]) for r in rows]
    end = t[-1]
    last = [r for r in rows if float(r["time"]) >= end - 1.0 - 1e-9]
    p_bottom = sum(float(r["p_bottom"]) for r in last) / len(last)
    ke = [(float(r["time"]), float(r["kinetic_energy"])) for r in rows]
    after = [e for tt, e in ke if tt >= damping - 1e-9]
    growth = max(after) / after[0] if after and after[0] > 0 else float("inf")
    envelope = []
    start = damping
    while start < end - 1e-9:
        inside = [e for tt, e in ke if start - 1e-9 <= tt < start + window - 1e-9]
        if inside:
            envelope.append(max(inside))
        start += window
    return {"end": end, "p_bottom": p_bottom, "rho_g_h": rho * g * depth,
            "row": rho * g * (depth - 0.5 * l0), "speed": float(rows[-1]["mean_speed"]),
            "scale": math.sqrt(g * depth), "growth": growth, "envelope": envelope}


def energy_budget(directory, damping=2.0, g=9.81):
    """The fluid's energies in every frame of DIR/fields.h5 from the frame nearest the end of the
    damping phase on, each as its change since that frame: gravity's potential sum m g y (y up),
    the kinetic sum m |u|^2 / 2 and the compression sum V p^2 / (2 rho c^2) (the equation of
    state p = rho c^2 (n - n0) / n0 as an elastic energy), m = rho V, V = l0^D (density, sound
    speed and l0 from run.json's fluid options). Returns a dict: time, gravity, kinetic (the
    values, not changes), compression and total (gravity + kinetic + compression, change) as
    arrays, kinetic_first (at that frame) and rise (the largest increase of total between two
    frames after it)."""
    with open(os.path.join(directory, "run.json")) as f:
        o = json.load(f)["fluid"]["options"]
    rho, c, l0 = o["density"], o["sound_speed"], o["l0"]
    rows = []
    with h5py.File(os.path.join(directory, "fields.h5"), "r") as f:
        frames = f["frames"]
        for k in sorted(frames.keys(), key=int):
            p = frames[k]["particles"]
            x, u, pr = p["position"][:], p["velocity"][:], p["pressure"][:]
            v = l0 ** x.shape[1]
            rows.append((frames[k].attrs["time"], rho * v * g * x[:, 1].sum(),
                         0.5 * rho * v * (u ** 2).sum(), v * (pr ** 2).sum() / (2 * rho * c * c)))
    r = np.array(rows)
    r = r[np.argmin(abs(r[:, 0] - damping)):]
    total = r[:, 1:].sum(axis=1) - r[0, 1:].sum()
    rise = max((total[j] - total[:j].min() for j in range(1, len(total))), default=0.0)
    return {"time": r[:, 0], "gravity": r[:, 1] - r[0, 1], "kinetic": r[:, 2],
            "compression": r[:, 3] - r[0, 3], "total": total, "kinetic_first": r[0, 2],
            "rise": max(rise, 0.0)}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("dir")
    p.add_argument("--depth", type=float, default=0.5)
    p.add_argument("--l0", type=float, default=0.0125)
    p.add_argument("--rho", type=float, default=1000.0)
    p.add_argument("--g", type=float, default=9.81)
    p.add_argument("--damping", type=float, default=2.0, help="end of the damping phase, s")
    p.add_argument("--window", type=float, default=1.0, help="envelope window, s")
    a = p.parse_args()
    with open(f"{a.dir}/probes.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    m = measure(rows, a.depth, a.l0, a.rho, a.g, a.damping, a.window)
    end, p_bottom, rho_g_h, row = m["end"], m["p_bottom"], m["rho_g_h"], m["row"]
    speed, scale, growth, envelope = m["speed"], m["scale"], m["growth"], m["envelope"]
    ok_p = abs(p_bottom / rho_g_h - 1.0) <= 0.01
    ok_v = speed / scale < 0.01
    ok_e = growth <= 1.0
    print(f"bottom-row pressure, mean over t = {end - 1:.2f}..{end:.2f} s: {p_bottom:.1f} Pa: "
          f"{100 * (p_bottom / rho_g_h - 1):+.2f} % of rho g H = {rho_g_h:.1f} Pa, "
          f"{100 * (p_bottom / row - 1):+.2f} % of rho g (H - l0/2) = {row:.1f} Pa "
          f"[{'pass' if ok_p else 'FAIL'}: 1 %]")
    print(f"mean particle speed at t = {end:.2f} s: {speed:.4f} m/s = "
          f"{100 * speed / scale:.2f} % of sqrt(gH) [{'pass' if ok_v else 'FAIL'}: 1 %]")
    print(f"kinetic energy after t = {a.damping:g} s: largest / first = {growth:.4g} "
          f"[{'pass' if ok_e else 'FAIL'}: 1]")
    print(f"  largest in each {a.window:g} s window after it: "
          + " ".join(f"{e:.3g}" for e in envelope) + " J/m")
    for tt in (1, 2, 3, 5, 10):
        near = min(rows, key=lambda r: abs(float(r["time"]) - tt))
        print(f"  t = {float(near['time']):5.2f} s  mean speed {float(near['mean_speed']):.4f} m/s"
              f"  kinetic energy {float(near['kinetic_energy']):.4g} J/m")
    if os.path.exists(os.path.join(a.dir, "fields.h5")):
        b = energy_budget(a.dir, a.damping, a.g)
        print(f"energy budget from t = {b['time'][0]:.2f} s to {b['time'][-1]:.2f} s (fields.h5): "
              f"gravity {b['gravity'][-1]:+.4g}, kinetic {b['kinetic'][-1] - b['kinetic_first']:+.4g}, "
              f"compression {b['compression'][-1]:+.4g}, total {b['total'][-1]:+.4g} J "
              f"(per metre in 2-D); the largest rise of the total between frames {b['rise']:.4g}")
    sys.exit(0 if ok_p and ok_v and ok_e else 1)


if __name__ == "__main__":
    main()
