#!/usr/bin/python3
"""Runs the benchmark scenes in a tier and checks each run against its acceptance
(data/ref/<scene>/acceptance.yaml, scripts/check_acceptance).

usage: scripts/validate [--tier quick|standard|full] [--scene NAME]... [--pair FLUID+STRUCTURE|all]...
                        [--fsi build/apps/fsi] [--out out/validate-TIER] [--threads 1] [--jobs 1]
                        [--report FILE.md] [--update-regression] [--dry-run]

Tiers: quick (coarse versions and short windows of the cheap cases, with the regression
comparison against our committed runs; about 5 minutes on one thread), standard (the shipped
scenes exactly as shipped, to their end time), full (the paper resolutions and the convergence
pairs). --pair asks for another fluid x structure pair where the scene's acceptance offers it
(`all`: every pair offered; a criterion may compare two pairs' runs of a case). --jobs N runs N
cases at once, the longest first by the acceptance file's `minutes` estimates. Each case's run
directory (probes.csv, run.json, coupling.csv, probes.png, probe_<name>.png) is kept under
--out/<scene>/<case>[+<pair>]/. Prints a progress line
per case and a summary table at the end; --report writes it as Markdown with a section per case
(its plot, copied beside the report, and its command). --update-regression rewrites the
regression files (data/ref/<scene>/regression_quick.csv) from these runs instead of judging
them: only after a change of results that is understood and meant.
Exit status 1 if a case fails to run or a judged criterion fails, 2 on bad arguments.
"""
import argparse
import concurrent.futures
import csv
import datetime
import os
import shlex
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import acceptance  # noqa: E402
from acceptance import ROOT, AcceptanceError  # noqa: E402

REGRESSION_ROWS = 200


def plan(tier, scenes, pairs):
    """[(spec, case, pair)] of the tier, in scene order."""
    jobs = []
    for name in scenes:
        spec = acceptance.load(name)
        offered = [acceptance.default_pair(spec)] + list(spec.get("pairs") or {})
        for case in spec.get("cases", []):
            if tier not in case["tiers"]:
                continue
            wanted = pairs or [acceptance.default_pair(spec, case)]
            if "all" in wanted:
                wanted = [acceptance.default_pair(spec, case)] + [
                    p for p in offered if p != acceptance.default_pair(spec, case)]
            for pair in wanted:
                if pair != acceptance.default_pair(spec, case) and pair not in offered:
                    if pairs and "all" not in pairs:
                        print(f"validate: {name}: pair {pair} not offered (offered: "
                              f"{', '.join(offered)}), skipped")
                    continue
                jobs.append((spec, case, pair))
    return jobs


def run_dir(out, spec, case, pair):
    suffix = "" if pair == acceptance.default_pair(spec, case) else "+" + pair
    return os.path.join(out, spec["scene"], case["id"] + suffix)


def command(fsi, spec, case, pair, directory, threads):
    cmd = [fsi, "run", case["file"], "--out", directory, "--threads", str(threads), "--overwrite"]
    for s in acceptance.case_sets(spec, case, pair):
        cmd += ["--set", s]
    return cmd


def shown(cmd):
    return " ".join(shlex.quote(c) for c in cmd)


