"""fsi: scenes, runs and results of the fluid-structure interaction framework from Python.

    import fsi
    scene = fsi.load("data/scenes/cantilever.yaml", {"time.end": 0.1})
    scene.check()                          # fsi.InputError: "FILE:LINE: KEY: what is wrong"
    result = scene.run(out="out/cantilever", threads=1, overwrite=True,
                       progress=lambda t, step: print(t, step))
    result.probes["tip_y"]                 # NumPy arrays, "time" included
    result.field("displacement", frame=-1, grid="beam")
    result.run                             # run.json as a dict
    scene.run(out="out/cantilever", restart=result.checkpoints()[-1])   # continue

A scene is a file or a dict (the YAML tree as Python values) plus overrides, which are the
`--set key.path=value` of the command line: {"structures[0].material.density": 2000}. check()
and run() validate it exactly as `fsi check` and `fsi run` do; run() steps the models in this
process with the GIL released, so other Python threads go on.
"""
import csv
import json
import os

import numpy as np

from . import _fsi
from ._fsi import InputError, RunError, available_processors, git_revision  # noqa: F401

__version__ = _fsi.__version__
__all__ = ["Scene", "Result", "Interrupted", "InputError", "RunError", "load", "from_dict",
           "result", "reference", "available_processors"]


class Interrupted(KeyboardInterrupt):
    """A run stopped by SIGINT / SIGTERM after a step; `checkpoint` continues it."""

    def __init__(self, signal, step, time, checkpoint):
        super().__init__(f"interrupted by signal {signal} at step {step}, t = {time:g} s; "
                         f"continue with restart={checkpoint!r}")
        self.signal, self.step, self.time, self.checkpoint = signal, step, time, checkpoint


def _override_text(key, value):
    """`key=value` with the value in YAML syntax (JSON is YAML): strings as given."""
    if isinstance(value, str):
        return f"{key}={value}"
    if isinstance(value, np.generic):
        value = value.item()
    return f"{key}={json.dumps(value)}"


class Scene:
    """A scene file or dict plus overrides. Cheap: every check() / run() reads it again."""

    def __init__(self, file, text=None, overrides=()):
        self.file = os.fspath(file)
        self.text = text
        self.overrides = list(overrides)

    def set(self, key, value):
        """Adds the override `key=value` (the command line's --set); returns self."""
        self.overrides.append(_override_text(key, value))
        return self

    def with_overrides(self, overrides):
        """A copy with more overrides (a dict key -> value or `key=value` strings)."""
        return Scene(self.file, self.text, self.overrides + _override_list(overrides))

    def check(self):
        """Validates the scene and builds its models as `fsi check`; returns the scene's name.
        Raises fsi.InputError with the command's one-line `FILE:LINE: KEY: what` message."""
        return _fsi.check(self.file, self.text, self.overrides)

    def run(self, out, threads=0, progress=None, restart=None, overwrite=False,
            progress_interval=0.5, quiet=True):
        """Runs the scene into the folder `out` (as `fsi run --out OUT`) and returns its Result.

        threads: OpenMP threads (0: all processors); progress(time, step): called at most every
        progress_interval wall seconds and after the last step (an exception it raises stops the
        run after that step with a checkpoint, and is raised again); restart: a checkpoint_*.h5
        of an earlier run into `out` to continue; overwrite: replace an earlier run's files;
        quiet: no log lines on stderr. Raises fsi.InputError, fsi.RunError (the run stopped:
        run.json and a failed_state.h5 are kept) or fsi.Interrupted (SIGINT / SIGTERM)."""
        r = _fsi.run(self.file, self.text, self.overrides, os.fspath(out), int(threads),
                     os.fspath(restart) if restart else "", bool(overwrite), progress,
                     float(progress_interval), bool(quiet))
        if r["signal"]:
            raise Interrupted(r["signal"], r["step"], r["time"], r["checkpoint"])
        return Result(out)

    def __repr__(self):
        return f"fsi.Scene({self.file!r}, overrides={self.overrides!r})"


