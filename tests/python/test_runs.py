"""The cantilever run through the module: the same bits as `fsi run`, results as arrays,
progress, the GIL released during the run, restart from a checkpoint."""
import os
import threading
import unittest

import numpy as np
import yaml

import fsi
from common import SCENES, command, fresh, read_bytes

CANTILEVER = os.path.join(SCENES, "cantilever.yaml")
SHORT = ["time.end=0.3", "checkpoint.interval_steps=100", "checkpoint.keep=5"]


class CantileverRunTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # The reference: the command, one thread.
        cls.cli = fresh("cantilever_cli")
        args = ["run", CANTILEVER, "--out", cls.cli, "--threads", "1"]
        for o in SHORT:
            args += ["--set", o]
        status, _, err = command(*args)
        assert status == 0, err
        cls.calls = []
        cls.py = fresh("cantilever_py")
        cls.result = fsi.load(CANTILEVER, SHORT).run(
            out=cls.py, threads=1, progress=lambda t, step: cls.calls.append((t, step)),
            progress_interval=0.0)

    def test_probes_equal_the_commands_bit_for_bit(self):
        self.assertEqual(read_bytes(os.path.join(self.py, "probes.csv")),
                         read_bytes(os.path.join(self.cli, "probes.csv")))
        probes, cli = self.result.probes, fsi.result(self.cli).probes
        self.assertEqual(sorted(probes), ["time", "tip_x", "tip_y"])
        self.assertEqual(len(probes["time"]), 31)  # t = 0, 0.01, ..., 0.3
        for name in probes:
            self.assertTrue(np.array_equal(probes[name], cli[name]), name)
        self.assertLess(probes["tip_y"][-1], -1e-3)  # the beam sags under its weight

    def test_fields_equal_the_commands_bit_for_bit(self):
        cli = fsi.result(self.cli)
        self.assertTrue(np.array_equal(self.result.frame_times(), cli.frame_times()))
        self.assertEqual(len(self.result.frame_times()), 31)
        for name in ["position", "displacement", "velocity", "von_mises"]:
            for frame in (1, 15, -1):
                a = self.result.field(name, frame=frame, grid="beam")
                self.assertTrue(np.array_equal(a, cli.field(name, frame=frame, grid="beam")))
        u = self.result.field("displacement", frame=-1)
        self.assertEqual(u.shape[1], 2)
        # The probe is the tip node's displacement: the field holds it (probes.csv: 10 digits).
        tip = np.argmin(np.linalg.norm(self.result.field("position", 0) - [1.0, 0.05], axis=1))
        probe = self.result.probes["tip_y"][-1]
        self.assertAlmostEqual(u[tip, 1], probe, delta=1e-9 * abs(probe))

    def test_run_json_as_dict(self):
        run = self.result.run
        self.assertEqual(run["status"], "completed")
        self.assertEqual(run["steps"], 300)
        self.assertEqual(run["threads"], 1)
        self.assertEqual(run["overrides"], SHORT)
        self.assertEqual(run["simulated_time"], 0.3)

    def test_progress_every_step_to_the_end(self):
        self.assertEqual([s for _, s in self.calls], list(range(1, 301)))
        self.assertEqual(self.calls[-1][0], 0.3)

    def test_dict_scene_runs_the_same_bits(self):
        with open(CANTILEVER) as f:
            tree = yaml.safe_load(f)
        out = fresh("cantilever_dict")
        fsi.from_dict(tree, SHORT, directory=SCENES).run(out=out, threads=1)
        self.assertEqual(read_bytes(os.path.join(out, "probes.csv")),
                         read_bytes(os.path.join(self.cli, "probes.csv")))

    def test_restart_from_a_checkpoint_continues_bitwise(self):
        out = fresh("cantilever_restart")
        first = fsi.load(CANTILEVER, SHORT).run(out=out, threads=1)
        checkpoints = first.checkpoints()
        self.assertEqual([os.path.basename(c) for c in checkpoints],
                         [f"checkpoint_{s:09d}.h5" for s in (100, 200, 300)])
        again = fsi.load(CANTILEVER, SHORT).run(out=out, threads=1, restart=checkpoints[0])
        self.assertEqual(again.run["restarted_from"], checkpoints[0])
        self.assertEqual(read_bytes(os.path.join(out, "probes.csv")),
                         read_bytes(os.path.join(self.cli, "probes.csv")))

    def test_an_exception_in_progress_stops_the_run_with_a_checkpoint(self):
        out = fresh("cantilever_stopped")

        def stop(t, step):
            if step == 42:
                raise ValueError("enough")

        with self.assertRaisesRegex(ValueError, "enough"):
            fsi.load(CANTILEVER, ["time.end=0.3"]).run(out=out, threads=1, progress=stop,
                                                      progress_interval=0.0)
        result = fsi.result(out)
        self.assertEqual(result.run["status"], "interrupted")
        self.assertEqual(result.run["steps"], 42)
        self.assertEqual([os.path.basename(c) for c in result.checkpoints()],
                         ["checkpoint_000000042.h5"])

    def test_other_python_threads_run_during_a_run(self):
        # With the GIL held for the run this loop would stand still until it returned.
        out = fresh("cantilever_gil")
        done, count, at_end = threading.Event(), [0], []
        scene = fsi.load(CANTILEVER, ["time.end=0.5"])
        # progress_interval 1e9 s: called once, after the last step, with the loop's count then.
        worker = threading.Thread(target=lambda: (
            scene.run(out=out, threads=1, progress=lambda t, s: at_end.append(count[0]),
                      progress_interval=1e9),
            done.set()))
        worker.start()
        while not done.is_set():
            count[0] += 1
        worker.join()
        self.assertEqual(len(at_end), 1)
        self.assertGreater(at_end[0], 1000)

    def test_run_errors_are_exceptions(self):
        with self.assertRaises(fsi.InputError):
            fsi.load(CANTILEVER, ["time.end=0.01"]).run(out=self.cli, threads=1)  # held by a run
        with self.assertRaises(fsi.InputError):
            fsi.load(CANTILEVER).run(out=fresh("x"), threads=fsi.available_processors() + 1)


if __name__ == "__main__":
    unittest.main()
