"""Surge front of a dam-break run against Martin & Moyce (1952): Z = x/a against T = t sqrt(2g/a).

usage: scripts/dam_break_front DIR [DIR2 ...] [--a 0.1] [--g 9.81] [--probe front] [--release 0]
                               [--compare PNG [--label NAME ...]]
Prints, at each experimental T with Z <= 3.5, the simulated Z and the relative difference, and
the largest difference; draws DIR/front.png. --compare: every DIR's Z(T) and dZ/dT (central
differences over +-2 samples) in one figure with the experiment, labelled by --label (one per DIR,
in order) or the directory names. --release: the scene time at which the column is
let go (a scene that settles it behind a gate first); T = 0 there.

Acceptance (data/ref/dam_break_rigid/acceptance.yaml): the experiment's release was not instantaneous, so its clock is shifted
by one offset dT in [0, 0.3] (T units), the least-squares fit of the relative differences over
the points with 1.2 <= Z <= 3.5; over those points the largest shifted difference must be
<= --tolerance (5 %), and the front speed dZ/dT between Z = 2 and 3.5 (straight-line fits of
the experiment's points and of the run's samples in that range) within --speed-tolerance (5 %).
The unshifted difference is printed beside. With two or more DIRs (two resolutions) each is
checked, and the largest relative difference of Z between the first two at the points' T must
be <= --agreement (3 %). Exits 1 when a criterion fails.

Also printed, not judged: Z at T = 2.5, the late speed (dZ/dT fitted over 3 <= T <= 4), and where
DIR holds fields.h5 with velocities: the tip speed, the mean
x-velocity of the particles within 0.2 a behind the front over sqrt(2 g a), averaged over the
frames with 2 <= Z <= 3.5 (tip_speed): the front's speed free of which particle leads it and of
the ramp the straight-line fit averages (docs/fluid_emps.md, "The front's speed split by term").
"""
import argparse
import csv
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REF = os.path.join(os.path.dirname(__file__), "..", "data", "ref", "martin_moyce_1952_front.csv")


def rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.reader(f) if r and not r[0].startswith("#")]


def run_front(path, probe, release, scale, a):
    table = rows(os.path.join(path, "probes.csv"))
    col = table[0].index(probe)
    kept = [r for r in table[1:] if float(r[0]) >= release]
    T = [(float(r[0]) - release) * scale for r in kept]
    Z = [float(r[col]) / a for r in kept]
    return T, Z


def at(T, Z, t):
    """Z at time t by linear interpolation (None outside the run)."""
    if t < T[0] or t > T[-1]:
        return None
    k = next(i for i in range(1, len(T)) if T[i] >= t)
    return Z[k - 1] + (Z[k] - Z[k - 1]) * (t - T[k - 1]) / (T[k] - T[k - 1])


def slope(ts, zs):
    n = len(ts)
    mt, mz = sum(ts) / n, sum(zs) / n
    return sum((t - mt) * (z - mz) for t, z in zip(ts, zs)) / sum((t - mt) ** 2 for t in ts)


def fitted_shift(T, Z, points):
    """dT in [0, 0.3] minimising sum ((Z_sim(T_exp - dT) - Z_exp) / Z_exp)^2, to 1e-4."""
    def cost(dt):
        return sum(((at(T, Z, t - dt) - z) / z) ** 2 for t, z in points)
    grid = [0.3 * k / 300 for k in range(301)]
    best = min(grid, key=cost)
    lo, hi = max(0.0, best - 0.001), min(0.3, best + 0.001)
    fine = [lo + (hi - lo) * k / 200 for k in range(201)]
    return min(fine, key=cost)


def reference(path=REF):
    """The experiment's (T, Z) points, those judged (1.2 <= Z <= 3.5) and its front speed."""
    ref = [(float(t), float(z)) for t, z in rows(path)[1:]]
    points = [(t, z) for t, z in ref if 1.2 <= z <= 3.5]
    speed_pts = [(t, z) for t, z in ref if 2.0 <= z <= 3.5]
    speed_exp = slope([t for t, _ in speed_pts], [z for _, z in speed_pts])
    return ref, points, speed_exp


