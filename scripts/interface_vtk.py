"""A 3-D coupled run's interface.h5 as a ParaView time series (issue 46): one .vtu per recorded
row, the interface's 6-node faces as VTK quadratic triangles (cell type 22: corners, then the
mid-sides 0-1, 1-2, 2-0, /faces' order) at that row's positions, with the point arrays velocity,
acceleration, load (N, per node: what the structure took) and traction (N/m^2), and a .pvd
listing them with their times. Open the .pvd in ParaView and step through time.

Each time's file holds that row alone, so no reader has to pick a row out of the [N x n x 3]
datasets (the XDMF hyperslab index ParaView 5.11 read wrong rows from; docs/coupling.md).

traction: the nodal loads' L2 projection onto the faces' quadratic field over the reference
surface (row 0), M t = f with M_ij = int N_i N_j dA: a T6 face's consistent nodal loads put
nothing on its corners under a uniform pressure p, while t = p n at every node. So |traction| is
the load magnitude to colour a surface by; sum_i a_i t_i = sum_i f_i with a_i = int N_i dA (to the
solver's tolerance, 1e-14 |f|).

usage: scripts/interface_vtk RUN_DIR|interface.h5 [--out FILE.pvd]
(default RUN_DIR/interface.pvd, its rows in RUN_DIR/interface/row_<k>.vtu)
"""
import argparse
import glob
import os
import sys

import h5py
import numpy as np


def fail(message):
    """Bad input: one line, exit 2."""
    print(message, file=sys.stderr)
    sys.exit(2)

QUADRATIC_TRIANGLE = 22  # VTK_QUADRATIC_TRIANGLE
ARRAYS = ("velocity", "acceleration", "load")

# Dunavant's 6-point rule on the reference triangle, degree 4 (exact for N_i N_j on a flat face):
# (area coordinates L2, L3), weights summing to 1.
_A, _B = 0.44594849091596488632, 0.09157621350977074346
_WA, _WB = 0.22338158967801146570, 0.10995174365532186764
QUAD_POINTS = np.array([(_A, _A), (1 - 2 * _A, _A), (_A, 1 - 2 * _A),
                        (_B, _B), (1 - 2 * _B, _B), (_B, 1 - 2 * _B)])
QUAD_WEIGHTS = np.array([_WA] * 3 + [_WB] * 3)


def shape(xi, eta):
    """T6 shape functions and their derivatives in (xi, eta) at one point, node order of /faces."""
    l1 = 1.0 - xi - eta
    n = np.array([l1 * (2 * l1 - 1), xi * (2 * xi - 1), eta * (2 * eta - 1),
                  4 * l1 * xi, 4 * xi * eta, 4 * eta * l1])
    d_xi = np.array([1 - 4 * l1, 4 * xi - 1, 0.0, 4 * (l1 - xi), 4 * eta, -4 * eta])
    d_eta = np.array([1 - 4 * l1, 0.0, 4 * eta - 1, -4 * xi, 4 * xi, 4 * (l1 - eta)])
    return n, d_xi, d_eta


def face_mass(x, faces):
    """[m x 6 x 6] consistent surface mass matrices int N_i N_j dA of the faces at positions x
    (isoparametric, dA = |x_xi x x_eta| dxi deta)."""
    xe = x[faces]  # [m x 6 x 3]
    mass = np.zeros((len(faces), 6, 6))
    for (xi, eta), w in zip(QUAD_POINTS, QUAD_WEIGHTS):
        n, d_xi, d_eta = shape(xi, eta)
        jac = np.linalg.norm(np.cross(d_xi @ xe, d_eta @ xe), axis=1)  # 2 x the area's scale
        mass += (0.5 * w * jac)[:, None, None] * np.outer(n, n)[None]
    return mass


class Projection:
    """Solves M t = f on the faces' nodes by conjugate gradients with Jacobi preconditioning, M
    assembled face by face (never as a matrix: any interface size)."""

    def __init__(self, x0, faces):
        self.faces, self.mass = faces, face_mass(x0, faces)
        self.diagonal = np.zeros(len(x0))
        np.add.at(self.diagonal, faces, np.einsum("mii->mi", self.mass))

    def apply(self, t):
        out = np.zeros_like(t)
        np.add.at(out, self.faces, np.einsum("mij,mjc->mic", self.mass, t[self.faces]))
        return out

    def solve(self, f, tolerance=1e-14):
        """t with |M t - f| <= tolerance |f|."""
        t, r = np.zeros_like(f), f.copy()
        goal = tolerance * np.linalg.norm(f)
        z = r / self.diagonal[:, None]
        p, rz = z.copy(), np.sum(r * z)
        for _ in range(10 * len(f) + 100):
            if np.linalg.norm(r) <= goal:
                return t
            q = self.apply(p)
            alpha = rz / np.sum(p * q)
            t += alpha * p
            r -= alpha * q
            z = r / self.diagonal[:, None]
            rz, rz_old = np.sum(r * z), rz
            p = z + (rz / rz_old) * p
        fail("interface_vtk: the traction's projection did not converge")


