"""Speed-accuracy sweep of a coupled scene (issues 7, 20): fluid/solid pair, resolution,
coupling scheme, time step.

Each case is one run through the Python module fsi (1 thread, in a child process, two cases at a
time by default) into OUT/CASE; a case whose run.json says `completed` is not run again, so an
interrupted sweep resumes. The table
(wall seconds, steps, coupling iterations, error against the scene's reference figure) goes to
OUT/table.md and, with --doc, between `<!-- sweep:NAME begin/end -->` markers of a Markdown
file; the error against wall time goes to a PNG (the Pareto front).
"""
import argparse
import concurrent.futures
import json
import multiprocessing
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The module fsi as built in BUILD_DIR (default build/): BUILD_DIR/python/fsi.
sys.path.insert(0, os.path.join(os.environ.get("BUILD_DIR", os.path.join(ROOT, "build")), "python"))
import fsi  # noqa: E402

# What each scene is measured by. The dam break: the upper-left corner's largest rightward
# deflection against the centre of the published band 0.040-0.050 m (issue 16; issue 7 had
# 0.040-0.055 m). The plate: the mean mid-span deflection over the last 0.5 s against the
# converged plane-strain plate's -7.066e-5 m (static FE ladder, CalculiX CPE6; the
# Euler-Bernoulli strip's -6.85e-5 m is not what the 2-D plate converges to).
SCENES = {
    "dam_break": {
        "file": "data/scenes/dam_break_elastic_obstacle.yaml",
        "probe": "corner_x",
        "metric": "max",
        "reference": 0.045,
        "what": "largest corner_x vs 0.045 m (centre of 0.040-0.050 m)",
    },
    "hydrostatic_plate": {
        "file": "data/scenes/hydrostatic_plate.yaml",
        "probe": "mid_span",
        "metric": "mean_last_0.5",
        "reference": -7.066e-5,
        "what": "mean mid_span over the last 0.5 s vs -7.066e-5 m (plane strain)",
    },
}

# Fluid/solid pairs (issue 20): name -> the scene overrides that choose it and the keys that set
# its resolution. A level is the fluid's spacing l0 (key "l0") and the coupling step; a TL-SPH
# structure gets dp_S = l0 / 2 (key "dp"; the RKGC paper's dp_F = 2 dp_S). The first pair of
# --pairs also runs the coupling variants and time-step factors at the middle level.
# The Walhorn scene keeps the EMPS keys at its top level (scripts and tests set fluid.l0 on it),
# so its SPH pairs replace the fluid block (the SPH run of docs/validation-history.md: RKGC,
# c0 34.2 m/s).
WALHORN_SPH = ("fluid={type: sph, density: 1000.0, viscosity: 1.0e-6, l0: 1.46e-3, "
               "sound_speed: 34.2, regions: [{min: [0.0, 0.0], max: [0.146, 0.292]}], "
               "domain: {min: [-0.02, -0.02], max: [0.604, 0.65]}}")
PAIRS = {
    "dam_break": {
        "emps+fem": {"set": [], "l0": "fluid.l0"},
        "sph+fem": {"set": [WALHORN_SPH], "l0": "fluid.l0"},
        "emps+tlsph": {"set": ["structures[0].type=tlsph"], "l0": "fluid.l0",
                       "dp": "structures[0].tlsph.dp"},
        "sph+tlsph": {"set": [WALHORN_SPH, "structures[0].type=tlsph"], "l0": "fluid.l0",
                      "dp": "structures[0].tlsph.dp"},
    },
    "hydrostatic_plate": {
        "emps+fem": {"set": ["fluid.type=emps", "structures[0].type=fem"], "l0": "fluid.emps.l0"},
        "sph+fem": {"set": ["fluid.type=sph", "structures[0].type=fem"], "l0": "fluid.sph.l0"},
        "emps+tlsph": {"set": ["fluid.type=emps", "structures[0].type=tlsph"],
                       "l0": "fluid.emps.l0", "dp": "structures[0].tlsph.dp"},
        "sph+tlsph": {"set": ["fluid.type=sph", "structures[0].type=tlsph"],
                      "l0": "fluid.sph.l0", "dp": "structures[0].tlsph.dp"},
    },
}

