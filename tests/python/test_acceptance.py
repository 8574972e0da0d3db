"""The acceptance checker (scripts/acceptance.py, scripts/check_acceptance) on synthetic run
directories: it passes what is inside a band and fails what drifts out of it, the regression
comparison catches a 2 % change that the published band lets through, and every acceptance file
loads with its scenes and regression files present."""
import contextlib
import io
import json
import math
import os
import sys
import unittest

import h5py
import numpy as np

from common import SOURCE, fresh

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
import acceptance  # noqa: E402
import dam_break_front  # noqa: E402
import hydrostatic_check  # noqa: E402


def write_run(name, scene, overrides, columns, rows):
    d = fresh(name)
    os.makedirs(d)
    with open(os.path.join(d, "probes.csv"), "w") as f:
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join(repr(v) for v in r) + "\n")
    with open(os.path.join(d, "run.json"), "w") as f:
        json.dump({"name": scene, "scene": f"data/scenes/{scene}.yaml",
                   "overrides": overrides}, f)
    return d


def check(*args):
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        status = acceptance.main(list(args))
    return status, out.getvalue()


def tank(name, pressure):
    """A still tank to 10 s: p_bottom constant, the energy falling after 2 s."""
    rows = [(0.05 * k, pressure, pressure, 1e-4, 0.01 / (1 + k)) for k in range(201)]
    return write_run(name, "hydrostatic_tank", [], ["time", "p_bottom", "p_centre", "mean_speed",
                                                    "kinetic_energy"], rows)


def block(name, corner_over_bulk):
    """Still water around the block to 4 s: p_corner = corner_over_bulk x p_bulk, both 2.5 %
    below rho g h (the ratio is judged, rho g h only reported)."""
    bulk = 2394.0 * 0.975
    rows = [(0.05 * k, corner_over_bulk * bulk, bulk, 1e-4, 0.01 / (1 + k)) for k in range(81)]
    return write_run(name, "hydrostatic_block", [], ["time", "p_corner", "p_bulk", "mean_speed",
                                                     "kinetic_energy"], rows)


def plate(name, scale):
    """The committed quick-tier plate series, multiplied by scale."""
    ref = acceptance.read_reference_csv(os.path.join(SOURCE, "data", "ref", "hydrostatic_plate",
                                                     "regression_quick.csv"))
    rows = [(t, scale * v) for t, v in zip(ref["time"], ref["mid_span"])]
    return write_run(name, "hydrostatic_plate", ["time.end=1.5"], ["time", "mid_span"], rows)


def settling_column(name):
    """fields.h5 of two particles (2-D, l0 = 0.1 m, rho 1000, c 10 m/s) at t = 0, 2, 3, 4 s:
    the top one sinks by 0.01 m and climbs back by 0.005 m after the damping phase."""
    d = fresh(name)
    os.makedirs(d)
    with open(os.path.join(d, "run.json"), "w") as f:
        json.dump({"fluid": {"options": {"density": 1000.0, "sound_speed": 10.0, "l0": 0.1}}}, f)
    frames = [(0.0, 0.25, 0.0, 0.0), (2.0, 0.15, 0.0, 100.0), (3.0, 0.14, 0.1, 200.0),
              (4.0, 0.145, 0.0, 100.0)]
    with h5py.File(os.path.join(d, "fields.h5"), "w") as f:
        for k, (t, y, u, p) in enumerate(frames):
            g = f.create_group(f"frames/{k}")
            g.attrs["time"] = t
            g["particles/position"] = np.array([[0.05, 0.05], [0.05, y]])
            g["particles/velocity"] = np.array([[u, 0.0], [0.0, 0.0]])
            g["particles/pressure"] = np.array([p, 0.0])
    return d


