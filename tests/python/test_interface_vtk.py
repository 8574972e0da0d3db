"""scripts/interface_vtk.py without ParaView: the 6-node faces' surface mass matrix against the
closed form, the traction projected from consistent nodal loads of a uniform and of a linearly
varying pressure equal to that pressure at every node, and a 2-D record (no /faces) refused with
one line and exit 2. tests/apps/test_interface_vtk.py opens the written series in ParaView."""
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

from common import SOURCE

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
import interface_vtk as iv  # noqa: E402

# The flat T6 mass matrix over area A, times 180 / A (corners, then mid-sides 0-1, 1-2, 2-0).
T6_MASS = np.array([[6, -1, -1, 0, -4, 0], [-1, 6, -1, 0, 0, -4], [-1, -1, 6, -4, 0, 0],
                    [0, 0, -4, 32, 16, 16], [-4, 0, 0, 16, 32, 16], [0, -4, 0, 16, 16, 32]])


def plate(cells, size, y=0.0):
    """A flat square [0, size]^2 in the plane y, cells x cells quads split in two 6-node faces:
    (node positions [n x 3], faces [m x 6])."""
    k = 2 * cells + 1  # nodes along a side, mid-sides included
    grid = np.linspace(0.0, size, k)
    x = np.array([(grid[i], y, grid[j]) for i in range(k) for j in range(k)])

    def node(i, j):
        return i * k + j

    faces = []
    for i in range(0, 2 * cells, 2):
        for j in range(0, 2 * cells, 2):
            a, b, c, d = node(i, j), node(i + 2, j), node(i + 2, j + 2), node(i, j + 2)
            faces.append((a, b, c, node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 1)))
            faces.append((a, c, d, node(i + 1, j + 1), node(i + 1, j + 2), node(i, j + 1)))
    return x, np.array(faces)


class InterfaceVtkTest(unittest.TestCase):
    def test_face_mass_is_the_closed_form(self):
        x = np.array([(0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (0.5, 0.0, 1.5)])
        x = np.vstack([x, 0.5 * (x + np.roll(x, -1, axis=0))])  # mid-sides 0-1, 1-2, 2-0
        mass = iv.face_mass(x, np.array([[0, 1, 2, 3, 4, 5]]))[0]
        np.testing.assert_allclose(mass, T6_MASS * 1.5 / 180.0, rtol=0.0, atol=1e-15)

    def test_uniform_pressure_gives_its_traction(self):
        p, n = 4905.0, np.array([0.0, -1.0, 0.0])  # the hydrostatic plate's rho g H, downwards
        x, faces = plate(4, 1.0)
        load = np.zeros_like(x)
        area = 1.0 / (2 * 4 * 4)  # each face's; its consistent loads: corners 0, mid-sides A/3 p
        for f in faces:
            load[f[3:]] += p * n * area / 3.0
        t = iv.Projection(x, faces).solve(load)
        np.testing.assert_allclose(t, np.tile(p * n, (len(x), 1)), rtol=0.0, atol=1e-12 * p)

    def test_linear_pressure_gives_its_traction(self):
        x, faces = plate(3, 0.6, y=0.25)
        want = np.zeros_like(x)
        want[:, 1] = 1000.0 + 8000.0 * x[:, 0] - 3000.0 * x[:, 2]  # in the faces' quadratic space
        projection = iv.Projection(x, faces)
        t = projection.solve(projection.apply(want))  # its consistent loads M p
        np.testing.assert_allclose(t, want, rtol=0.0, atol=1e-11 * np.abs(want).max())

    def test_two_d_record_refused(self):
        with tempfile.TemporaryDirectory() as d:
            with h5py.File(os.path.join(d, "interface.h5"), "w") as f:
                f["time"] = np.array([0.0, 0.1])
                for name in ("position", "velocity", "acceleration", "load"):
                    f[name] = np.zeros((2, 3, 2))
            p = subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "interface_vtk.py"),
                                d], capture_output=True, text=True)
            self.assertEqual(p.returncode, 2)
            self.assertEqual(p.stderr.count("\n"), 1)
            self.assertIn("/faces: missing", p.stderr)
            self.assertFalse(os.path.exists(os.path.join(d, "interface.pvd")))

    def test_a_shorter_record_leaves_no_old_rows(self):
        x, faces = plate(1, 1.0)
        with tempfile.TemporaryDirectory() as d:
            h5, pvd = os.path.join(d, "interface.h5"), os.path.join(d, "interface.pvd")
            for rows in (4, 2):
                with h5py.File(h5, "w") as f:
                    f["time"] = 0.1 * np.arange(rows)
                    f["faces"] = faces
                    f["position"] = np.tile(x, (rows, 1, 1))
                    for name in ("velocity", "acceleration", "load"):
                        f[name] = np.zeros((rows, len(x), 3))
                self.assertEqual(iv.convert(h5, pvd), rows)
                self.assertEqual(sorted(os.listdir(os.path.join(d, "interface"))),
                                 ["row_%06d.vtu" % k for k in range(rows)])


if __name__ == "__main__":
    unittest.main()