# Coupling variants: name -> scene overrides.
SCHEMES = {
    "css": ["coupling.scheme=css", "coupling.predictor=none"],
    "css_pred": ["coupling.scheme=css", "coupling.predictor=second_order"],
    "bgs_none": ["coupling.scheme=bgs", "coupling.acceleration=none"],
    "bgs_constant": ["coupling.scheme=bgs", "coupling.acceleration=constant"],
    "bgs_aitken": ["coupling.scheme=bgs", "coupling.acceleration=aitken"],
    "bgs_iqn": ["coupling.scheme=bgs", "coupling.acceleration=iqn-ils"],
}


def read_probe(path, name):
    with open(path) as f:
        header = f.readline().strip().split(",")
        col = header.index(name)
        rows = [line.strip().split(",") for line in f if line.strip()]
    return [float(r[0]) for r in rows], [float(r[col]) for r in rows]


def measure(scene, case_dir):
    """(value, time of value or None) of the scene's figure from probes.csv."""
    t, v = read_probe(os.path.join(case_dir, "probes.csv"), scene["probe"])
    if scene["metric"] == "max":
        k = max(range(len(v)), key=v.__getitem__)
        return v[k], t[k]
    last = [x for s, x in zip(t, v) if s >= t[-1] - 0.5 - 1e-9]
    return sum(last) / len(last), None


def ladder(text, what):
    """--levels / --dts: one comma list for every pair, or per pair 'pair:a,b,c;pair:...'."""
    out = {}
    for part in text.split(";"):
        pair, _, values = part.rpartition(":")
        try:
            out[pair] = [float(x) for x in values.split(",")]
        except ValueError:
            sys.exit(f"sweep: --{what}: not a list of numbers: {values!r}")
    return out


def cases(args):
    """(name, overrides) of the plan: for each pair CSS over its levels (dt with them); for the
    first pair also every coupling variant at the middle level and CSS there with dt scaled.
    Names carry the pair when --pairs names more than the scene as it is."""
    pairs = args.pairs.split(",") if args.pairs else [""]
    known = PAIRS.get(args.scene, {})
    for pair in pairs:
        if pair and pair not in known:
            sys.exit(f"sweep: --pairs: {pair!r} is not one of {', '.join(known)}")
    levels_of, dts_of = ladder(args.levels, "levels"), ladder(args.dts, "dts")
    common = [f"time.end={args.end}"] + args.set
    out = []

    for n, pair in enumerate(pairs):
        levels, dts = levels_of.get(pair, levels_of.get("")), dts_of.get(pair, dts_of.get(""))
        if levels is None or dts is None or len(levels) != len(dts):
            sys.exit(f"sweep: --levels and --dts need the same number of entries for {pair!r}")
        spec = known.get(pair, {"set": [], "l0": "fluid.l0"})
        prefix = f"{pair}_" if pair else ""

        def add(name, l0, dt, scheme):
            keys = [f"{spec['l0']}={l0}"] + ([f"{spec['dp']}={l0 / 2:g}"] if "dp" in spec else [])
            out.append((prefix + name,
                        common + spec["set"] + keys + ["time.courant=null", f"time.dt={dt}"]
                        + SCHEMES[scheme]))

        for l0, dt in zip(levels, dts):
            add(f"l0_{l0:g}_dt_{dt:g}_css", l0, dt, "css")
        if n > 0:
            continue
        if args.middle is not None and args.middle not in levels:
            sys.exit(f"sweep: --middle {args.middle:g} is not one of --levels")
        mid = len(levels) // 2 if args.middle is None else levels.index(args.middle)
        for scheme in args.schemes.split(","):
            if scheme != "css":
                add(f"l0_{levels[mid]:g}_dt_{dts[mid]:g}_{scheme}", levels[mid], dts[mid], scheme)
        for factor in [float(x) for x in args.dt_factors.split(",") if x]:
            dt = dts[mid] * factor
            add(f"l0_{levels[mid]:g}_dt_{dt:g}_css", levels[mid], dt, "css")
    return out


