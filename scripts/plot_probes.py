"""Probe histories of one run (DIR/probes.csv) into DIR/probes.png, with optional references."""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_columns(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    cols = {name: [] for name in header}
    for r in body:
        for name, value in zip(header, r):
            cols[name].append(float(value))
    return cols


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("dir", help="run output directory holding probes.csv")
    parser.add_argument("--ref", action="append", default=[],
                        help="PROBE=FILE.csv:TIME_COLUMN:VALUE_COLUMN:LABEL")
    args = parser.parse_args()
    probes = read_columns(os.path.join(args.dir, "probes.csv"))
    names = [n for n in probes if n != "time"]
    if not names:
        sys.exit(f"plot: {args.dir}/probes.csv has no probe columns")
    refs = {}
    for spec in args.ref:
        probe, rest = spec.split("=", 1)
        path, tcol, vcol, label = rest.split(":", 3)
        data = read_columns(path)
        refs.setdefault(probe, []).append((data[tcol], data[vcol], label))
    fig, axes = plt.subplots(len(names), 1, figsize=(8, 2.8 * len(names)), squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        ax.plot(probes["time"], probes[name], label="fsi")
        for t, v, label in refs.get(name, []):
            ax.plot(t, v, "o", ms=3, label=label)
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    axes[-1, 0].set_xlabel("time (s)")
    fig.tight_layout()
    out = os.path.join(args.dir, "probes.png")
    fig.savefig(out, dpi=100)
    print(f"plot: {out}")


if __name__ == "__main__":
    main()