def surge(name):
    """A dam break's probes.csv (front x) and fields.h5 at t = 0, 0.1, 0.2, 0.3 s (a = 0.1 m):
    the front at Z = 1.5, 2.5, 3.0 and 4.0; three particles a frame, the two nearest the front
    within 0.2 a of it."""
    d = fresh(name)
    os.makedirs(d)
    frames = [(0.0, 0.15, [0.10, 0.14, 0.15], [100.0, 100.0, 100.0]),
              (0.1, 0.25, [0.10, 0.24, 0.25], [5.0, 1.0, 2.0]),
              (0.2, 0.30, [0.20, 0.29, 0.30], [5.0, 2.0, 4.0]),
              (0.3, 0.40, [0.30, 0.39, 0.40], [100.0, 100.0, 100.0])]
    with open(os.path.join(d, "probes.csv"), "w") as f:
        f.write("time,front\n" + "".join(f"{t!r},{x!r}\n" for t, x, _, _ in frames))
    with h5py.File(os.path.join(d, "fields.h5"), "w") as f:
        for k, (t, _, x, u) in enumerate(frames):
            g = f.create_group(f"frames/{k}")
            g.attrs["time"] = t
            g["particles/position"] = np.array([[xi, 0.0] for xi in x])
            g["particles/velocity"] = np.array([[ui, 0.0] for ui in u])
    return d


def accelerating_front(name):
    """A dam break's probes.csv (a = 0.1 m) whose front is Z = 1 + 0.5 T + 0.1 T^2, sampled at
    T = 0.025 + 0.05 k to T = 4.2."""
    d = fresh(name)
    os.makedirs(d)
    scale = math.sqrt(2 * 9.81 / 0.1)
    T = [0.025 + 0.05 * k for k in range(84)]
    with open(os.path.join(d, "probes.csv"), "w") as f:
        f.write("time,front\n" + "".join(f"{t / scale!r},{0.1 * (1 + 0.5 * t + 0.1 * t * t)!r}\n"
                                         for t in T))
    return d