def status(case_dir):
    try:
        with open(os.path.join(case_dir, "run.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def _run_child(scene_file, case_dir, overrides, log_path):
    """One case in a child process: fsi.Scene.run (replacing an earlier attempt's files) with its
    log and messages in log_path; the exit status is the command's (0 completed, 2 bad input,
    3 stopped, 128 + signal)."""
    with open(log_path, "w") as log:
        os.dup2(log.fileno(), 1)
        os.dup2(log.fileno(), 2)
    sys.stdout = os.fdopen(1, "w", buffering=1)
    sys.stderr = os.fdopen(2, "w", buffering=1)
    try:
        fsi.load(scene_file, overrides).run(out=case_dir, threads=1, overwrite=True, quiet=False)
    except fsi.InputError as e:
        print(e, file=sys.stderr)
        sys.exit(2)
    except fsi.RunError as e:
        print(f"run stopped: {e}", file=sys.stderr)
        sys.exit(3)
    except fsi.Interrupted as e:
        print(e, file=sys.stderr)
        sys.exit(128 + e.signal)


def run_in_child(scene_file, case_dir, overrides, timeout=None):
    """Runs a case (case_dir.log gets its output); its exit status, or None past timeout s
    (the child is killed)."""
    child = multiprocessing.get_context("spawn").Process(
        target=_run_child, args=(scene_file, case_dir, overrides, case_dir + ".log"))
    child.start()
    child.join(timeout)
    if child.exitcode is None:
        child.kill()
        child.join()
        return None
    return child.exitcode


def run_case(scene_file, out, name, overrides):
    case_dir = os.path.join(out, name)
    done = status(case_dir)
    if done and done.get("status") == "completed":
        return name, "skipped (completed before)"
    # A case that stopped or was cut short before starts again (its files are replaced).
    code = run_in_child(os.path.join(ROOT, scene_file), case_dir, overrides)
    return name, f"exit {code}"


def row(scene, out, name, overrides):
    r = status(os.path.join(out, name))
    # A replaced fluid block (WALHORN_SPH) is named, not printed.
    settings = ", ".join("fluid={sph block of sweep.py}" if o.startswith("fluid={") else o
                         for o in overrides if not o.startswith("time.end="))
    if r is None:
        return None, f"| {name} | {settings} | not run | | | | | |"
    c = r.get("coupling", {})
    iters = f"{c.get('iterations_mean', 0):.2f} / {c.get('iterations_max', 0)}"
    if c.get("unconverged_steps"):
        iters += f" ({c['unconverged_steps']} unconverged)"
    if r["status"] != "completed":
        msg = r.get("message", "").replace("|", "/")
        return None, (f"| {name} | {settings} | failed at t = {r['simulated_time']:.4g} s: {msg} "
                      f"| {r['wall_seconds']:.0f} | {r['steps']} | {iters} | | |")
    value, when = measure(scene, os.path.join(out, name))
    error = abs(value - scene["reference"]) / abs(scene["reference"])
    at = f" at {when:.3f} s" if when is not None else ""
    point = (r["wall_seconds"], error, name)
    return point, (f"| {name} | {settings} | completed | {r['wall_seconds']:.0f} | {r['steps']} | "
                   f"{iters} | {value:.4g}{at} | {100 * error:.1f} % |")


def pair_of(name):
    """The pair a case name starts with ('' for a sweep without --pairs)."""
    head = name.split("_", 1)[0]
    return head if "+" in head else ""


def pareto_png(points, path, title):
    """Error against wall time, one Pareto front per pair (its colour)."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    groups = {}
    for point in points:
        groups.setdefault(pair_of(point[2]), []).append(point)
    for k, (pair, group) in enumerate(sorted(groups.items())):
        colour = f"C{k}"
        for wall, error, name in group:
            ax.plot(wall, 100 * error, "o", color=colour)
            ax.annotate(name[len(pair) + 1:] if pair else name, (wall, 100 * error), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
        front, best = [], float("inf")
        for wall, error, _ in sorted(group):
            if error < best:
                front.append((wall, 100 * error))
                best = error
        if front:
            ax.step(*zip(*front), where="post", color=colour, alpha=0.4)
            ax.plot(*zip(*front), "s", mfc="none", ms=11, color=colour,
                    label=f"{pair or 'Pareto'} front")
    if groups:
        ax.legend(fontsize=8, loc="best")
    ax.set_xscale("log")
    ax.margins(x=0.3, y=0.1)
    ax.set_xlabel("wall time (s, 1 thread)")
    ax.set_ylabel("error vs reference (%)")
    ax.set_title(title, fontsize=9)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def write_doc(path, section, text):
    begin, end = f"<!-- sweep:{section} begin -->", f"<!-- sweep:{section} end -->"
    with open(path) as f:
        doc = f.read()
    block = f"{begin}\n{text}{end}"
    if begin in doc and end in doc:
        doc = doc[: doc.index(begin)] + block + doc[doc.index(end) + len(end):]
    else:
        doc = doc.rstrip("\n") + "\n\n" + block + "\n"
    with open(path, "w") as f:
        f.write(doc)


def add_run_arguments(p, png, name):
    """The options a resumable study shares (sweep, dt_study): overrides, parallel cases, the
    plot (default OUT/png), the Markdown block (default name) and --dry-run."""
    p.add_argument("--set", action="append", default=[], help="extra scene override for all")
    p.add_argument("--jobs", type=int, default=2, help="cases run at once (1 thread each)")
    p.add_argument("--png", help=f"error-vs-wall-time plot (default OUT/{png})")
    p.add_argument("--doc", help="Markdown file whose sweep:NAME block gets the table")
    p.add_argument("--name", help=f"block name in --doc (default: {name})")
    p.add_argument("--dry-run", action="store_true", help="list the cases and stop")


def run_plan(plan, args, run, label):
    """Lists the plan's cases (--dry-run, returns False) or runs them, args.jobs at once."""
    if args.dry_run:
        for name, overrides in plan:
            print(name, " ".join(overrides))
        return False
    os.makedirs(args.out, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        jobs = [pool.submit(run, name, overrides) for name, overrides in plan]
        for job in concurrent.futures.as_completed(jobs):
            name, what = job.result()
            print(f"{label}: {name}: {what}", flush=True)
    return True


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", choices=sorted(SCENES))
    p.add_argument("out", help="output directory (one subdirectory per case)")
    p.add_argument("--pairs", help="fluid+solid pairs, e.g. emps+fem,sph+tlsph (default: the "
                   "scene as it is); choices per scene: " +
                   "; ".join(f"{k}: {', '.join(v)}" for k, v in PAIRS.items()))
    p.add_argument("--levels", default="5.84e-3,4.13e-3,2.92e-3",
                   help="l0 values, m; per pair: 'emps+fem:0.04,0.02;sph+fem:0.05,0.025'")
    p.add_argument("--dts", default="1e-5,7e-6,5e-6", help="time step per level, s (per pair "
                   "as --levels)")
    p.add_argument("--end", type=float, default=0.3, help="end time, s")
    p.add_argument("--schemes", default=",".join(SCHEMES), help="variants at the middle level")
    p.add_argument("--dt-factors", default="2,4", help="CSS at the middle level with dt x these")
    p.add_argument("--middle", type=float, help="the level (one of --levels) for the variants "
                   "and dt factors (default: the middle one)")
    add_run_arguments(p, "pareto.png", "the scene")
    args = p.parse_args()

    scene = SCENES[args.scene]
    plan = cases(args)
    if not run_plan(plan, args, lambda n, o: run_case(scene["file"], args.out, n, o), "sweep"):
        return

    lines = ["| case | settings | result | wall s | steps | iterations mean / max | "
             f"figure | error |", "|---|---|---|---|---|---|---|---|"]
    points = []
    for name, overrides in plan:
        point, line = row(scene, args.out, name, overrides)
        lines.append(line)
        if point:
            points.append(point)
    png = args.png or os.path.join(args.out, "pareto.png")
    pareto_png(points, png, f"{args.scene}: {scene['what']}, to t = {args.end} s")
    table = "\n".join(lines) + "\n"
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(table)
    print(table, end="")
    print(f"sweep: plot {png}")
    if args.doc:
        write_doc(args.doc, args.name or args.scene, table)


if __name__ == "__main__":
    main()
