#!/usr/bin/python3
"""Runs every shipped scene (and the coupled ones under BGS with Aitken and IQN-ILS) to a short end
time with two fsi binaries and compares the results: probes.csv byte for byte, and the iteration
columns of coupling.csv (step, time, dt, iterations, residuals, omega, converged). Where a byte
differs, prints the largest relative difference of any probe value. Exit status 1 if any case
differs, 2 on bad arguments.

  scripts/compare_scenes --base OLD/fsi --new build/apps/fsi --out out/compare [--end 0.004]
"""
import argparse, csv, pathlib, subprocess, sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
COUPLING_COLUMNS = ["step", "time", "dt", "iterations", "residual_initial", "residual_final",
                    "omega", "converged"]


def cases():
    for scene in sorted((ROOT / "data" / "scenes").glob("*.yaml")):
        yield scene.stem, scene, []
        if "scheme:" in scene.read_text():
            yield scene.stem + "+bgs_aitken", scene, ["coupling.scheme=bgs",
                                                     "coupling.acceleration=aitken"]
            yield scene.stem + "+bgs_iqn", scene, ["coupling.scheme=bgs",
                                                  "coupling.acceleration=iqn-ils"]


def run(fsi, scene, sets, out, end, threads):
    cmd = [str(fsi), "run", str(scene), "--out", str(out), "--threads", str(threads),
           "--set", f"time.end={end}", "--set", f"output.interval={end / 4}"]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    return r.returncode, r.stderr.strip().splitlines()[-1:] if r.stderr else []


def coupling_rows(path):
    if not path.exists():
        return None
    with open(path) as f:
        return [[row[c] for c in COUPLING_COLUMNS] for row in csv.DictReader(f)]


def max_relative(a, b):
    worst = 0.0
    ra, rb = list(csv.reader(open(a))), list(csv.reader(open(b)))
    if len(ra) != len(rb):
        return float("inf")
    for x, y in zip(ra[1:], rb[1:]):
        for u, v in zip(x, y):
            u, v = float(u), float(v)
            if u != v:
                worst = max(worst, abs(u - v) / max(abs(u), abs(v)))
    return worst


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--base", required=True, type=pathlib.Path)
    p.add_argument("--new", required=True, type=pathlib.Path)
    p.add_argument("--out", required=True, type=pathlib.Path)
    p.add_argument("--end", type=float, default=0.004, help="end time of every case, s")
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--only", help="run only cases whose name contains this")
    a = p.parse_args()
    for exe in (a.base, a.new):
        if not exe.is_file():
            print(f"compare_scenes: {exe}: no such executable", file=sys.stderr)
            return 2
    failed = 0
    print(f"{'case':52} {'probes.csv':>12} {'coupling.csv':>14} {'max rel diff':>13}")
    for name, scene, sets in cases():
        if a.only and a.only not in name:
            continue
        dirs = {}
        for tag, exe in (("base", a.base), ("new", a.new)):
            d = a.out / tag / name
            if not (d / "run.json").exists():
                code, err = run(exe, scene, sets, d, a.end, a.threads)
                if code != 0:
                    print(f"{name:52} {tag} exited {code}: {' '.join(err)}")
            dirs[tag] = d
        pb, pn = dirs["base"] / "probes.csv", dirs["new"] / "probes.csv"
        same_probes = pb.exists() and pn.exists() and pb.read_bytes() == pn.read_bytes()
        cb, cn = coupling_rows(dirs["base"] / "coupling.csv"), coupling_rows(dirs["new"] / "coupling.csv")
        same_coupling = cb == cn
        rel = 0.0 if same_probes else (max_relative(pb, pn) if pb.exists() and pn.exists() else float("inf"))
        coupling = "-" if cb is None and cn is None else ("identical" if same_coupling else "DIFFER")
        print(f"{name:52} {'identical' if same_probes else 'DIFFER':>12} {coupling:>14} {rel:13.3g}")
        failed += (not same_probes) or (not same_coupling)
    print(f"{failed} case(s) differ")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
