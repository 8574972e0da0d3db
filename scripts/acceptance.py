#!/usr/bin/python3
"""Checks a run directory against its scene's acceptance (data/ref/<scene>/acceptance.yaml).

usage: scripts/check_acceptance DIR [--scene NAME] [--tier quick|standard|full] [--case ID]
                                [--pair FLUID+STRUCTURE] [--with ID=DIR]...

DIR holds a run's probes.csv and run.json (and coupling.csv for a coupled scene). The scene is
run.json's "name" unless --scene names it; the case is the one of that tier whose overrides match
run.json's (or --case); the pair is read from run.json's overrides (or --pair). Prints one line
per criterion that applies in the tier, case and pair: PASS, FAIL, "fail (expected)" for a
criterion marked `expected: fail` (with its reason), "reported" for one that is measured but
not judged, "not run" for a comparison with a case that was not given (--with ID=DIR). Exit
status 1 if any judged criterion fails (an expected failure that passes is a FAIL too: the
acceptance file must be updated), 2 on bad arguments or a broken acceptance file.

The acceptance file's format is described in data/ref/README.md.
"""
import argparse
import csv
import json
import math
import os
import sys

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)

import dam_break_front  # noqa: E402
import hydrostatic_check  # noqa: E402
import oscillation  # noqa: E402

TIERS = ("quick", "standard", "full")


class AcceptanceError(Exception):
    """A broken acceptance file or run directory (exit status 2)."""


def ref_dir(scene):
    return os.path.join(ROOT, "data", "ref", scene)


def load(scene):
    path = os.path.join(ref_dir(scene), "acceptance.yaml")
    if not os.path.isfile(path):
        raise AcceptanceError(f"{path}: no acceptance file for scene {scene!r}")
    try:
        with open(path) as f:
            spec = yaml.safe_load(f)
    except yaml.YAMLError as e:
        raise AcceptanceError(f"{path}: {e}") from None
    spec["_path"] = path
    if spec.get("like"):
        # The references and criteria of another scene (the same benchmark with another fluid):
        # its files are named relative to its folder, which sits beside this one.
        base = load(spec["like"])
        spec["references"] = {**base.get("references", {}), **spec.get("references", {})}
        spec["criteria"] = base.get("criteria", []) + spec.get("criteria", [])
    ids = [c["id"] for c in spec.get("cases", [])]
    if len(ids) != len(set(ids)):
        raise AcceptanceError(f"{path}: duplicate case id")
    for c in spec.get("criteria", []):
        for key in ("name", "quantity", "against", "tiers"):
            if key not in c:
                raise AcceptanceError(f"{path}: criterion {c.get('name')!r}: no {key!r}")
        for t in c["tiers"]:
            if t not in TIERS:
                raise AcceptanceError(f"{path}: criterion {c['name']!r}: unknown tier {t!r}")
        if ("band" in c) == ("target" in c):
            raise AcceptanceError(f"{path}: criterion {c['name']!r}: give band or target")
        for cid in c.get("cases", []):
            if cid not in ids:
                raise AcceptanceError(f"{path}: criterion {c['name']!r}: unknown case {cid!r}")
    return spec


def scenes_with_acceptance():
    base = os.path.join(ROOT, "data", "ref")
    return sorted(d for d in os.listdir(base)
                  if os.path.isfile(os.path.join(base, d, "acceptance.yaml")))


def case_sets(spec, case, pair):
    """The --set list of a case under a pair: the case's own, then the pair's."""
    sets = [f"{k}={v}" for k, v in (case.get("set") or {}).items()]
    if pair and pair != default_pair(spec, case):
        pairs = spec.get("pairs") or {}
        if pair not in pairs:
            raise AcceptanceError(f"{spec['_path']}: pair {pair!r} not offered "
                                  f"(offered: {', '.join(pairs) or 'the default only'})")
        sets += [f"{k}={v}" for k, v in (pairs[pair] or {}).items()]
    return sets


def default_pair(spec, case=None):
    return (case or {}).get("pair") or spec.get("pair")


# --- reading a run ----------------------------------------------------------------------------

