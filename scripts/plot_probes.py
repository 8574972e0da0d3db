"""Probe histories of one run (DIR/probes.csv) into DIR/probes.png (all probes) and
DIR/probe_<name>.png (one per probe), with the published figures the scene is validated against.

The overlays come from data/ref/<scene name>/plot.json (scene name from DIR/run.json), so a new
scene gets its references by adding that file, not by changing this script. Format:
  {"probes": {"<probe name or *>": [overlay, ...]},
   "secondary": {"file": F, "time": COL, "value": COL, "label": L, "scale": 1}}
with overlays
  {"kind": "curve", "file": F, "time": COL, "value": COL, "label": L, "scale": 1,
   "time_scale": 1, "marker": M}       value * scale against time * time_scale; points if marker
  {"kind": "line", "value": V, "label": L}                  horizontal line
  {"kind": "band", "t": [T0, T1], "value": [V0, V1], "label": L, "color": C}  a box
  {"kind": "vline", "t": T, "label": L}                     a published event time
  {"kind": "range", "value": [V0, V1], "label": L}          published range, all times
Files are relative to plot.json; a missing file is reported and skipped ("if present"). Labels
carry the source. The y axis names the probe's quantity and unit (from the scene's
output.probes); plot.json's "source" is printed under the title.
"""
import argparse
import csv
import json
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_columns(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    cols = {name: [] for name in header}
    for r in body:
        for name, value in zip(header, r):
            cols[name].append(float(value))
    return cols


def scene_name(run_dir):
    try:
        with open(os.path.join(run_dir, "run.json")) as f:
            run = json.load(f)
    except (OSError, ValueError):
        return None
    return run.get("name") or os.path.splitext(os.path.basename(run.get("scene", "")))[0]


# Unit of each probe quantity (2D: energies per metre of thickness).
UNITS = {"displacement_x": "m", "displacement_y": "m", "displacement_x_tank": "m",
         "displacement_y_tank": "m", "surge_front": "m", "pressure": "Pa", "mean_pressure": "Pa",
         "mean_speed": "m/s", "kinetic_energy": "J/m"}


def probe_labels(run_dir):
    """Probe name -> y-axis label "name: quantity (unit)" from the run's scene file."""
    try:
        import yaml

        with open(os.path.join(run_dir, "run.json")) as f:
            scene = json.load(f)["scene"]
        with open(scene) as f:
            probes = yaml.safe_load(f)["output"]["probes"]
    except (ImportError, OSError, ValueError, KeyError, TypeError):
        return {}
    labels = {}
    for p in probes:
        quantity = p.get("quantity", "")
        unit = UNITS.get(quantity)
        labels[p["name"]] = f"{p['name']}: {quantity}" + (f" ({unit})" if unit else "")
    return labels


def load_references(path):
    """The scene's plot.json and its directory, or (None, None)."""
    if not path or not os.path.isfile(path):
        return None, None
    with open(path) as f:
        return json.load(f), os.path.dirname(path)


def read_curve(spec, base):
    path = os.path.join(base, spec["file"])
    if not os.path.isfile(path):
        print(f"plot: reference {path} not present, skipped")
        return None
    data = read_columns(path)
    scale, time_scale = spec.get("scale", 1.0), spec.get("time_scale", 1.0)
    return ([time_scale * t for t in data[spec["time"]]],
            [scale * v for v in data[spec["value"]]])


def draw_overlay(ax, spec, base, t_end):
    """One overlay; curves only up to the run's end time t_end (the y range follows the run)."""
    kind, label = spec["kind"], spec.get("label")
    if kind == "curve":
        curve = read_curve(spec, base)
        if curve:
            curve = tuple(zip(*[(t, v) for t, v in zip(*curve) if t <= t_end])) or None
        if curve and spec.get("marker"):
            ax.plot(*curve, spec["marker"], ms=4, mfc="none", label=label)
        elif curve:
            ax.plot(*curve, "-", lw=1.0, alpha=0.8, label=label)
    elif kind == "line":
        ax.axhline(spec["value"], color="k", ls="--", lw=1.0, label=label)
    elif kind == "band":
        (t0, t1), (v0, v1) = spec["t"], spec["value"]
        ax.fill_between([t0, t1], v0, v1, color=spec.get("color", "tab:green"), alpha=0.2,
                        label=label)
    elif kind == "range":
        v0, v1 = spec["value"]
        ax.axhspan(v0, v1, color="tab:orange", alpha=0.15, label=label)
    elif kind == "vline":
        ax.axvline(spec["t"], color="tab:gray", ls=":", lw=1.2, label=label)
    else:
        sys.exit(f"plot: {base}/plot.json: unknown overlay kind '{kind}'")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dir", help="run output directory holding probes.csv (and run.json)")
    parser.add_argument("--ref", action="append", default=[],
                        help="extra curve: PROBE=FILE.csv:TIME_COLUMN:VALUE_COLUMN:LABEL")
    parser.add_argument("--references", help="plot.json to use instead of the scene's")
    args = parser.parse_args()
    probes = read_columns(os.path.join(args.dir, "probes.csv"))
    names = [n for n in probes if n != "time"]
    if not names:
        sys.exit(f"plot: {args.dir}/probes.csv has no probe columns")
    name = scene_name(args.dir)
    default = os.path.join(ROOT, "data", "ref", name, "plot.json") if name else None
    refs, base = load_references(args.references or default)
    extra = {}
    for spec in args.ref:
        probe, rest = spec.split("=", 1)
        path, tcol, vcol, label = rest.split(":", 3)
        data = read_columns(path)
        extra.setdefault(probe, []).append((data[tcol], data[vcol], label))
    labels = probe_labels(args.dir)
    title = name or os.path.basename(os.path.abspath(args.dir))
    source = refs.get("source", "") if refs else ""

    def panel(ax, probe):
        ax.plot(probes["time"], probes[probe], color="tab:blue", lw=1.5, label="fsi (this run)")
        if refs:
            for spec in refs.get("probes", {}).get(probe, []) + refs.get("probes", {}).get("*", []):
                draw_overlay(ax, spec, base, max(probes["time"]))
        for t, v, label in extra.get(probe, []):
            ax.plot(t, v, "o", ms=3, label=label)
        ax.set_ylabel(labels.get(probe, probe))
        ax.set_xlabel("time t (s)")
        ax.set_xlim(0.0, max(probes["time"]))
        ax.grid(True, alpha=0.3)
        handles, legend = ax.get_legend_handles_labels()
        secondary = refs.get("secondary") if refs else None
        if secondary:
            curve = read_curve(secondary, base)
            if curve:
                ax2 = ax.twinx()
                t_end = max(probes["time"])
                t, v = zip(*[(a, b) for a, b in zip(*curve) if a <= t_end] or [(0.0, 0.0)])
                ax2.plot(t, v, color="tab:red", lw=0.8, alpha=0.6)
                ax2.set_ylabel(secondary["label"], color="tab:red")
                ax2.tick_params(axis="y", colors="tab:red")
                handles += ax2.get_lines()
                legend += [secondary["label"]]
        ax.legend(handles, legend, loc="best", fontsize=7)

    def save(fig, path):
        """Title on top, plot.json's source in small print at the bottom, then the PNG."""
        height = fig.get_figheight()
        fig.suptitle(title + (f" (references: data/ref/{name}/plot.json)" if refs else ""),
                     fontsize=9)
        lines = textwrap.wrap(source, 150)
        if lines:
            fig.text(0.01, 0.005, "\n".join(lines), fontsize=6, va="bottom", color="0.3")
        fig.tight_layout(rect=(0, (0.1 * len(lines) + 0.05) / height, 1, 1 - 0.3 / height))
        fig.savefig(path, dpi=100)
        plt.close(fig)
        print(f"plot: {path}")

    fig, axes = plt.subplots(len(names), 1, figsize=(9, 3.2 * len(names) + 1.0), squeeze=False)
    for ax, probe in zip(axes[:, 0], names):
        panel(ax, probe)
    save(fig, os.path.join(args.dir, "probes.png"))
    for probe in names:
        fig, ax = plt.subplots(figsize=(9, 5.0))
        panel(ax, probe)
        save(fig, os.path.join(args.dir, f"probe_{probe}.png"))


if __name__ == "__main__":
    main()
