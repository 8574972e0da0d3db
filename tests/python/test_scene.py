"""Scenes through the module: loading, overrides, check() errors as the command gives them; the
sweep's fluid/solid pair plans are valid scenes."""
import os
import sys
import types
import unittest

import fsi
import yaml

from common import SCENES, SOURCE, command

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
import sweep  # noqa: E402

CANTILEVER = os.path.join(SCENES, "cantilever.yaml")


class SceneTest(unittest.TestCase):
    def test_check_ok_names_the_scene(self):
        self.assertEqual(fsi.load(CANTILEVER).check(), "cantilever")

    def test_check_error_is_the_commands_line(self):
        # A bad override, a bad key in a dict-built scene: the message is `fsi check`'s stderr.
        for override in ["structures[0].material.density=-1", "time.dt=zero",
                         "output.probes[0].structure=nowhere", "fluid.l0=1e-3"]:
            with self.subTest(override=override):
                status, _, err = command("check", CANTILEVER, "--set", override)
                self.assertEqual(status, 2)
                with self.assertRaises(fsi.InputError) as caught:
                    fsi.load(CANTILEVER, [override]).check()
                self.assertEqual(str(caught.exception), err.strip())
                self.assertRegex(str(caught.exception), r"^[^:]+cantilever\.yaml(:\d+)?: ")

    def test_overrides_as_one_string_are_a_type_error(self):
        # Issue 41: 'time.end=0.005' was iterated character by character.
        for bad in ["time.end=0.005", b"time.end=0.005", 7]:
            with self.subTest(bad=bad):
                with self.assertRaises(TypeError) as caught:
                    fsi.load(CANTILEVER, bad)
                self.assertIn("overrides: expected a dict (key -> value) or a list of "
                              "'key=value' strings, got " + type(bad).__name__,
                              str(caught.exception))
        with self.assertRaises(TypeError):
            fsi.load(CANTILEVER).with_overrides("time.end=0.005")

    def test_override_values_from_python(self):
        # Numbers, lists and strings become YAML values; the result is checked like --set.
        scene = fsi.load(CANTILEVER, {"time.end": 0.5, "gravity": [0.0, -1.0],
                                      "structures[0].linear_solver": "umfpack"})
        self.assertEqual(scene.overrides, ["time.end=0.5", "gravity=[0.0, -1.0]",
                                           "structures[0].linear_solver=umfpack"])
        self.assertEqual(scene.check(), "cantilever")
        with self.assertRaises(fsi.InputError) as caught:
            scene.with_overrides({"time.end": -1.0}).check()
        self.assertIn("time.end", str(caught.exception))

    def test_dict_scene_line_of_the_bad_key(self):
        with open(CANTILEVER) as f:
            tree = yaml.safe_load(f)
        self.assertEqual(fsi.from_dict(tree, directory=SCENES).check(), "cantilever")
        tree["time"]["dt"] = -1.0
        with self.assertRaises(fsi.InputError) as caught:
            fsi.from_dict(tree, directory=SCENES, name="beam.yaml").check()
        message = str(caught.exception)
        # The dict dumped as indented JSON: the message names the line of "dt" in that text.
        text = fsi.from_dict(tree, directory=SCENES, name="beam.yaml").text
        line = next(k + 1 for k, s in enumerate(text.splitlines()) if s.strip().startswith('"dt"'))
        self.assertTrue(message.startswith(os.path.join(SCENES, "beam.yaml") + f":{line}: time.dt"),
                        message)

    def test_reference_is_the_commands(self):
        status, out, _ = command("reference")
        self.assertEqual(status, 0)
        self.assertEqual(fsi.reference(), out)


class SweepPairsTest(unittest.TestCase):
    def plan(self, scene, levels, dts):
        args = types.SimpleNamespace(scene=scene, pairs=",".join(sweep.PAIRS[scene]),
                                     levels=levels, dts=dts, end=0.1, set=[], middle=None,
                                     schemes="css,bgs_aitken", dt_factors="2")
        return sweep.cases(args)

    def check_all(self, scene, plan):
        for name, overrides in plan:
            sets = [a for o in overrides for a in ("--set", o)]
            status, _, err = command("check", os.path.join(sweep.ROOT, scene), *sets)
            self.assertEqual((status, err), (0, ""), name)

    def test_every_pair_of_the_hydrostatic_plate_at_every_level(self):
        # Per pair: a TL-SPH plate needs dp_S = l0 / 2 <= 0.0125 (4 particles through it).
        plan = self.plan("hydrostatic_plate",
                         "0.04,0.025,0.02;sph+fem:0.05,0.025,0.0125;"
                         "emps+tlsph:0.025,0.02,0.0125;sph+tlsph:0.025,0.02,0.0125",
                         "2.5e-4,1.5625e-4,1.25e-4;sph+fem:5e-4,2.5e-4,1.25e-4;"
                         "emps+tlsph:1.5625e-4,1.25e-4,7.8125e-5;sph+tlsph:2.5e-4,2e-4,1.25e-4")
        # 4 pairs x 3 levels, and the first pair's variant and dt factor at the middle level.
        self.assertEqual(len(plan), 14)
        names = dict(plan)
        self.assertIn("structures[0].tlsph.dp=0.0125", names["sph+tlsph_l0_0.025_dt_0.00025_css"])
        self.assertIn("fluid.emps.l0=0.02", names["emps+fem_l0_0.02_dt_0.000125_css"])
        self.check_all(sweep.SCENES["hydrostatic_plate"]["file"], plan)

    def test_every_pair_of_the_elastic_obstacle(self):
        plan = self.plan("dam_break", "5.84e-3,2.92e-3", "1e-5,5e-6")
        self.assertEqual(len(plan), 10)
        self.check_all(sweep.SCENES["dam_break"]["file"], plan)

    def test_an_unknown_pair_is_refused(self):
        args = types.SimpleNamespace(scene="dam_break", pairs="emps+dem", levels="1", dts="1",
                                     end=0.1, set=[], middle=None, schemes="css", dt_factors="")
        with self.assertRaises(SystemExit):
            sweep.cases(args)


if __name__ == "__main__":
    unittest.main()