class Run:
    def __init__(self, path):
        self.path = path
        probes = os.path.join(path, "probes.csv")
        if not os.path.isfile(probes):
            raise AcceptanceError(f"{probes}: no such file")
        with open(probes, newline="") as f:
            self.rows = list(csv.DictReader(f))
        if not self.rows:
            raise AcceptanceError(f"{probes}: no samples")
        self.columns = list(self.rows[0].keys())
        try:
            with open(os.path.join(path, "run.json")) as f:
                self.info = json.load(f)
        except (OSError, ValueError):
            self.info = {}

    def series(self, probe):
        if probe not in self.columns:
            raise AcceptanceError(f"{self.path}/probes.csv: no column {probe!r} "
                                  f"(columns: {', '.join(self.columns)})")
        t, v = [], []
        for r in self.rows:
            if r[probe] not in ("", "nan"):
                t.append(float(r["time"]))
                v.append(float(r[probe]))
        return t, v

    @property
    def end(self):
        return float(self.rows[-1]["time"])


def window(q, run):
    """(t0, t1) of a quantity: `window: [t0, t1]` (t1 may be "end") or `last: seconds`."""
    if "last" in q:
        return run.end - float(q["last"]) - 1e-9, run.end + 1e-9
    w = q.get("window", [0.0, "end"])
    t1 = run.end if w[1] == "end" else float(w[1])
    return float(w[0]) - 1e-9, t1 + 1e-9


def inside(run, q):
    t, v = run.series(q["probe"])
    t0, t1 = window(q, run)
    w = [(a, b) for a, b in zip(t, v) if t0 <= a <= t1]
    if not w:
        raise AcceptanceError(f"{run.path}: no sample of {q['probe']} in [{t0:g}, {t1:g}] s")
    return w


# --- measures: each returns a dict of named figures --------------------------------------------

def m_peak(run, q, _others, _spec):
    w = inside(run, q)
    pick = min if q.get("sign") == "min" else max
    t, v = pick(w, key=lambda p: p[1])
    return {"value": v, "time": t}


def m_mean(run, q, _others, _spec):
    w = inside(run, q)
    return {"value": sum(v for _, v in w) / len(w)}


def m_final(run, q, _others, _spec):
    t, v = run.series(q["probe"])
    return {"value": v[-1], "time": t[-1]}


def m_gradient(run, q, _others, _spec):
    """Mean over the window of (probe b - probe a) / (x_b - x_a)."""
    a = inside(run, dict(q, probe=q["probes"][0]))
    b = inside(run, dict(q, probe=q["probes"][1]))
    mean_a, mean_b = (sum(v for _, v in a) / len(a)), (sum(v for _, v in b) / len(b))
    return {"value": (mean_b - mean_a) / (q["x"][1] - q["x"][0])}


def m_ratio(run, q, _others, _spec):
    """Mean of probe a over the window over the mean of probe b over the same window."""
    a = inside(run, dict(q, probe=q["probes"][0]))
    b = inside(run, dict(q, probe=q["probes"][1]))
    mean_b = sum(v for _, v in b) / len(b)
    if mean_b == 0:
        raise AcceptanceError(f"{run.path}: {q['probes'][1]}: mean over the window is 0")
    return {"value": (sum(v for _, v in a) / len(a)) / mean_b}


def m_front(run, q, _others, _spec):
    """Martin & Moyce: dam_break_front.measure (fitted release offset, errors, front speed)."""
    m = dam_break_front.measure(run.path, q.get("probe", "front"), q.get("release", 0.0),
                                q.get("a", 0.1), q.get("g", 9.81))
    return {"shifted_error": m["worst"], "unshifted_error": m["worst_raw"], "shift": m["shift"],
            "speed_error": m["speed_diff"], "speed": m["speed_sim"], "_front": m}


def m_front_agreement(run, q, others, spec):
    """Largest relative difference of the front Z between this run and case q["with"] at the
    experiment's judged T (relative to this run), as dam_break_front computes it."""
    other = others.get(q["with"])
    if other is None:
        return None
    a = m_front(run, q, others, spec)["_front"]["shifted"]
    b = m_front(other, q, others, spec)["_front"]["shifted"]
    return {"value": dam_break_front.agreement(a, b)}


def m_agreement(run, q, others, spec):
    """Relative difference of one figure (`of`: a quantity, its figure `of_field`, default value)
    between this run and the run `with` (a case id, or ID+PAIR for another pair's run), relative
    to that run's: |ours / theirs - 1|."""
    other = others.get(q["with"])
    if other is None:
        return None
    of, field = q["of"], q.get("of_field", "value")
    if of["measure"] not in MEASURES or of["measure"] == "agreement":
        raise AcceptanceError(f"{spec['_path']}: agreement of {of['measure']!r}: not a measure")
    ours = MEASURES[of["measure"]](run, of, others, spec)[field]
    theirs = MEASURES[of["measure"]](other, of, others, spec)[field]
    if theirs == 0:
        raise AcceptanceError(f"{other.path}: {of.get('probe')}: {field} is 0")
    return {"value": abs(ours / theirs - 1.0), "ours": ours, "theirs": theirs}


