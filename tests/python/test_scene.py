"""Scenes through the module: loading, overrides, check() errors as the command gives them."""
import os
import unittest

import fsi
import yaml

from common import SCENES, command

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


if __name__ == "__main__":
    unittest.main()
