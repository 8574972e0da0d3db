"""Time-step study (issue 21): a scene at Courant numbers on c (time.courant), each case against
the smallest Courant number run (the dt -> 0 limit), with the stability boundary and the wall
seconds per simulated second.

Each case is one run through the Python module fsi (1 thread, in a child process) into OUT/C_x;
a completed case is not run again, so an interrupted study resumes (scripts/sweep.py's runner).
The table goes to OUT/table.md and, with --doc, between `<!-- sweep:NAME begin/end -->`
markers of a Markdown file; the error against wall time goes to a PNG.
"""
import argparse
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from sweep import (add_run_arguments, read_probe, run_case, run_plan, status,  # noqa: E402
                   write_doc)

# What each scene is measured by. The rigid dam break: the surge front x(t), at the output
# times where the reference front has not yet reached `front_until` (the right wall is at
# 0.8 m). The elastic obstacle: the upper-left corner's largest rightward deflection and when.
STUDIES = {
    "dam_break_rigid": {
        "file": "data/scenes/dam_break_rigid.yaml",
        "probe": "front",
        "metric": "front",
        "front_until": 0.7,
    },
    "elastic_obstacle": {
        "file": "data/scenes/dam_break_elastic_obstacle.yaml",
        "probe": "corner_x",
        "metric": "peak",
    },
}


def front_error(study, case_dir, ref_dir):
    """Mean |x - x_ref| / x_ref of the front over the compared times (%), and the largest gap
    (the front is its leading particle: a jump of one l0 is noise, not time-step error)."""
    t, x = read_probe(os.path.join(case_dir, "probes.csv"), study["probe"])
    tr, xr = read_probe(os.path.join(ref_dir, "probes.csv"), study["probe"])
    ref = {round(s, 9): v for s, v in zip(tr, xr)}
    rel, worst = [], 0.0
    for s, v in zip(t, x):
        r = ref.get(round(s, 9))
        if r is None or r > study["front_until"]:
            continue
        rel.append(abs(v - r) / r)
        worst = max(worst, abs(v - r))
    return 100 * sum(rel) / len(rel), f"largest front gap {1e3 * worst:.2f} mm"


def peak(case_dir, probe):
    t, v = read_probe(os.path.join(case_dir, "probes.csv"), probe)
    k = max(range(len(v)), key=v.__getitem__)
    return v[k], t[k]


def peak_error(study, case_dir, ref_dir):
    """|peak - peak_ref| as % of peak_ref, and the peak with its time."""
    v, t = peak(case_dir, study["probe"])
    vr, tr = peak(ref_dir, study["probe"])
    return 100 * abs(v - vr) / abs(vr), f"peak {v:.4g} m at {t:.3f} s ({1e3 * (t - tr):+.0f} ms)"


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("study", choices=sorted(STUDIES))
    p.add_argument("out", help="output directory (one subdirectory per case)")
    p.add_argument("--courants", default="0.025,0.05,0.1,0.2,0.3,0.4,0.5,0.6,0.8",
                   help="Courant numbers on c; the smallest is the reference")
    p.add_argument("--end", type=float, default=0.3, help="end time, s")
    add_run_arguments(p, "dt_study.png", "dt_STUDY")
    args = p.parse_args()

    study = STUDIES[args.study]
    courants = sorted(float(c) for c in args.courants.split(","))
    plan = [(f"C_{c:g}", [f"time={{end: {args.end}, courant: {c}}}"] + args.set)
            for c in courants]
    if not run_plan(plan, args, lambda n, o: run_case(study["file"], args.out, n, o), "dt_study"):
        return

    ref_name = plan[0][0]
    ref_dir = os.path.join(args.out, ref_name)
    ref = status(ref_dir)
    if not ref or ref.get("status") != "completed":
        raise SystemExit(f"dt_study: the reference case {ref_name} did not complete")
    error = front_error if study["metric"] == "front" else peak_error
    lines = [f"| Courant | result | steps | wall s | wall s per simulated s | error vs {ref_name} "
             "| order | figure |", "|---|---|---|---|---|---|---|---|"]
    points, last = [], None
    for c, (name, _) in zip(courants, plan):
        r = status(os.path.join(args.out, name))
        if r is None:
            lines.append(f"| {c:g} | not run | | | | | | |")
            continue
        per_s = r["wall_seconds"] / max(r["simulated_time"], 1e-300)
        if r["status"] != "completed":
            msg = r.get("message", "").replace("|", "/")
            lines.append(f"| {c:g} | stopped at t = {r['simulated_time']:.4g} s: {msg} | "
                         f"{r['steps']} | {r['wall_seconds']:.0f} | {per_s:.0f} | | | |")
            continue
        e, figure = error(study, os.path.join(args.out, name), ref_dir)
        order = ""
        if name != ref_name and last and last[1] > 0 and e > 0:
            order = f"{math.log(e / last[1]) / math.log(c / last[0]):.2f}"
        if name != ref_name:
            last = (c, e)
            points.append((per_s, e, c))
        lines.append(f"| {c:g} | completed | {r['steps']} | {r['wall_seconds']:.0f} | {per_s:.0f} "
                     f"| {'reference' if name == ref_name else f'{e:.2f} %'} | {order} | {figure} |")
    table = "\n".join(lines) + "\n"
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(table)
    print(table, end="")

    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    if points:
        ax.loglog([q[0] for q in points], [max(q[1], 1e-3) for q in points], "o-")
        for per_s, e, c in points:
            ax.annotate(f"C = {c:g}", (per_s, max(e, 1e-3)), fontsize=8, xytext=(4, 3),
                        textcoords="offset points")
    ax.set_xlabel("wall seconds per simulated second (1 thread)")
    ax.set_ylabel(f"error vs {ref_name} (%)")
    ax.set_title(f"{args.study}: time-step study, to t = {args.end} s "
                 f"{' '.join(args.set)}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    png = args.png or os.path.join(args.out, "dt_study.png")
    fig.savefig(png, dpi=100)
    print(f"dt_study: plot {png}")
    if args.doc:
        write_doc(args.doc, args.name or f"dt_{args.study}", table)


if __name__ == "__main__":
    main()