def _override_list(overrides):
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return [_override_text(k, v) for k, v in overrides.items()]
    # A lone string would be iterated character by character (issue 41).
    if isinstance(overrides, (str, bytes)) or not hasattr(overrides, "__iter__"):
        raise TypeError("overrides: expected a dict (key -> value) or a list of 'key=value' "
                        f"strings, got {type(overrides).__name__} {overrides!r}; e.g. "
                        f"[{overrides!r}]")
    return [str(o) for o in overrides]


def load(file, overrides=None):
    """The scene of a YAML file, with overrides (dict key -> value, or `key=value` strings)."""
    return Scene(file, None, _override_list(overrides))


def from_dict(tree, overrides=None, directory=None, name="<dict>"):
    """A scene from a dict (the YAML tree). Messages name `DIRECTORY/NAME:LINE` with the line of
    the key in the dict dumped as indented JSON; relative file paths resolve against directory
    (default: the current directory)."""
    file = os.path.join(os.path.abspath(directory or os.getcwd()), name)
    return Scene(file, json.dumps(tree, indent=1), _override_list(overrides))


def reference():
    """The scene-file reference (Markdown), as `fsi reference` prints it."""
    return _fsi.reference()


def result(out):
    """The Result of an earlier run into the folder `out`."""
    return Result(out)


class Result:
    """What a run wrote into its folder: probes, run.json, fields.h5, checkpoints."""

    def __init__(self, out):
        self.out = os.fspath(out)

    @property
    def run(self):
        """run.json as a dict (scene, overrides, status, timing, counts, coupling statistics)."""
        with open(os.path.join(self.out, "run.json")) as f:
            return json.load(f)

    @property
    def probes(self):
        """probes.csv as a dict column name -> float64 array ("time" and every probe); the
        numbers are the file's, parsed exactly."""
        with open(os.path.join(self.out, "probes.csv"), newline="") as f:
            rows = [r for r in csv.reader(f) if r]
        header, body = rows[0], rows[1:]
        table = np.array(body, dtype=np.float64).reshape(len(body), len(header))
        return {name: table[:, k].copy() for k, name in enumerate(header)}

    def _fields(self):
        import h5py  # only for fields: a probe-only user needs no h5py

        return h5py.File(os.path.join(self.out, "fields.h5"), "r")

    def frame_times(self):
        """The times of the frames in fields.h5, s (frame k at index k)."""
        with self._fields() as f:
            frames = f["frames"]
            return np.array([frames[str(k)].attrs["time"] for k in range(len(frames))])

    def grids(self, frame=0):
        """The grids (fluid, structure names) of a frame and the fields each holds."""
        with self._fields() as f:
            g = f["frames"][str(self._frame_index(f, frame))]
            return {name: sorted(g[name].keys()) for name in g}

    def field(self, name, frame=-1, grid=None):
        """The array of field `name` ("position", "velocity", "pressure", "displacement", ...) of
        `grid` (default: the only grid holding it) at frame index `frame` (negative: from the
        end) as float64, one row per particle or node."""
        with self._fields() as f:
            k = self._frame_index(f, frame)
            g = f["frames"][str(k)]
            holders = [n for n in g if name in g[n]] if grid is None else [grid]
            if len(holders) != 1 or name not in g[holders[0]]:
                have = {n: sorted(g[n].keys()) for n in g}
                raise KeyError(f"{self.out}/fields.h5 frame {k}: field {name!r} of grid "
                               f"{grid!r}: the frame holds {have}")
            return np.array(g[holders[0]][name], dtype=np.float64)

    @staticmethod
    def _frame_index(f, frame):
        count = len(f["frames"])
        k = frame + count if frame < 0 else frame
        if not 0 <= k < count:
            raise IndexError(f"frame {frame}: fields.h5 has {count} frames")
        return k

    def checkpoints(self):
        """The checkpoint files of the run, oldest first (restart= continues from one)."""
        names = sorted(n for n in os.listdir(self.out)
                       if n.startswith("checkpoint_") and n.endswith(".h5"))
        return [os.path.join(self.out, n) for n in names]

    def __repr__(self):
        return f"fsi.Result({self.out!r})"