def write_regression(spec, case, run, directory):
    """The case's regression file from this run: the probes its regression criteria compare,
    at most REGRESSION_ROWS samples, with where it came from."""
    probes = sorted({c["quantity"]["probe"] for c in spec.get("criteria", [])
                     if c["quantity"]["measure"] == "regression"
                     and (not c.get("cases") or case["id"] in c["cases"])})
    path = os.path.join(os.path.dirname(spec["_path"]), case["regression"])
    rows = run.rows
    step = max(1, -(-len(rows) // REGRESSION_ROWS))
    kept = rows[::step]
    if kept[-1] is not rows[-1]:
        kept.append(rows[-1])
    with open(path, "w", newline="") as f:
        f.write(f"# Our own run of case {case['id']} (scripts/validate --tier quick), for the\n"
                f"# regression criteria of acceptance.yaml: fsi {run.info.get('git_revision', '?')},"
                f" {run.info.get('start', '?')}, {run.info.get('threads', '?')} thread(s);\n"
                f"# {'every sample' if step == 1 else f'one sample in {step}'} of "
                f"{directory}/probes.csv.\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["time"] + probes)
        for r in kept:
            w.writerow([r["time"]] + [r[p] for p in probes])
    return path


def plots(spec, directory):
    """probes.png and probe_<name>.png (scripts/plot), the front against Martin & Moyce where the
    case measures it; the path of the case's main plot."""
    subprocess.run([sys.executable, os.path.join(HERE, "plot_probes.py"), directory],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    if any(c["quantity"]["measure"] == "front" for c in spec.get("criteria", [])):
        m = acceptance.dam_break_front.measure(directory)
        acceptance.dam_break_front.plot(m, os.path.join(directory, "front.png"))
        return os.path.join(directory, "front.png")
    probe = (spec.get("plot") or {}).get("probe")
    main = os.path.join(directory, f"probe_{probe}.png" if probe else "probes.png")
    return main if os.path.isfile(main) else os.path.join(directory, "probes.png")


def run_case(args, out, k, jobs):
    """Runs case k of the plan; its result record (judged later)."""
    spec, case, pair = jobs[k]
    directory = run_dir(out, spec, case, pair)
    cmd = command(args.fsi, spec, case, pair, directory, args.threads)
    label = f"[{k + 1}/{len(jobs)}] {spec['scene']} {case['id']} {pair}"
    print(f"{label}: running", flush=True)
    os.makedirs(directory, exist_ok=True)
    t0 = time.monotonic()
    with open(os.path.join(directory, "fsi.log"), "w") as log:
        code = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT).returncode
    wall = time.monotonic() - t0
    res = {"index": k, "scene": spec["scene"], "case": case["id"], "pair": pair, "spec": spec,
           "case_spec": case, "dir": os.path.relpath(directory, ROOT), "wall": wall,
           "command": shown([os.path.relpath(c, ROOT) if c in (args.fsi, directory) else c
                             for c in cmd]),
           "rows": [], "error": None, "commit": "?", "date": "?", "plot": None, "run": None}
    if os.path.isfile(os.path.join(directory, "probes.csv")):
        # A run that stopped early is judged as far as it went (its completion row fails).
        run = acceptance.Run(directory)
        res["run"] = run
        res["commit"] = run.info.get("git_revision", "?")
        res["date"] = run.info.get("start", "?")[:10]
        res["plot"] = plots(spec, directory)
    if code != 0 and res["run"] is None:
        res["error"] = f"fsi exited {code} (see {res['dir']}/fsi.log)"
    print(f"{label}: {'ran' if code == 0 else f'exit {code}'} in {wall:.0f} s", flush=True)
    return res


def fmt_value(r):
    return acceptance.fmt(r["value"], r["unit"])


def fmt_error(r):
    return "" if r["error"] is None else f"{100 * r['error']:+.2f} %"


def table(results, markdown):
    head = ["scene", "case", "pair", "quantity", "ours", "reference", "error", "band", "status"]
    if markdown:
        head += ["commit", "date", "wall s"]
    lines = []
    for res in results:
        rows = res["rows"] or [{"name": res["error"] or "no criterion", "value": None, "unit": "",
                                "reference": "-", "error": None, "band": "-",
                                "status": "FAIL" if res["error"] else "-"}]
        for r in rows:
            cells = [res["scene"], res["case"], res["pair"], r["name"], fmt_value(r),
                     r["reference"], fmt_error(r), r["band"], r["status"]]
            if markdown:
                cells += [res["commit"], res["date"], f"{res['wall']:.0f}"]
            lines.append(cells)
    if markdown:
        out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
        out += ["| " + " | ".join(c.replace("|", "/") for c in cells) + " |" for cells in lines]
        return "\n".join(out)
    widths = [max(len(h), *(len(c[k]) for c in lines)) if lines else len(h)
              for k, h in enumerate(head)]
    widths[3] = min(widths[3], 60)
    out = ["  ".join(h.ljust(w) for h, w in zip(head, widths))]
    out += ["  ".join(c[:w].ljust(w) for c, w in zip(cells, widths)) for cells in lines]
    return "\n".join(out)


def report(path, args, results, total, argv):
    """The Markdown report: the summary table, then a section per case."""
    folder = os.path.dirname(os.path.abspath(path))
    images = os.path.splitext(os.path.abspath(path))[0] + "_img"
    os.makedirs(images, exist_ok=True)
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    commits = sorted({r["commit"] for r in results})
    fails = sum(r["status"] == "FAIL" for res in results for r in res["rows"]) + sum(
        1 for res in results if res["error"])
    lines = [f"# Validation report: {args.tier} tier", "",
             f"Generated by `scripts/validate {' '.join(shlex.quote(a) for a in argv)}` on {now}, "
             f"fsi {', '.join(commits)}; {len(results)} case(s), {total:.0f} s wall in total, "
             f"{args.threads} thread(s) per case. "
             + ("**All judged criteria pass.**" if not fails else f"**{fails} FAIL(s).**"), "",
             "Status: PASS / FAIL against the band; *fail (expected)*: a known failure, with its "
             "reason below; *reported*: measured, not judged. Error: relative to the reference "
             "value. The acceptance of each scene, with the references' provenance, is "
             "`data/ref/<scene>/acceptance.yaml`; `scripts/check_acceptance DIR` checks one run.",
             "", table(results, True), ""]
    for res in results:
        spec, case = res["spec"], res["case_spec"]
        lines += [f"## {spec.get('title', spec['scene'])}: {case['id']}, {res['pair']}", ""]
        if case.get("note"):
            lines += [case["note"][0].upper() + case["note"][1:] + ".", ""]
        lines += ["```", res["command"], "```", ""]
        refs = spec.get("references") or {}
        for key, ref in refs.items():
            lines.append(f"- Reference ({ref.get('kind', '')}): {' '.join(ref.get('provenance', '').split())}")
        if refs:
            lines.append("")
        notes = [r for r in res["rows"] if r.get("note")]
        for r in notes:
            lines.append(f"- {r['name']}: {r['status']}, {r['note']}")
        if notes:
            lines.append("")
        lines += [f"Wall time {res['wall']:.0f} s; run directory `{res['dir']}`.", ""]
        if res.get("plot") and os.path.isfile(res["plot"]):
            name = f"{spec['scene']}-{os.path.basename(res['dir'])}.png"
            shutil.copyfile(res["plot"], os.path.join(images, name))
            rel = os.path.relpath(os.path.join(images, name), folder)
            lines += [f"![{spec['scene']} {case['id']}]({rel})", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))
    print(f"validate: report {path}, plots in {images}/")


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--tier", default="quick", choices=acceptance.TIERS)
    p.add_argument("--scene", action="append", default=[])
    p.add_argument("--pair", action="append", default=[])
    p.add_argument("--fsi", default=os.environ.get("FSI", os.path.join(ROOT, "build", "apps", "fsi")))
    p.add_argument("--out")
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--jobs", type=int, default=1, help="cases run at once (the longest first)")
    p.add_argument("--report")
    p.add_argument("--update-regression", action="store_true")
    p.add_argument("--dry-run", action="store_true", help="print the commands only")
    args = p.parse_args(argv)
    out = os.path.abspath(args.out or os.path.join(ROOT, "out", f"validate-{args.tier}"))
    os.chdir(ROOT)
    try:
        scenes = args.scene or acceptance.scenes_with_acceptance()
        jobs = plan(args.tier, scenes, args.pair)
    except AcceptanceError as e:
        print(f"validate: {e}", file=sys.stderr)
        return 2
    if not jobs:
        print(f"validate: no case of tier {args.tier} in {', '.join(scenes)}", file=sys.stderr)
        return 2
    if not args.dry_run and not os.access(args.fsi, os.X_OK):
        print(f"validate: {args.fsi}: not an executable (build it, or give --fsi)", file=sys.stderr)
        return 2
    start = time.monotonic()
    if args.dry_run:
        for spec, case, pair in jobs:
            print(shown(command(args.fsi, spec, case, pair, run_dir(out, spec, case, pair),
                                args.threads)))
        known = [case["minutes"] for _, case, _ in jobs if "minutes" in case]
        print(f"validate: {len(jobs)} case(s); the {len(known)} with an estimate take about "
              f"{sum(known):.0f} min on one thread each")
        return 0
    print(f"validate: {args.tier} tier, {len(jobs)} case(s), fsi {args.fsi}, runs in {out}"
          + (f", {args.jobs} at a time" if args.jobs > 1 else ""))
    # With several at a time, the longest (by the acceptance file's estimate) go first.
    order = sorted(range(len(jobs)), key=lambda k: -jobs[k][1].get("minutes", 0)) \
        if args.jobs > 1 else range(len(jobs))
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_case, args, out, k, jobs) for k in order]
        results = [f.result() for f in futures]
    results.sort(key=lambda res: res["index"])
    done = {(res["scene"], res["pair"], res["case"]): res["run"] for res in results
            if not res["error"]}
    # Judge after every case has run: a criterion may compare two cases of the same scene.
    for res in results:
        if res["error"]:
            continue
        spec, case = res["spec"], res["case_spec"]
        # The same pair's other cases by id, every pair's as ID+PAIR.
        others = {}
        for (scene, pair, cid), run in done.items():
            if scene == spec["scene"]:
                others[f"{cid}+{pair}"] = run
                if pair == res["pair"]:
                    others[cid] = run
        completed = res["run"].info.get("status", "completed") == "completed"
        if args.update_regression and case.get("regression") and completed:
            path = write_regression(spec, case, res["run"], res["dir"])
            print(f"validate: wrote {os.path.relpath(path, ROOT)}")
        try:
            res["rows"] = acceptance.evaluate(spec, args.tier, case, res["pair"], res["run"], others)
        except (AcceptanceError, ValueError) as e:
            res["error"] = f"not measurable: {e}"
        print(f"{res['scene']} {res['case']} {res['pair']} ({res['dir']}):")
        acceptance.print_rows(res["rows"])
        if res["error"]:
            print(f"  FAIL             {res['error']}")
    total = time.monotonic() - start
    print()
    print(table(results, False))
    fails = [res for res in results if res["error"] or acceptance.failed(res["rows"])]
    print(f"\nvalidate: {args.tier} tier, {len(results)} case(s) in {total:.0f} s wall: "
          + ("PASS" if not fails else f"FAIL ({', '.join(r['scene'] + ' ' + r['case'] for r in fails)})"))
    if args.report:
        report(args.report, args, results, total, argv)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
