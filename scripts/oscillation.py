#!/usr/bin/python3
"""Mean, amplitude and frequency of a periodic probe (Turek & Hron's "mean +/- amplitude
[frequency]"): over whole cycles in a time window of a run's probes.csv. The cycles are cut at the
upward crossings of the window's mid-range (max + min)/2, found by linear interpolation; over the
whole cycles between the first and the last crossing, mean = (max + min)/2, amplitude =
(max - min)/2 and frequency = cycles / (last - first crossing). With --plot, the probe of each
run against time in one PNG.

  scripts/oscillation RUN/probes.csv [RUN2/probes.csv ...] --probe tip_y --from 10 --to 20 \\
      [--scale 10] [--plot out.png --label bh4 --label bh8 --xlabel "t U0/D" --ref-amplitude 0.083]

--scale multiplies time for the frequency and the plot (e.g. U0/D = 10 1/s gives the frequency
in U0/D); --ref-amplitude draws a published amplitude as dashed lines at +-A. Exit status 2 on bad arguments or a window with fewer than two crossings.
"""
import argparse
import csv
import sys


def fail(message):
    print(message, file=sys.stderr)
    sys.exit(2)


def read(path, probe):
    t, v = [], []
    try:
        with open(path) as f:
            rows = csv.DictReader(f)
            if probe not in (rows.fieldnames or []) or "time" not in rows.fieldnames:
                fail(f"{path}:1: no column {probe!r} or 'time' (columns: {rows.fieldnames})")
            for line, r in enumerate(rows, start=2):
                try:
                    if r[probe] not in ("", "nan"):
                        t.append(float(r["time"]))
                        v.append(float(r[probe]))
                except (TypeError, ValueError):
                    fail(f"{path}:{line}: {probe}: not a number: {r[probe]!r}")
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    return t, v


def measure(t, v, t0, t1):
    """(mean, amplitude, frequency, cycles) over the whole cycles in [t0, t1]."""
    w = [(a, b) for a, b in zip(t, v) if t0 <= a <= t1]
    if len(w) < 4:
        raise ValueError(f"{len(w)} samples in [{t0}, {t1}]")
    mid = 0.5 * (max(b for _, b in w) + min(b for _, b in w))
    ups = [a0 + (mid - b0) * (a1 - a0) / (b1 - b0)
           for (a0, b0), (a1, b1) in zip(w, w[1:]) if b0 < mid <= b1]
    if len(ups) < 2:
        raise ValueError(f"{len(ups)} upward crossings of {mid:.4g} in [{t0}, {t1}]")
    cyc = [b for a, b in w if ups[0] <= a <= ups[-1]]
    hi, lo = max(cyc), min(cyc)
    cycles = len(ups) - 1
    return 0.5 * (hi + lo), 0.5 * (hi - lo), cycles / (ups[-1] - ups[0]), cycles


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("probes", nargs="+")
    p.add_argument("--probe", required=True)
    p.add_argument("--from", dest="t0", type=float, required=True)
    p.add_argument("--to", dest="t1", type=float, default=float("inf"))
    p.add_argument("--scale", type=float, default=1.0, help="time scale, e.g. U0/D")
    p.add_argument("--plot")
    p.add_argument("--label", action="append", default=[])
    p.add_argument("--xlabel")
    p.add_argument("--ref-amplitude", type=float)
    a = p.parse_args()
    if a.label and len(a.label) != len(a.probes):
        p.error("give one --label per probes file")
    series, rows = [], []
    for k, path in enumerate(a.probes):
        t, v = read(path, a.probe)
        label = a.label[k] if a.label else path
        try:
            mean, amp, freq, n = measure(t, v, a.t0, a.t1)
        except ValueError as e:
            fail(f"{path}: {e}")
        rows.append(f"| {label} | {mean:.5g} | {amp:.5g} | {freq / a.scale:.4g} | {n} |")
        series.append((label, t, v))
    print("| run | mean | amplitude | frequency | cycles |")
    print("|---|---|---|---|---|")
    print("\n".join(rows))
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(9, 4))
        for label, t, v in series:
            ax.plot([x * a.scale for x in t], v, lw=0.8, label=label)
        if a.ref_amplitude is not None:
            for sign in (1, -1):
                ax.axhline(sign * a.ref_amplitude, color="k", ls="--", lw=0.8,
                           label=f"published +-{a.ref_amplitude:g}" if sign > 0 else None)
        ax.set_xlabel(a.xlabel or ("time" + (f" x {a.scale:g}" if a.scale != 1.0 else ", s")))
        ax.set_ylabel(a.probe)
        ax.grid(alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(a.plot, dpi=110)


if __name__ == "__main__":
    main()
