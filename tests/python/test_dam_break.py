"""The coarse dam break with an elastic obstacle (EMPS + FEM, coupled) to a short end time
through the module: probes and every field of the last frame equal the command's bit for bit."""
import os
import unittest

import h5py
import numpy as np

import fsi
from common import SCENES, command, fresh, read_bytes

SCENE = os.path.join(SCENES, "dam_break_elastic_obstacle_coarse.yaml")
# 400 steps of 5e-6 s, a frame every 100.
SHORT = ["time.end=0.002", "output.interval=0.0005"]


class DamBreakTest(unittest.TestCase):
    def test_probes_and_fields_equal_the_commands(self):
        cli = fresh("dam_break_cli")
        args = ["run", SCENE, "--out", cli, "--threads", "1"]
        for o in SHORT:
            args += ["--set", o]
        status, _, err = command(*args)
        self.assertEqual(status, 0, err)
        py = fresh("dam_break_py")
        result = fsi.load(SCENE, SHORT).run(out=py, threads=1)
        self.assertEqual(read_bytes(os.path.join(py, "probes.csv")),
                         read_bytes(os.path.join(cli, "probes.csv")))
        self.assertEqual(read_bytes(os.path.join(py, "coupling.csv")).count(b"\n"),
                         read_bytes(os.path.join(cli, "coupling.csv")).count(b"\n"))
        self.assertEqual(result.run["steps"], 400)
        self.assertEqual(len(result.probes["time"]), 5)
        reference = fsi.result(cli)
        grids = result.grids(-1)
        self.assertIn("obstacle", grids)
        self.assertEqual(grids, reference.grids(-1))
        compared = 0
        for grid, names in grids.items():
            for name in names:
                a = result.field(name, frame=-1, grid=grid)
                self.assertTrue(np.array_equal(a, reference.field(name, frame=-1, grid=grid)),
                                f"{grid}/{name}")
                compared += a.size
        # The fluid moved: its particles' velocities are not all zero after 2 ms of collapse.
        fluid = [g for g in grids if g != "obstacle"][0]
        self.assertGreater(np.abs(result.field("velocity", -1, fluid)).max(), 1e-3)
        self.assertGreater(compared, 10000)
        with h5py.File(os.path.join(py, "fields.h5"), "r") as f:
            self.assertEqual(len(f["frames"]), 5)


if __name__ == "__main__":
    unittest.main()