class AcceptanceTest(unittest.TestCase):
    def test_the_front_at_2_5_and_the_late_speed_of_an_accelerating_front(self):
        d = accelerating_front("late")
        m = dam_break_front.measure(d, a=0.1, g=9.81)
        # linear interpolation at T = 2.5 between 2.475 and 2.525: Z(2.5) + 0.1 x 0.025^2
        self.assertAlmostEqual(m["z_25"], 2.875 + 6.25e-5, delta=1e-9)
        # the straight line over 20 samples symmetric about T = 3.5 has the slope 0.5 + 0.2 x 3.5
        self.assertAlmostEqual(m["late"], 1.2, delta=1e-9)
        out = os.path.join(d, "compare.png")
        dam_break_front.compare([m, m], ["one", "two"], out)
        self.assertGreater(os.path.getsize(out), 10000)

    def test_the_tip_speed_averages_the_particles_behind_the_front_inside_the_window(self):
        # frames at Z = 2.5 and 3.0 only; the particles within 0.02 m of the front: 1.5 and 3.0
        tip = dam_break_front.tip_speed(surge("tip"), a=0.1, g=9.81)
        self.assertAlmostEqual(tip, 2.25 / math.sqrt(2 * 9.81 * 0.1), delta=1e-12)

    def test_no_tip_speed_from_frames_without_velocities(self):
        # output.fields without velocity (the EMPS peer case): the frames hold positions only
        d = surge("no_velocity")
        with h5py.File(os.path.join(d, "fields.h5"), "a") as f:
            for g in f["frames"].values():
                del g["particles/velocity"]
        self.assertIsNone(dam_break_front.tip_speed(d, a=0.1, g=9.81))

    def test_the_energy_budget_splits_gravity_kinetic_and_compression(self):
        b = hydrostatic_check.energy_budget(settling_column("budget"), damping=2.0, g=9.81)
        # m = rho l0^2 = 10 kg; from t = 2 s: gravity m g dy, kinetic m u^2 / 2,
        # compression l0^2 (p^2 - p_2^2) / (2 rho c^2).
        self.assertEqual(list(b["time"]), [2.0, 3.0, 4.0])
        self.assertAlmostEqual(b["gravity"][1], -0.981, delta=1e-12)
        self.assertAlmostEqual(b["kinetic"][1], 0.05, delta=1e-12)
        self.assertAlmostEqual(b["compression"][1], 0.0015, delta=1e-12)
        self.assertAlmostEqual(b["total"][1], -0.9295, delta=1e-12)
        self.assertAlmostEqual(b["total"][2], -0.4905, delta=1e-12)
        self.assertAlmostEqual(b["rise"], 0.439, delta=1e-12)

    def test_a_tank_within_one_percent_passes_and_two_percent_off_fails(self):
        status, out = check(tank("tank_ok", 4905.0 * 0.995), "--tier", "standard")
        self.assertEqual(status, 0, out)
        self.assertIn("PASS", out)
        status, out = check(tank("tank_off", 4905.0 * 0.98), "--tier", "standard")
        self.assertEqual(status, 1, out)
        self.assertRegex(out, r"FAIL +p_bottom .*: 4807 Pa against 4905 Pa, error -2.00 %")

    def test_the_block_judges_the_corner_against_the_bulk_at_its_depth(self):
        status, out = check(block("block_ok", 1.005), "--tier", "standard")
        self.assertEqual(status, 0, out)
        self.assertRegex(out, r"PASS +p_corner over p_bulk .*: 1.005 against 1, error \+0.50 %")
        self.assertRegex(out, r"reported +p_corner, mean over the last 1 s: .* error -2.01 %")
        status, out = check(block("block_off", 1.02), "--tier", "standard")
        self.assertEqual(status, 1, out)
        self.assertRegex(out, r"FAIL +p_corner over p_bulk .*: 1.02 against 1, error \+2.00 %")

    def test_the_regression_catches_what_the_published_band_lets_through(self):
        status, out = check(plate("plate_same", 1.0), "--tier", "quick")
        self.assertEqual(status, 0, out)
        self.assertIn("case quick, pair emps+fem", out)
        status, out = check(plate("plate_stiffer", 1.02), "--tier", "quick")
        self.assertEqual(status, 1, out)
        self.assertRegex(out, r"PASS +mid_span, mean over the last 0.5 s, against the plane-strain")
        self.assertRegex(out, r"FAIL +regression, mid_span against our committed run: 2.\d\d %")

    def test_a_run_that_stopped_early_fails(self):
        d = plate("plate_stopped", 1.0)
        with open(os.path.join(d, "run.json"), "w") as f:
            json.dump({"name": "hydrostatic_plate", "scene": "data/scenes/hydrostatic_plate.yaml",
                       "overrides": ["time.end=1.5"], "status": "interrupted",
                       "simulated_time": 1.5, "message": "stopped by signal 15"}, f)
        status, out = check(d, "--tier", "quick")
        self.assertEqual(status, 1, out)
        self.assertIn("FAIL             run to its end time: 1.5 s", out)
        self.assertIn("stopped by signal 15", out)

    def test_a_completed_run_says_so_with_its_steps_and_wall_time(self):
        d = plate("plate_completed", 1.0)
        with open(os.path.join(d, "run.json"), "w") as f:
            json.dump({"name": "hydrostatic_plate", "scene": "data/scenes/hydrostatic_plate.yaml",
                       "overrides": ["time.end=1.5"], "status": "completed", "steps": 1234,
                       "wall_seconds": 56.7, "simulated_time": 1.5}, f)
        status, out = check(d, "--tier", "quick")
        self.assertEqual(status, 0, out)
        self.assertIn("PASS             run to its end time: 1.5 s, band -  "
                      "(completed, 1234 steps, 57 s wall)", out)

    def test_two_pairs_agree_within_the_band_or_fail(self):
        """The rolling baffle's EMPS + FEM run against its SPH + TL-SPH run: a tip history 4 %
        larger agrees within 10 %, one 12 % larger does not; without the other run, not run."""
        tip = [(0.01 * k, 0.08 * math.sin(2 * math.pi * 0.01 * k / 1.17)) for k in range(301)]
        sets = ["fluid.type=emps", "structures[0].type=fem"]
        theirs = write_run("baffle_sph", "rolling_tank_elastic_baffle", [],
                           ["time", "baffle_tip_x"], tip)
        close = write_run("baffle_emps", "rolling_tank_elastic_baffle", sets,
                          ["time", "baffle_tip_x"], [(t, 1.04 * v) for t, v in tip])
        far = write_run("baffle_emps_far", "rolling_tank_elastic_baffle", sets,
                        ["time", "baffle_tip_x"], [(t, 1.12 * v) for t, v in tip])
        status, out = check(close, "--tier", "full", "--with", f"shipped+sph+tlsph={theirs}")
        self.assertEqual(status, 0, out)
        self.assertIn("pair emps+fem", out)
        self.assertRegex(out, r"PASS +baffle_tip_x, first rightward extreme .*: 4.00 %, "
                              r".*\(0.05348 m against 0.05142 m\)")
        status, out = check(far, "--tier", "full", "--with", f"shipped+sph+tlsph={theirs}")
        self.assertEqual(status, 1, out)
        self.assertRegex(out, r"FAIL +baffle_tip_x, first rightward extreme .*: 12.00 %")
        status, out = check(far, "--tier", "full")
        self.assertEqual(status, 0, out)
        self.assertRegex(out, r"not run +baffle_tip_x, first rightward extreme")

    def test_a_run_of_no_case_and_a_missing_column_are_errors(self):
        d = plate("plate_other", 1.0)
        with open(os.path.join(d, "run.json"), "w") as f:
            json.dump({"name": "hydrostatic_plate", "scene": "data/scenes/hydrostatic_plate.yaml",
                       "overrides": ["time.end=9"]}, f)
        status, out = check(d, "--tier", "quick")
        self.assertEqual(status, 2, out)
        self.assertIn("matches no case of tier quick", out)
        d = write_run("tank_no_column", "hydrostatic_block", [], ["time", "x"], [(0.0, 1.0)])
        status, out = check(d, "--tier", "standard")
        self.assertEqual(status, 2, out)
        self.assertIn("no column 'p_corner'", out)

    def test_arrival_impulse_and_history_measures(self):
        # v = t on 0.01 s frames: it reaches 0.255 at 0.255 s (between frames), its integral
        # over [0.2, 0.6] is (0.6^2 - 0.2^2) / 2 = 0.16 (trapezoids are exact for a line).
        d = write_run("measures_line", "spheric_test2_emps_3d", [], ["time", "v"],
                      [(0.01 * k, 0.01 * k) for k in range(101)])
        run = acceptance.Run(d)
        q = {"probe": "v", "level": 0.255, "window": [0.0, 1.0]}
        self.assertAlmostEqual(acceptance.m_arrival(run, q, {}, {})["value"], 0.255, places=12)
        q = {"probe": "v", "window": [0.2, 0.6]}
        self.assertAlmostEqual(acceptance.m_impulse(run, q, {}, {})["value"], 0.16, places=12)
        with self.assertRaises(ValueError):  # never reached: not measurable
            acceptance.m_arrival(run, {"probe": "v", "level": 2.0}, {}, {})
        # The measured reservoir height (column 13) at its own sample times, then 0.01 m higher:
        # RMS 0 and 0.01 m over the window's largest height (0.5511 m).
        path = "data/ref/spheric_test2/test_case_2_exp_data.dat"
        t, h = (acceptance.read_table(os.path.join(SOURCE, path))[c] for c in (0, 12))
        samples = [(a, b) for a, b in zip(t, h) if a <= 1.0]
        for name, shift, rms in (("history_same", 0.0, 0.0),
                                 ("history_shift", 0.01, 0.01 / 0.5511333333)):
            d = write_run(name, "spheric_test2_emps_3d", [], ["time", "H4"],
                          [(a, b + shift) for a, b in samples])
            q = {"probe": "H4", "file": path, "column": 13, "window": [0.0, 1.0]}
            value = acceptance.m_history(acceptance.Run(d), q, {}, {})["value"]
            self.assertAlmostEqual(value, rms, places=9)

    def test_every_acceptance_file_loads_with_its_scenes_and_regression_files(self):
        scenes = acceptance.scenes_with_acceptance()
        self.assertGreaterEqual(len(scenes), 10)
        shipped = set()
        for name in scenes:
            spec = acceptance.load(name)
            self.assertEqual(spec["scene"], name)
            for case in spec["cases"]:
                self.assertTrue(os.path.isfile(os.path.join(SOURCE, case["file"])), case["file"])
                if "standard" in case["tiers"] and not case.get("sensitivity"):
                    self.assertFalse(case.get("set"), f"{name} {case['id']}: standard is as shipped")
                    shipped.add(os.path.basename(case["file"]))
                if case.get("regression"):
                    self.assertTrue(os.path.isfile(os.path.join(SOURCE, "data", "ref", name,
                                                                case["regression"])))
            for c in spec["criteria"]:
                self.assertIn(c["quantity"]["measure"], acceptance.MEASURES, c["name"])
                if c.get("expected") == "fail":
                    self.assertTrue(c.get("reason"), c["name"])
        # The standard tier runs every shipped scene as shipped.
        self.assertEqual(shipped, set(os.listdir(os.path.join(SOURCE, "data", "scenes"))))


if __name__ == "__main__":
    unittest.main()
