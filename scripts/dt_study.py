"""Time-step study (issues 21, 48): a scene at Courant numbers on c (time.courant), each case
against the smallest Courant number run (the dt -> 0 limit) or --reference's, with the stability
boundary, the steps and the wall and CPU seconds per simulated second.

Each case is one run of build/apps/fsi (1 thread) into OUT/C_x, its CPU seconds (user + system)
into OUT/C_x/cpu_seconds; a completed case is not run again, so an interrupted study resumes.
The table goes to OUT/table.md and, with --doc, between `<!-- sweep:NAME begin/end -->`
markers of a Markdown file; the error against wall time goes to a PNG.
"""
import argparse
import json
import math
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import dam_break_front  # noqa: E402
import h5py  # noqa: E402
from sweep import ROOT, add_run_arguments, read_probe, run_plan, status, write_doc  # noqa: E402

FSI = os.path.join(os.environ.get("BUILD_DIR", os.path.join(ROOT, "build")), "apps", "fsi")

# What each scene is measured by. The rigid dam break: the surge front x(t), at the output
# times where the reference front has not yet reached `front_until` (the right wall is at
# 0.8 m); its 3-D slab (issue 43) likewise. The elastic obstacle: the upper-left corner's largest rightward deflection and when.
# Issue 48's EMPS peer case (column width a = 1 m): the front at the frames with
# T = t sqrt(2 g / a) in `T_window`, Martin & Moyce's acceptance figures (scripts/dam_break_front)
# and the density error of the interior (`density`, from fields.h5).
STUDIES = {
    "dam_break_rigid": {
        "file": "data/scenes/dam_break_rigid.yaml",
        "probe": "front",
        "metric": "front",
        "front_until": 0.7,
    },
    "dam_break_slab_emps_3d": {
        "file": "data/scenes/dam_break_slab_emps_3d.yaml",
        "probe": "front",
        "metric": "front",
        "front_until": 0.7,
    },
    "elastic_obstacle": {
        "file": "data/scenes/dam_break_elastic_obstacle.yaml",
        "probe": "corner_x",
        "metric": "peak",
    },
    "peer_dam_break_emps": {
        "file": "bench/peers/sphinxsys/dam_break_emps.yaml",
        "probe": "front",
        "metric": "front",
        "a": 1.0,
        "T_window": (0.5, 2.5),
        "density": True,
        "end": 0.65,
    },
}


def run_timed(scene_file, out, name, overrides):
    """One case through the fsi command (1 thread) into OUT/NAME, its log in OUT/NAME.log and
    its CPU seconds (user + system, from wait4) in OUT/NAME/cpu_seconds; a completed case is not
    run again, one that stopped or was cut short starts again (its files are replaced)."""
    case_dir = os.path.join(out, name)
    done = status(case_dir)
    if done and done.get("status") == "completed":
        return name, "skipped (completed before)"
    cmd = [FSI, "run", os.path.join(ROOT, scene_file), "--out", case_dir, "--threads", "1",
           "--overwrite"]
    for o in overrides:
        cmd += ["--set", o]
    with open(case_dir + ".log", "w") as log:
        child = subprocess.Popen(cmd, stdout=log, stderr=log)
        _, code, usage = os.wait4(child.pid, 0)
    if os.path.isdir(case_dir):
        with open(os.path.join(case_dir, "cpu_seconds"), "w") as f:
            f.write(f"{usage.ru_utime + usage.ru_stime:.2f}\n")
    return name, f"exit {os.waitstatus_to_exitcode(code)}"


def cpu_seconds(case_dir):
    try:
        with open(os.path.join(case_dir, "cpu_seconds")) as f:
            return float(f.read())
    except (OSError, ValueError):
        return math.nan


def front_error(study, case_dir, ref_dir):
    """Mean |x - x_ref| / x_ref of the front over the compared times (%), and the largest gap
    (the front is its leading particle: a jump of one l0 is noise, not time-step error); with a
    column width `a`, Martin & Moyce's acceptance figures of the case."""
    t, x = read_probe(os.path.join(case_dir, "probes.csv"), study["probe"])
    tr, xr = read_probe(os.path.join(ref_dir, "probes.csv"), study["probe"])
    ref = {round(s, 9): v for s, v in zip(tr, xr)}
    scale = math.sqrt(2 * 9.81 / study["a"]) if "a" in study else 0.0
    lo, hi = study.get("T_window", (0.0, math.inf))
    rel, worst = [], (0.0, 0.0)
    for s, v in zip(t, x):
        r = ref.get(round(s, 9))
        if r is None or r > study.get("front_until", math.inf) or not lo <= s * scale <= hi:
            continue
        rel.append(abs(v - r) / r)
        worst = max(worst, (abs(v - r) / r, abs(v - r)))
    if not rel:
        raise SystemExit(f"dt_study: {case_dir}: no frame at the reference's times (a fixed "
                         "time.dt must divide output.interval)")
    figure = f"largest front gap {1e3 * worst[1]:.2f} mm ({100 * worst[0]:.2f} %)"
    if "a" in study:
        m = dam_break_front.measure(case_dir, study["probe"], a=study["a"])
        figure += (f"; Martin & Moyce: shifted {100 * m['worst']:.1f} % (dT {m['shift']:.3f}), "
                   f"speed {100 * m['speed_diff']:+.1f} %")
    return 100 * sum(rel) / len(rel), figure