def vtu(points, faces, point_data):
    """One VTK XML UnstructuredGrid: float64 points and arrays appended raw (exact), UInt64 sizes."""
    blocks = [points, faces.astype("<i8").ravel(),
              (6 * np.arange(1, len(faces) + 1)).astype("<i8"),
              np.full(len(faces), QUADRATIC_TRIANGLE, dtype="u1")]
    blocks += list(point_data.values())
    raw, offsets, at = [], [], 0
    for b in blocks:
        data = np.ascontiguousarray(b).tobytes()
        raw.append(np.array([len(data)], dtype="<u8").tobytes() + data)
        offsets.append(at)
        at += len(raw[-1])

    def array(name, kind, comps, k):
        return ('<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="appended" '
                'offset="%d"/>' % (kind, name, comps, offsets[k]))

    arrays = "".join(array(name, "Float64", 3, 4 + k) for k, name in enumerate(point_data))
    head = ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" '
            'byte_order="LittleEndian" header_type="UInt64">\n<UnstructuredGrid>\n'
            '<Piece NumberOfPoints="%d" NumberOfCells="%d">\n<PointData>%s</PointData>\n'
            '<Points>%s</Points>\n<Cells>%s%s%s</Cells>\n</Piece>\n</UnstructuredGrid>\n'
            '<AppendedData encoding="raw">\n_'
            % (len(points), len(faces), arrays, array("Points", "Float64", 3, 0),
               array("connectivity", "Int64", 1, 1), array("offsets", "Int64", 1, 2),
               array("types", "UInt8", 1, 3)))
    return head.encode() + b"".join(raw) + b"\n</AppendedData>\n</VTKFile>\n"


def convert(h5_path, pvd_path):
    """Writes the series; returns the number of rows."""
    folder = os.path.splitext(pvd_path)[0]
    with h5py.File(h5_path, "r") as f:
        if "faces" not in f:
            fail("%s: /faces: missing (a 2-D record has no faces; 3-D only)" % h5_path)
        faces = f["faces"][...].astype(np.int64)
        time = f["time"][...]
        nodes = f["position"].shape[1]
        if faces.ndim != 2 or faces.shape[1] != 6 or faces.min() < 0 or faces.max() >= nodes:
            fail("%s: /faces: not [m x 6] indices of the %d nodes" % (h5_path, nodes))
        lonely = nodes - len(np.unique(faces))
        if lonely:
            fail("%s: /faces: %d of the %d nodes on no face" % (h5_path, lonely, nodes))
        projection = Projection(f["position"][0], faces)
        os.makedirs(folder, exist_ok=True)
        for old in glob.glob(os.path.join(folder, "row_[0-9][0-9][0-9][0-9][0-9][0-9].vtu")):
            os.remove(old)  # a longer earlier conversion's rows: the folder holds this series only
        entries = []
        for k, t in enumerate(time):
            data = {name: f[name][k] for name in ARRAYS}
            data["traction"] = projection.solve(data["load"])
            name = "row_%06d.vtu" % k
            with open(os.path.join(folder, name), "wb") as out:
                out.write(vtu(f["position"][k], faces, data))
            entries.append('<DataSet timestep="%r" file="%s/%s"/>'
                           % (float(t), os.path.basename(folder), name))
    with open(pvd_path, "w") as out:
        out.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                  "<Collection>\n%s\n</Collection>\n</VTKFile>\n" % "\n".join(entries))
    return len(time)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("record", help="a run folder holding interface.h5, or the file")
    p.add_argument("--out", help="the .pvd to write (default beside interface.h5)")
    a = p.parse_args()
    h5 = os.path.join(a.record, "interface.h5") if os.path.isdir(a.record) else a.record
    if not os.path.isfile(h5):
        fail("%s: no interface.h5 (run with coupling.record_interface=true)" % a.record)
    pvd = a.out or os.path.join(os.path.dirname(h5), "interface.pvd")
    rows = convert(h5, pvd)
    print("%s: %d times (open it in ParaView)" % (pvd, rows))


if __name__ == "__main__":
    main()
