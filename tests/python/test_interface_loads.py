"""scripts/interface_loads.py on made-up interface.h5 files: a 2-D record and the same load on
a 3-D slab (spread over its depth) give the same per-metre impulses, part by part."""
import os
import sys
import tempfile
import unittest

import h5py
import numpy as np

from common import SOURCE

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
import interface_loads as il  # noqa: E402

# The obstacle's outline x in [0, 0.01], y in [0, 0.08] (its base y = 0 clamped): left,
# top-left, top, top-right, right.
OUTLINE = [(0.0, 0.0), (0.0, 0.04), (0.0, 0.08), (0.005, 0.08), (0.01, 0.08), (0.01, 0.04),
           (0.01, 0.0)]
PART = [0, 0, 1, 2, 3, 4, 4]  # index into interface_loads.PARTS
# Loads (N/m) per node, constant in time: x on the sides, y on the top.
LOADS = [(1.5, 0.0), (3.0, 0.5), (2.0, -1.0), (0.25, -4.0), (-0.5, -1.5), (-1.0, 0.125),
         (-2.0, 0.0)]
TIME = [0.0, 0.1, 0.2, 0.3]


def write(path, points, loads):
    rows = len(TIME)
    with h5py.File(path, "w") as f:
        f["time"] = np.array(TIME)
        f["position"] = np.repeat(np.array(points)[None], rows, axis=0)
        f["load"] = np.repeat(np.array(loads)[None], rows, axis=0)


class InterfaceLoadsTest(unittest.TestCase):
    def test_slab_per_metre_equals_plane(self):
        with tempfile.TemporaryDirectory() as d:
            plane, slab = os.path.join(d, "plane.h5"), os.path.join(d, "slab.h5")
            write(plane, OUTLINE, LOADS)
            depth = 0.5  # three z layers, the load shared 1/4, 1/2, 1/4 over them
            points, loads = [], []
            for z, share in ((0.0, 0.25), (0.25, 0.5), (0.5, 0.25)):
                points += [(x, y, z) for x, y in OUTLINE]
                loads += [(share * depth * fx, share * depth * fy, 7.0) for fx, fy in LOADS]
            write(slab, points, loads)
            a = il.impulses(il.read(plane), 0.1, 0.3)
            b = il.impulses(il.read(slab), 0.1, 0.3)
            for k, part in enumerate(il.PARTS):  # two steps of 0.1 s inside the window
                for c in range(2):
                    f = sum(q[c] for q, j in zip(LOADS, PART) if j == k)
                    self.assertAlmostEqual(a[part][c], 0.2 * f, places=14)
                    self.assertAlmostEqual(b[part][c], a[part][c], places=14)
                for c in range(2, 5):
                    self.assertAlmostEqual(b[part][c], a[part][c], places=14)
            # The moment about the base's centre (0.005, 0): y fx - (x - 0.005) fy.
            mx = sum(y * fx for (x, y), (fx, fy) in zip(OUTLINE, LOADS))
            my = sum(-(x - 0.005) * fy for (x, y), (fx, fy) in zip(OUTLINE, LOADS))
            self.assertAlmostEqual(a["total"][3], 0.2 * mx, places=14)
            self.assertAlmostEqual(a["total"][4], 0.2 * my, places=14)
            self.assertAlmostEqual(a["total"][2], 0.2 * (mx + my), places=14)

    def test_a_node_on_no_face_is_refused(self):
        with self.assertRaises(SystemExit):
            il.parts_of(np.array(OUTLINE + [(0.005, 0.04)]))


if __name__ == "__main__":
    unittest.main()