def measure(d, probe="front", release=0.0, a=0.1, g=9.81):
    """The acceptance figures of one run directory against Martin & Moyce: a dict with T, Z (the
    run), ref, shift (fitted dT), table (T_exp, Z_exp, Z_sim(T), Z_sim(T - dT), inside), worst and
    worst_raw (largest shifted / unshifted relative difference over 1.2 <= Z <= 3.5), speed_sim,
    speed_exp, speed_diff, and shifted (the run's unshifted Z at the judged points, for the
    agreement between two runs)."""
    scale = math.sqrt(2.0 * g / a)
    ref, points, speed_exp = reference()
    T, Z = run_front(d, probe, release, scale, a)
    shift = fitted_shift(T, Z, points)
    worst = worst_raw = 0.0
    shifted, table = [], []
    for t, z in ref:
        if z > 3.5 or t > T[-1]:
            continue
        z_raw, z_sh = at(T, Z, t), at(T, Z, t - shift)
        d_raw, d_sh = (z_raw - z) / z, (z_sh - z) / z
        inside = 1.2 <= z <= 3.5
        if inside:
            worst, worst_raw = max(worst, abs(d_sh)), max(worst_raw, abs(d_raw))
            shifted.append(z_raw)
        table.append((t, z, z_raw, d_raw, z_sh, d_sh, inside))
    sim_pts = [(t, z) for t, z in zip(T, Z) if 2.0 <= z <= 3.5]
    speed_sim = slope([t for t, _ in sim_pts], [z for _, z in sim_pts])
    late = [(t, z) for t, z in zip(T, Z) if 3.0 <= t <= 4.0]
    return {"T": T, "Z": Z, "ref": ref, "shift": shift, "table": table, "worst": worst,
            "worst_raw": worst_raw, "speed_sim": speed_sim, "speed_exp": speed_exp,
            "speed_diff": (speed_sim - speed_exp) / speed_exp, "shifted": shifted,
            "z_25": at(T, Z, 2.5),
            "late": slope([t for t, _ in late], [z for _, z in late]) if len(late) > 1 else None}


def tip_speed(d, probe="front", release=0.0, a=0.1, g=9.81):
    """The mean over DIR/fields.h5's frames with 2 <= Z <= 3.5 (Z from probes.csv at the frame's
    time) of the mean x-velocity of the particles with x > x_front - 0.2 a, over sqrt(2 g a);
    None without fields.h5 or without such a frame."""
    path = os.path.join(d, "fields.h5")
    if not os.path.exists(path):
        return None
    table = rows(os.path.join(d, "probes.csv"))
    col = table[0].index(probe)
    front = {float(r[0]): float(r[col]) for r in table[1:]}
    speeds = []
    with h5py.File(path, "r") as f:
        for frame in f["frames"].values():
            t = float(frame.attrs["time"])
            x_front = min(front.items(), key=lambda item: abs(item[0] - t))[1]
            if "velocity" not in frame["particles"]:
                return None  # a run that wrote no velocities (output.fields)
            if t < release or not 2.0 <= x_front / a <= 3.5:
                continue
            x, v = frame["particles/position"][:, 0], frame["particles/velocity"][:, 0]
            tip = v[x > x_front - 0.2 * a]
            speeds.append(tip.mean() / math.sqrt(2.0 * g * a))
    return sum(speeds) / len(speeds) if speeds else None


def agreement(first, second):
    """Largest relative difference of Z between two runs at the experiment's judged T (relative to
    the first), from measure()'s "shifted" lists."""
    n = min(len(first), len(second))
    return max(abs(b - a_) / a_ for a_, b in zip(first[:n], second[:n]))


def plot(m, out):
    """The run's front over the experiment, shifted by the fitted dT and unshifted, into out."""
    shift, ref = m["shift"], m["ref"]
    plt.figure()
    plt.plot(m["T"], m["Z"], label="fsi")
    plt.plot([t - shift for t, _ in ref], [z for _, z in ref], "o",
             label=f"Martin & Moyce 1952, T - {shift:.2f}")
    plt.plot([t for t, _ in ref], [z for _, z in ref], "x", color="grey",
             label="Martin & Moyce 1952, unshifted")
    plt.xlabel("T = t sqrt(2g/a)")
    plt.ylabel("Z = x/a")
    plt.grid(alpha=0.3)
    plt.legend()
    plt.savefig(out, dpi=100)
    plt.close()


