"""Surge front of a dam-break run against Martin & Moyce (1952): Z = x/a against T = t sqrt(2g/a).

usage: scripts/dam_break_front DIR [--a 0.1] [--g 9.81] [--probe front] [--release 0]
Prints, at each experimental T with Z <= 3.5, the simulated Z and the relative difference, and
the largest difference; draws DIR/front.png. Exits 1 if the largest difference exceeds
--tolerance. --release: the scene time at which the column is let go (a scene that settles it
behind a gate first); T = 0 there.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REF = os.path.join(os.path.dirname(__file__), "..", "data", "ref", "martin_moyce_1952_front.csv")


def rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.reader(f) if r and not r[0].startswith("#")]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("dir")
    p.add_argument("--a", type=float, default=0.1, help="column width a, m")
    p.add_argument("--g", type=float, default=9.81)
    p.add_argument("--probe", default="front")
    p.add_argument("--tolerance", type=float, default=0.10)
    p.add_argument("--release", type=float, default=0.0, help="scene time of the release, s")
    args = p.parse_args()
    table = rows(os.path.join(args.dir, "probes.csv"))
    col = table[0].index(args.probe)
    scale = math.sqrt(2.0 * args.g / args.a)
    kept = [r for r in table[1:] if float(r[0]) >= args.release]
    T = [(float(r[0]) - args.release) * scale for r in kept]
    Z = [float(r[col]) / args.a for r in kept]
    ref = [(float(t), float(z)) for t, z in rows(REF)[1:]]
    worst = 0.0
    print("T_exp  Z_exp  Z_sim  diff")
    for t, z in ref:
        if z > 3.5 or t > T[-1]:
            continue
        k = next(i for i in range(1, len(T)) if T[i] >= t)
        z_sim = Z[k - 1] + (Z[k] - Z[k - 1]) * (t - T[k - 1]) / (T[k] - T[k - 1])
        diff = (z_sim - z) / z
        worst = max(worst, abs(diff))
        print(f"{t:5.2f}  {z:5.2f}  {z_sim:5.2f}  {100 * diff:+5.1f} %")
    print(f"largest difference {100 * worst:.1f} % (tolerance {100 * args.tolerance:.0f} %)")
    plt.plot(T, Z, label="fsi")
    plt.plot([t for t, _ in ref], [z for _, z in ref], "o", label="Martin & Moyce 1952")
    plt.xlabel("T = t sqrt(2g/a)")
    plt.ylabel("Z = x/a")
    plt.grid(alpha=0.3)
    plt.legend()
    out = os.path.join(args.dir, "front.png")
    plt.savefig(out, dpi=100)
    print(f"plot: {out}")
    sys.exit(1 if worst > args.tolerance else 0)


if __name__ == "__main__":
    main()