def m_still_water(run, q, _others, _spec):
    """hydrostatic_check.measure: bottom-row pressure (last 1 s), end speed, energy growth."""
    m = hydrostatic_check.measure(run.rows, q.get("depth", 0.5), q.get("l0", 0.0125),
                                  q.get("rho", 1000.0), q.get("g", 9.81), q.get("damping", 2.0))
    return {"p_bottom": m["p_bottom"], "speed_ratio": m["speed"] / m["scale"],
            "energy_growth": m["growth"]}


def m_growth(run, q, _others, _spec):
    """Largest value of a probe after t0 over its value at t0 (an energy that must fall)."""
    t, v = run.series(q["probe"])
    after = [b for a, b in zip(t, v) if a >= float(q["after"]) - 1e-9]
    if not after or after[0] <= 0:
        raise AcceptanceError(f"{run.path}: {q['probe']}: no positive value at t = {q['after']}")
    return {"value": max(after) / after[0]}


def m_decay(run, q, _others, _spec):
    """Mean of a probe over the window over its mean over the window `before` (an energy that
    oscillates as it falls)."""
    now = inside(run, q)
    then = inside(run, dict(q, window=q["before"]))
    mean_then = sum(v for _, v in then) / len(then)
    if mean_then <= 0:
        raise AcceptanceError(f"{run.path}: {q['probe']}: mean over {q['before']} not positive")
    return {"value": (sum(v for _, v in now) / len(now)) / mean_then}


def m_oscillation(run, q, _others, _spec):
    """oscillation.measure over whole cycles in the window: mean, amplitude, frequency."""
    t, v = run.series(q["probe"])
    t0, t1 = window(q, run)
    mean, amp, freq, cycles = oscillation.measure(t, v, t0, t1)
    return {"mean": mean, "amplitude": amp, "frequency": freq, "cycles": cycles}


