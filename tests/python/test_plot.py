"""scripts/plot: the published curves each scene's plot.json names are found and scaled, the
axes carry units, and every probe gets its own PNG. scripts/oscillation: mean, amplitude and
frequency of a known signal."""
import json
import math
import os
import subprocess
import sys
import unittest

from common import SOURCE, fresh

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
import oscillation  # noqa: E402
import plot_probes  # noqa: E402

REF = os.path.join(SOURCE, "data", "ref")


def overlays(scene, probe):
    with open(os.path.join(REF, scene, "plot.json")) as f:
        refs = json.load(f)
    return refs["probes"].get(probe, []) + refs["probes"].get("*", [])


class PlotTest(unittest.TestCase):
    def test_elastic_obstacle_curves_are_the_published_peaks(self):
        curves = [s for s in overlays("dam_break_elastic_obstacle", "corner_x")
                  if s["kind"] == "curve"]
        self.assertEqual(len(curves), 2)
        peaks = {}
        for spec in curves:
            t, v = plot_probes.read_curve(spec, os.path.join(REF, "dam_break_elastic_obstacle"))
            k = max(range(len(v)), key=v.__getitem__)
            peaks[spec["label"].split(" ")[0]] = (round(v[k], 4), round(t[k], 3))
        # PROVENANCE.md: Walhorn peak 0.0414 m at 0.246 s, Ryzhakov 0.0420 m at 0.231 s.
        self.assertEqual(peaks, {"Walhorn": (0.0414, 0.246), "Ryzhakov": (0.042, 0.231)})

    def test_martin_moyce_in_metres_and_seconds(self):
        (spec,) = [s for s in overlays("dam_break_rigid", "front") if s["kind"] == "curve"]
        t, x = plot_probes.read_curve(spec, os.path.join(REF, "dam_break_rigid"))
        # First point T = 0.41, Z = 1.11 at a = 0.1 m, g = 9.81: t = T / sqrt(2 g / a).
        self.assertAlmostEqual(t[0], 0.41 / (2 * 9.81 / 0.1) ** 0.5, places=12)
        self.assertAlmostEqual(x[0], 0.111, places=12)

    def test_one_png_per_probe_with_units(self):
        out = fresh("plot")
        os.makedirs(out)
        with open(os.path.join(out, "probes.csv"), "w") as f:
            f.write("time,p_bottom,mean_speed\n0,4800,0.1\n0.5,4840,0.01\n1.0,4844,0.001\n")
        with open(os.path.join(out, "run.json"), "w") as f:
            json.dump({"name": "hydrostatic_tank",
                       "scene": os.path.join(SOURCE, "data", "scenes", "hydrostatic_tank.yaml")}, f)
        labels = plot_probes.probe_labels(out)
        self.assertEqual(labels["p_bottom"], "p_bottom: mean_pressure (Pa)")
        self.assertEqual(labels["mean_speed"], "mean_speed: mean_speed (m/s)")
        p = subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "plot_probes.py"), out],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        for png in ["probes.png", "probe_p_bottom.png", "probe_mean_speed.png"]:
            self.assertGreater(os.path.getsize(os.path.join(out, png)), 10000, png)


class OscillationTest(unittest.TestCase):
    def test_mean_amplitude_frequency_of_a_sampled_sine(self):
        # 0.001 + 0.08 sin(2 pi 1.9 t) sampled every 0.01 s (the FSI2 probes' interval) from
        # t = 3 to 10 s: whole cycles between the first and last upward mid-range crossing.
        t = [3.0 + 0.01 * k for k in range(701)]
        v = [0.001 + 0.08 * math.sin(2 * math.pi * 1.9 * x) for x in t]
        mean, amplitude, frequency, cycles = oscillation.measure(t, v, 3.0, 10.0)
        self.assertEqual(cycles, 12)  # crossings at k / 1.9 s, k = 6 .. 18
        self.assertAlmostEqual(frequency, 1.9, delta=1e-4)  # crossings interpolated linearly
        self.assertAlmostEqual(amplitude, 0.08, delta=0.08 * 2e-3)  # peaks between samples
        self.assertAlmostEqual(mean, 0.001, delta=1e-4)

    def test_a_window_without_two_crossings_is_refused(self):
        t = [0.01 * k for k in range(50)]
        with self.assertRaises(ValueError):
            oscillation.measure(t, [math.sin(2 * math.pi * x) for x in t], 0.0, 0.49)


if __name__ == "__main__":
    unittest.main()