def compare(runs, labels, out):
    """Every run's Z(T) (left) and dZ/dT by central differences over +-2 samples (right), with the
    experiment's points and the straight line's speed over 2 <= Z <= 3.5, into out."""
    _, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for m, label in zip(runs, labels):
        T, Z = m["T"], m["Z"]
        ax[0].plot(T, Z, label=label, lw=1)
        ax[1].plot(T[2:-2], [(Z[k + 2] - Z[k - 2]) / (T[k + 2] - T[k - 2])
                             for k in range(2, len(T) - 2)], label=label, lw=1)
    ref, _, speed_exp = reference()
    ax[0].plot([t for t, _ in ref], [z for _, z in ref], "ko", ms=4, label="Martin & Moyce 1952")
    ax[0].axhspan(2.0, 3.5, color="0.9")
    ax[1].axhline(speed_exp, color="k", ls="--", lw=1, label=f"experiment's fit, {speed_exp:.3f}")
    ax[0].set_ylim(0.9, 6)
    ax[1].set_ylim(0, 2.2)
    ax[0].set_xlabel("T = t sqrt(2g/a)")
    ax[1].set_xlabel("T")
    ax[0].set_ylabel("Z = x/a (grey: the criterion's window)")
    ax[1].set_ylabel("dZ/dT")
    for a_ in ax:
        a_.set_xlim(0, 4.25)
        a_.grid(alpha=0.3)
    ax[0].legend(fontsize=7)
    ax[1].legend(fontsize=7, loc="lower right")
    plt.tight_layout()
    plt.savefig(out, dpi=80)
    plt.close()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("dirs", nargs="+", metavar="DIR")
    p.add_argument("--a", type=float, default=0.1, help="column width a, m")
    p.add_argument("--g", type=float, default=9.81)
    p.add_argument("--probe", default="front")
    p.add_argument("--tolerance", type=float, default=0.05)
    p.add_argument("--speed-tolerance", type=float, default=0.05)
    p.add_argument("--agreement", type=float, default=0.03)
    p.add_argument("--release", type=float, default=0.0, help="scene time of the release, s")
    p.add_argument("--compare", metavar="PNG", help="every DIR's front and speed in one figure")
    p.add_argument("--label", action="append", help="a DIR's name in --compare's figure")
    args = p.parse_args()
    if args.label and len(args.label) != len(args.dirs):
        p.error(f"--label given {len(args.label)} times for {len(args.dirs)} DIRs")
    ok = True
    shifted_runs, runs = [], []
    for d in args.dirs:
        m = measure(d, args.probe, args.release, args.a, args.g)
        print(f"{d}: least-squares shift dT = {m['shift']:.3f} (T units)")
        print("T_exp  Z_exp  Z_sim(T)  diff     Z_sim(T-dT)  diff")
        for t, z, z_raw, d_raw, z_sh, d_sh, inside in m["table"]:
            print(f"{t:5.2f}  {z:5.2f}  {z_raw:6.2f}  {100 * d_raw:+6.1f} %  {z_sh:9.2f}  "
                  f"{100 * d_sh:+6.1f} %{'' if inside else '  (outside 1.2 <= Z <= 3.5)'}")
        print(f"largest difference over 1.2 <= Z <= 3.5: shifted {100 * m['worst']:.1f} % "
              f"(tolerance {100 * args.tolerance:.0f} %), unshifted {100 * m['worst_raw']:.1f} %")
        print(f"front speed dZ/dT for 2 <= Z <= 3.5: {m['speed_sim']:.3f} against "
              f"{m['speed_exp']:.3f} ({100 * m['speed_diff']:+.1f} %, tolerance "
              f"{100 * args.speed_tolerance:.0f} %)")
        if m["z_25"] is not None:
            print(f"Z at T = 2.5: {m['z_25']:.3f} (reported, not judged)")
        if m["late"] is not None:
            print(f"late speed dZ/dT for 3 <= T <= 4: {m['late']:.3f} (reported, not judged)")
        tip = tip_speed(d, args.probe, args.release, args.a, args.g)
        if tip is not None:
            print(f"tip speed (particles within 0.2 a of the front, 2 <= Z <= 3.5): {tip:.3f} "
                  f"(reported, not judged)")
        ok = ok and m["worst"] <= args.tolerance and abs(m["speed_diff"]) <= args.speed_tolerance
        shifted_runs.append(m["shifted"])
        runs.append(m)
        out = os.path.join(d, "front.png")
        plot(m, out)
        print(f"plot: {out}")
    if args.compare:
        compare(runs, args.label or args.dirs, args.compare)
        print(f"comparison: {args.compare}")
    if len(shifted_runs) >= 2:
        agree = agreement(shifted_runs[0], shifted_runs[1])
        print(f"{args.dirs[0]} against {args.dirs[1]}: largest difference of Z at the experiment's T "
              f"{100 * agree:.1f} % (tolerance {100 * args.agreement:.0f} %)")
        ok = ok and agree <= args.agreement
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