def read_reference_csv(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header = rows[0]
    return {name: [float(r[k]) for r in rows[1:]] for k, name in enumerate(header)}


def interpolate(t, v, x):
    if x < t[0] - 1e-9 or x > t[-1] + 1e-9:
        return None
    lo, hi = 0, len(t) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if t[mid] <= x else (lo, mid)
    if t[hi] == t[lo]:
        return v[lo]
    return v[lo] + (v[hi] - v[lo]) * (x - t[lo]) / (t[hi] - t[lo])


def m_regression(run, q, _others, spec):
    """Our committed time series (q["file"], data/ref/<scene>/): the largest difference of the
    probe at the file's times, over the file's range of that probe."""
    path = os.path.join(os.path.dirname(spec["_path"]), q["file"])
    if not os.path.isfile(path):
        raise AcceptanceError(f"{path}: no such file (scripts/validate --update-regression)")
    ref = read_reference_csv(path)
    probe = q["probe"]
    if probe not in ref:
        raise AcceptanceError(f"{path}: no column {probe!r}")
    t, v = run.series(probe)
    span = max(ref[probe]) - min(ref[probe])
    if span <= 0:
        raise AcceptanceError(f"{path}: {probe} is constant")
    worst, at = 0.0, None
    for x, r in zip(ref["time"], ref[probe]):
        ours = interpolate(t, v, x)
        if ours is None:
            return {"value": math.inf, "time": x}
        if abs(ours - r) / span > worst:
            worst, at = abs(ours - r) / span, x
    return {"value": worst, "time": at}


def m_arrival(run, q, _others, _spec):
    """The first time in the window the probe reaches q["level"], between frames linearly."""
    w = inside(run, q)
    level = float(q["level"])
    for (t0, v0), (t1, v1) in zip(w, w[1:]):
        if v0 < level <= v1:
            return {"value": t0 + (t1 - t0) * (level - v0) / (v1 - v0)}
    raise ValueError(f"{q['probe']} never reaches {level:g} in the window")


def read_table(path):
    """A whitespace-separated table with one header line: its numeric columns."""
    with open(path) as f:
        rows = [line.split() for line in f.readlines()[1:] if line.strip()]
    return [[float(r[k]) for r in rows] for k in range(len(rows[0]))]


def m_history(run, q, _others, _spec):
    """A measured history (q["file"] from the repository's root, whitespace-separated, time in
    column 1, q["column"] counted from 1): the RMS over the run's samples in the window of
    probe - reference (interpolated at each sample's time), over the reference's largest |value|
    in the window."""
    path = os.path.join(ROOT, q["file"])
    if not os.path.isfile(path):
        raise AcceptanceError(f"{path}: no such file")
    cols = read_table(path)
    t_ref, v_ref = cols[0], cols[int(q["column"]) - 1]
    t0, t1 = window(q, run)
    pairs = [(v, interpolate(t_ref, v_ref, t)) for t, v in inside(run, q)]
    errors = [v - r for v, r in pairs if r is not None]  # samples the reference covers
    scale = max(abs(v) for t, v in zip(t_ref, v_ref) if t0 <= t <= t1)
    return {"value": math.sqrt(sum(e * e for e in errors) / len(errors)) / scale}


def m_impulse(run, q, _others, _spec):
    """value: the probe's integral over the window (trapezoids between frames)."""
    w = inside(run, q)
    return {"value": sum(0.5 * (v0 + v1) * (t1 - t0) for (t0, v0), (t1, v1) in zip(w, w[1:]))}


MEASURES = {"peak": m_peak, "mean": m_mean, "final": m_final, "gradient": m_gradient,
            "ratio": m_ratio,
            "front": m_front, "front_agreement": m_front_agreement, "agreement": m_agreement,
            "still_water": m_still_water, "growth": m_growth, "decay": m_decay, "oscillation": m_oscillation,
            "regression": m_regression, "arrival": m_arrival, "history": m_history,
            "impulse": m_impulse}


# --- judging ----------------------------------------------------------------------------------

def fmt(x, unit=""):
    if x is None:
        return "-"
    if unit == "%":
        return f"{100 * x:.2f} %"
    if isinstance(x, int):
        return f"{x}"
    s = f"{x:.4g}"
    return f"{s} {unit}".strip()


def applies(c, tier, case_id, pair):
    return (tier in c["tiers"] and (not c.get("cases") or case_id in c["cases"])
            and (not c.get("pairs") or pair in c["pairs"]))


def judge(c, run, others, spec):
    """One criterion on one run: a dict with name, value, reference, error, band, status, note."""
    q = c["quantity"]
    if q["measure"] not in MEASURES:
        raise AcceptanceError(f"{spec['_path']}: {c['name']}: unknown measure {q['measure']!r}")
    unit = c.get("unit", "")
    against = c["against"]
    row = {"name": c["name"], "against": against.get("what", ""),
           "reference_file": against.get("file", ""), "unit": unit}
    try:
        figures = MEASURES[q["measure"]](run, q, others, spec)
    except ValueError as e:  # e.g. no whole cycle in the window
        row.update(value=None, reference="-", error=None, band="-", note=f"not measurable: {e}",
                   status="reported" if c.get("judged", True) is False else "FAIL")
        return row
    if figures is None:
        row.update(value=None, reference="-", error=None, band="-", status="not run",
                   note=f"case {q['with']} not given")
        return row
    value = figures[c.get("field", "value")]
    row["value"] = value
    row["extra"] = {k: v for k, v in figures.items()
                    if not k.startswith("_") and k != c.get("field", "value")}
    if "band" in c:
        lo, hi = c["band"]
        ok = lo <= value <= hi
        row["band"] = f"{fmt(lo, unit)} .. {fmt(hi, unit)}"
        row["reference"] = against.get("value_text", row["band"])
        row["error"] = None
        ref_value = against.get("value")
        if ref_value is not None:
            row["error"] = value / ref_value - 1.0 if ref_value else value - ref_value
    else:
        target, tol = float(c["target"]), float(c["tolerance"])
        error = value / target - 1.0
        ok = abs(error) <= tol
        row["reference"] = fmt(target, unit)
        row["error"] = error
        row["band"] = f"+-{100 * tol:g} %"
    expected = c.get("expected")
    if c.get("judged", True) is False:
        row["status"] = "reported"
    elif expected == "fail":
        row["status"] = "fail (expected)" if not ok else "FAIL"
        row["note"] = ("expected to fail: " + c.get("reason", "") if not ok else
                       "passes although marked expected: fail; update the acceptance file")
    else:
        row["status"] = "PASS" if ok else "FAIL"
    if "theirs" in figures:
        of_unit = q.get("of_unit", "")
        mine = f"{fmt(figures['ours'], of_unit)} against {fmt(figures['theirs'], of_unit)}"
        row["note"] = f"{mine}; {row['note']}" if row.get("note") else mine
    row.setdefault("note", c.get("note", ""))
    return row


def match_case(spec, tier, run):
    """The case of the tier whose --set list (without the pair's) is the run's overrides."""
    overrides = set(run.info.get("overrides", []))
    candidates = [c for c in spec.get("cases", []) if tier in c["tiers"]]
    for c in candidates:
        own = set(case_sets(spec, c, None))
        extra = overrides - own
        if own <= overrides and all(any(e == f"{k}={v}" for p in (spec.get("pairs") or {}).values()
                                        for k, v in (p or {}).items()) for e in extra):
            if os.path.basename(run.info.get("scene", c["file"])) == os.path.basename(c["file"]):
                return c
    return None


def pair_of(spec, case, run):
    overrides = set(run.info.get("overrides", []))
    matching = [(len(sets), name) for name, sets in (spec.get("pairs") or {}).items()
                if sets and all(f"{k}={v}" in overrides for k, v in sets.items())]
    return max(matching)[1] if matching else default_pair(spec, case)


def completion(run):
    """The row every run gets: did it reach its end time (run.json), in how many steps, how long."""
    info = run.info
    status = info.get("status", "completed")
    steps, wall = info.get("steps"), info.get("wall_seconds")
    done = f"{steps} steps, {wall:.0f} s wall" if steps is not None and wall is not None else ""
    row = {"name": "run to its end time", "value": float(info.get("simulated_time", run.end)),
           "unit": "s", "reference": "-", "error": None, "band": "-", "against": "",
           "reference_file": ""}
    if status == "completed":
        row.update(status="PASS", note=f"completed, {done}" if done else "completed")
    else:
        # A run that stopped early is judged as far as it went, and fails.
        row.update(status="FAIL", note=f"run.json: {status} at t = {info.get('simulated_time')} s: "
                                       f"{info.get('message', '')}")
    return row


def evaluate(spec, tier, case, pair, run, others):
    rows = [completion(run)]
    for c in spec.get("criteria", []):
        if applies(c, tier, case["id"], pair):
            rows.append(judge(c, run, others, spec))
    return rows


def failed(rows):
    return any(r["status"] == "FAIL" for r in rows)


def print_rows(rows, out=None):
    out = out or sys.stdout
    for r in rows:
        err = "" if r["error"] is None else f", error {100 * r['error']:+.2f} %"
        note = f"  ({r['note']})" if r.get("note") else ""
        ref = "" if r["reference"] in (r["band"], "-") else f" against {r['reference']}"
        print(f"  {r['status']:16} {r['name']}: {fmt(r['value'], r['unit'])}{ref}{err}, "
              f"band {r['band']}{note}", file=out)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("dir")
    p.add_argument("--scene")
    p.add_argument("--tier", default="standard", choices=TIERS)
    p.add_argument("--case")
    p.add_argument("--pair")
    p.add_argument("--with", dest="others", action="append", default=[], metavar="ID=DIR")
    a = p.parse_args(argv)
    try:
        run = Run(a.dir)
        scene = a.scene or run.info.get("name")
        if not scene:
            raise AcceptanceError(f"{a.dir}/run.json: no scene name; give --scene")
        spec = load(scene)
        if a.case:
            case = next((c for c in spec["cases"] if c["id"] == a.case), None)
            if case is None:
                raise AcceptanceError(f"{spec['_path']}: no case {a.case!r}")
        else:
            case = match_case(spec, a.tier, run)
            if case is None:
                raise AcceptanceError(f"{a.dir}: matches no case of tier {a.tier} in "
                                      f"{spec['_path']}; give --case")
        pair = a.pair or pair_of(spec, case, run)
        others = {}
        for o in a.others:
            cid, _, d = o.partition("=")
            others[cid] = Run(d)
        rows = evaluate(spec, a.tier, case, pair, run, others)
    except AcceptanceError as e:
        print(f"check_acceptance: {e}", file=sys.stderr)
        return 2
    print(f"{a.dir}: {scene}, case {case['id']}, pair {pair}, tier {a.tier}")
    print_rows(rows)
    if not rows:
        print("  no criterion applies")
    print("FAIL" if failed(rows) else "PASS")
    return 1 if failed(rows) else 0


if __name__ == "__main__":
    sys.exit(main())
