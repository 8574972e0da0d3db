"""The fluid's force on the structure by wall term, from a coupled run's coupling.csv.

usage: scripts/force_split DIR [--from 0.10] [--to 0.30] [--probe corner_x]
Prints the horizontal and vertical impulse (N s per m of depth) over [from, to] carried by the
pressure mirror terms (eqs. 25-26), the repulsive term (eq. 27, with wall damping) and the viscous
mirror term (eq. 24), and each part's share of the horizontal impulse; and, from probes.csv, the
probe's most negative value before its maximum (the leftward dip) and its maximum, with times.
"""
import argparse
import csv
import os


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("dir")
    p.add_argument("--from", dest="t0", type=float, default=0.10)
    p.add_argument("--to", dest="t1", type=float, default=0.30)
    p.add_argument("--probe", default="corner_x")
    a = p.parse_args()
    parts = ("pressure", "repulsive", "viscous")
    imp = {(k, c): 0.0 for k in parts for c in "xy"}
    last = None
    with open(os.path.join(a.dir, "coupling.csv"), newline="") as f:
        for r in csv.DictReader(f):
            t, dt = float(r["time"]), float(r["dt"])  # the step from t to t + dt
            last = t + dt
            if t < a.t0 - 1e-12 or t + dt > a.t1 + 1e-12:
                continue
            for k in parts:
                for c in "xy":
                    imp[(k, c)] += dt * float(r[f"f{c}_{k}"])
    total_x = sum(imp[(k, "x")] for k in parts)
    print(f"impulse over {a.t0}-{min(a.t1, last)} s, N s/m (force on the structure):")
    for k in parts:
        share = 100 * imp[(k, "x")] / total_x if total_x else float("nan")
        print(f"  {k:9s} x {imp[(k, 'x')]:+9.4f}  y {imp[(k, 'y')]:+9.4f}  share of x {share:5.1f} %")
    print(f"  total     x {total_x:+9.4f}")
    probes = os.path.join(a.dir, "probes.csv")
    if os.path.exists(probes):
        with open(probes, newline="") as f:
            rows = list(csv.DictReader(f))
        if rows and a.probe in rows[0]:
            ts = [float(r["time"]) for r in rows]
            vs = [float(r[a.probe]) for r in rows]
            k = max(range(len(vs)), key=lambda i: vs[i])
            j = min(range(k + 1), key=lambda i: vs[i])
            print(f"{a.probe}: dip {vs[j]:+.5f} at {ts[j]:.4f} s, peak {vs[k]:.5f} at {ts[k]:.4f} s")


if __name__ == "__main__":
    main()
