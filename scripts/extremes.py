"""Stability of the coupled dam break with an elastic obstacle at the extremes (issue 7).

Short runs of data/scenes/dam_break_elastic_obstacle.yaml (coarse, to --end): the obstacle 100x
stiffer and 10x softer, structure/fluid density ratio 1 down to 0.01, Courant numbers 0.05-0.5 (the
coupled scene has a fixed dt, so dt = C l0 / c), the coarsest and a finer resolution, each with
several coupling schemes. Every case runs through the Python module fsi (1 thread, in a child
process, two at a time; sweep.run_in_child) into OUT/CASE and
reports `completed` or how it stopped: the run's exit status and run.json message (or the last line
of its output when it left no run.json), or `timed out` past --timeout. A case with a run.json or a
timeout marker is not run again, so the script resumes. The stability map goes to OUT/table.md and,
with --doc, into a `<!-- sweep:NAME begin/end -->` block of a Markdown file.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep import ROOT, SCHEMES, read_probe, run_in_child, run_plan, status, write_doc  # noqa: E402

SCENE = "data/scenes/dam_break_elastic_obstacle.yaml"
SOUND_SPEED = 17.1  # m/s, the scene's c: Courant number C = c dt / l0
E, RHO_S = 1.0e6, 2500.0  # the scene's obstacle


def conditions(l0, dt, fine_l0, fine_dt):
    """(name, overrides, schemes) of each extreme; the base case is the scene at l0, dt."""
    base = [f"fluid.l0={l0}", "time.courant=null"]  # the scene is Courant-stepped
    at = [f"time.dt={dt}"]
    few = ["css", "bgs_aitken", "bgs_iqn"]
    out = [
        ("base", base + at, few),
        ("E_x100", base + at + [f"structures[0].material.youngs_modulus={100 * E:g}"], few),
        ("E_x0.1", base + at + [f"structures[0].material.youngs_modulus={0.1 * E:g}"], few),
        ("rho_ratio_1", base + at + ["structures[0].material.density=1000"], few),
        ("rho_ratio_0.5", base + at + ["structures[0].material.density=500"], list(SCHEMES)),
        ("rho_ratio_0.1", base + at + ["structures[0].material.density=100"], few),
        ("rho_ratio_0.01", base + at + ["structures[0].material.density=10"], few),
    ]
    for courant in (0.05, 0.2, 0.5):
        dt_c = courant * l0 / SOUND_SPEED
        out.append((f"courant_{courant}", base + [f"time.dt={dt_c:.3g}"], few))
    dt_c = 0.5 * l0 / SOUND_SPEED
    for ratio in (0.1, 0.01):
        out.append((f"rho_ratio_{ratio}_courant_0.5", base + [
            f"time.dt={dt_c:.3g}", f"structures[0].material.density={1000 * ratio:g}"], few))
    out.append(("fine", [f"fluid.l0={fine_l0}", "time.courant=null", f"time.dt={fine_dt}"], few))
    return out


def run_case(out, name, overrides, timeout):
    case_dir = os.path.join(out, name)
    marker = case_dir + ".timeout"
    if status(case_dir) is not None or os.path.exists(marker):
        return name, "skipped (ran before)"
    code = run_in_child(os.path.join(ROOT, SCENE), case_dir, overrides, timeout)
    if code is None:
        with open(marker, "w") as f:
            f.write(f"{timeout}\n")
        return name, "timed out"
    with open(case_dir + ".exit", "w") as f:
        f.write(f"{code}\n")
    return name, f"exit {code}"


def last_line(path):
    try:
        with open(path) as f:
            lines = [line.strip() for line in f if line.strip()]
        return lines[-1] if lines else ""
    except OSError:
        return ""


def row(out, name, overrides, timeout):
    case_dir = os.path.join(out, name)
    settings = ", ".join(o for o in overrides if not o.startswith("time.end="))
    r = status(case_dir)
    if r is None:
        if os.path.exists(case_dir + ".timeout"):
            return (f"| {name} | {settings} | timed out after {timeout:.0f} s "
                    f"(last: {last_line(case_dir + '.log')}) | | | | |")
        if os.path.exists(case_dir + ".exit"):
            code = last_line(case_dir + ".exit")
            return (f"| {name} | {settings} | **stopped, exit {code}, no run.json**: "
                    f"{last_line(case_dir + '.log')} | | | | |")
        return f"| {name} | {settings} | not run | | | | |"
    c = r.get("coupling", {})
    iters = f"{c.get('iterations_mean', 0):.2f} / {c.get('iterations_max', 0)}"
    if c.get("unconverged_steps"):
        iters += f" ({c['unconverged_steps']} unconverged)"
    peak = ""
    try:
        _, v = read_probe(os.path.join(case_dir, "probes.csv"), "corner_x")
        peak = f"{max(v):.4g} / {min(v):.3g}"
    except (OSError, ValueError):
        pass
    if r["status"] == "completed":
        result = "stable (completed)"
    else:
        code = last_line(case_dir + ".exit")
        msg = r.get("message", "").replace("|", "/")
        result = f"**failed, exit {code}, t = {r['simulated_time']:.4g} s**: {msg}"
    return (f"| {name} | {settings} | {result} | {r['wall_seconds']:.0f} | {r['steps']} | "
            f"{iters} | {peak} |")


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("out", help="output directory (one subdirectory per case)")
    p.add_argument("--l0", type=float, default=5.84e-3, help="coarse spacing, m")
    p.add_argument("--dt", type=float, default=1e-5, help="time step at --l0, s")
    p.add_argument("--fine-l0", type=float, default=2.92e-3, help="finer spacing, m")
    p.add_argument("--fine-dt", type=float, default=5e-6, help="time step at --fine-l0, s")
    p.add_argument("--end", type=float, default=0.15, help="end time, s")
    p.add_argument("--timeout", type=float, default=1200, help="wall seconds per case")
    p.add_argument("--only", help="comma-separated condition names to run")
    p.add_argument("--jobs", type=int, default=2, help="cases run at once (1 thread each)")
    p.add_argument("--doc", help="Markdown file whose sweep:NAME block gets the map")
    p.add_argument("--name", default="extremes", help="block name in --doc")
    p.add_argument("--dry-run", action="store_true", help="list the cases and stop")
    args = p.parse_args()

    plan = []
    for cond, overrides, schemes in conditions(args.l0, args.dt, args.fine_l0, args.fine_dt):
        if args.only and cond not in args.only.split(","):
            continue
        for scheme in schemes:
            plan.append((f"{cond}_{scheme}",
                         [f"time.end={args.end}", "output.interval=0.005"] + overrides +
                         SCHEMES[scheme]))
    if not run_plan(plan, args, lambda n, o: run_case(args.out, n, o, args.timeout), "extremes"):
        return
    lines = ["| case | settings | result | wall s | steps | iterations mean / max | "
             "corner_x max / min (m) |", "|---|---|---|---|---|---|---|"]
    lines += [row(args.out, n, o, args.timeout) for n, o in plan]
    table = "\n".join(lines) + "\n"
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(table)
    print(table, end="")
    if args.doc:
        write_doc(args.doc, args.name, table)


if __name__ == "__main__":
    main()