def density_error(case_dir):
    """Largest |n - n0| / n0 = |p| / (rho c^2) (eq. 15) over the interior (not free-surface)
    particles of every frame, in %, and the mean over the frames of each frame's largest."""
    with open(os.path.join(case_dir, "run.json")) as f:
        o = json.load(f)["fluid"]["options"]
    rho_c2 = o["density"] * o["sound_speed"] ** 2
    worst = []
    with h5py.File(os.path.join(case_dir, "fields.h5"), "r") as h:
        for frame in h["frames"].values():
            g = frame["particles"]
            inside = g["free_surface"][:] == 0
            if inside.any():
                worst.append(abs(g["pressure"][:][inside]).max() / rho_c2)
    return 100 * max(worst), 100 * sum(worst) / len(worst)


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
    p.add_argument("--end", type=float, help="end time, s (default: the study's, else 0.3)")
    p.add_argument("--reference", help="the reference case's directory (default: the smallest "
                   "Courant number's case of this study)")
    add_run_arguments(p, "dt_study.png", "dt_STUDY")
    args = p.parse_args()

    study = STUDIES[args.study]
    args.end = args.end or study.get("end", 0.3)
    courants = sorted(float(c) for c in args.courants.split(","))
    plan = [(f"C_{c:g}", [f"time={{end: {args.end}, courant: {c}}}"] + args.set)
            for c in courants]
    if not run_plan(plan, args, lambda n, o: run_timed(study["file"], args.out, n, o), "dt_study"):
        return

    ref_dir = args.reference or os.path.join(args.out, plan[0][0])
    ref_name = os.path.basename(os.path.normpath(ref_dir)) if args.reference else plan[0][0]
    ref = status(ref_dir)
    if not ref or ref.get("status") != "completed":
        raise SystemExit(f"dt_study: the reference case {ref_dir} did not complete")
    error = front_error if study["metric"] == "front" else peak_error
    density = ("density error: largest / mean of the frames' largest | "
               if study.get("density") else "")
    lines = [f"| Courant | result | steps | steps per 0.1 s | wall s | CPU s "
             f"| wall s per simulated s | error vs {ref_name} | order | {density}figure |",
             "|---|---|---|---|---|---|---|---|---|---|" + ("---|" if density else "")]
    points, last = [], None
    for c, (name, _) in zip(courants, plan):
        case_dir = os.path.join(args.out, name)
        r = status(case_dir)
        if r is None:
            lines.append(f"| {c:g} | not run | | | | | | | | |{' |' if density else ''}")
            continue
        per_s = r["wall_seconds"] / max(r["simulated_time"], 1e-300)
        cells = (f"{r['steps']} | {0.1 * r['steps'] / max(r['simulated_time'], 1e-300):.0f} | "
                 f"{r['wall_seconds']:.0f} | {cpu_seconds(case_dir):.0f} | {per_s:.0f}")
        if r["status"] != "completed":
            msg = r.get("message", "").replace("|", "/")
            lines.append(f"| {c:g} | stopped at t = {r['simulated_time']:.4g} s: {msg} | "
                         f"{cells} | | |{' |' if density else ''} |")
            continue
        is_ref = os.path.samefile(case_dir, ref_dir)
        e, figure = error(study, case_dir, ref_dir)
        order = ""
        if not is_ref and last and last[1] > 0 and e > 0:
            order = f"{math.log(e / last[1]) / math.log(c / last[0]):.2f}"
        if not is_ref:
            last = (c, e)
            points.append((per_s, e, c))
        rho = ""
        if density:
            worst, mean = density_error(case_dir)
            rho = f"{worst:.2f} % / {mean:.2f} % | "
        lines.append(f"| {c:g} | completed | {cells} "
                     f"| {'reference' if is_ref else f'{e:.2f} %'} | {order} | {rho}{figure} |")
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
