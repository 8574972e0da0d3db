"""The vertical pressure-gradient terms of an EMPS hydrostatic tank's interior column, layer by
layer, from the frames of DIR/fields.h5 (docs/fluid_emps.md, "Where the tank's +3 % sits").

usage: scripts/column_split DIR --l0 L --depth H --width X [--width-z Z] [--re 3.1]
                                [--alpha-rep 1e5] [--rho 1000] [--g 9.81] [--window 0.5]

2-D (positions (x, y)) or 3-D (x, y, z), y up, the floor at y = 0, the side walls at x = 0, X
(and z = 0, Z). The interior column: particles at least r_e from every side wall, so that the
floor is the only wall acting on them. For each frame of the last --window seconds and each such
particle i, with p, free_surface and positions as written:
  eq. 10 fluid sum   d/n0 sum_j (p_j + p_i) (y_j - y_i) w_ij / r_ij^2, split into the neighbours
                     j on the free surface (p_j = 0, eq. 17) and the rest
  floor mirror       eqs. 25-26 across y = 0: d/n0 R_ref sum_j (p_j + p_i) (x_j - x_i') w / r^2,
                     x_i' = (x_i, -y_i), j = i included, p_i' = p_i
  repulsion          eq. 27: -alpha_rep (l0/2 / y_i - 1) for y_i < l0/2
all in the units of grad p (Pa/m) and printed over rho g per layer (y in [k l0, (k + 1) l0)),
with the balance (terms + rho g, the particle's acceleration times rho over rho g).
Then the bottom layer's mean pressure against rho g (H - l0/2), and the floor's support of the
column: its mirror and repulsion terms summed over the column (times V) against the column's
weight (the fluid sums are antisymmetric in pairs: what the floor carries beyond the column's
weight, the fluid around the column pushes onto it).
Only the viscous terms (0 at rest) are left out.
"""
import argparse
import math

import h5py
import numpy as np
from scipy.spatial import cKDTree


def lattice_n0(dim, re_over_l0):
    """n0 of eq. 9 on the full square (cubic) lattice of spacing 1, w = (1 - r/r_e)^2."""
    k = int(math.ceil(re_over_l0))
    axes = [np.arange(-k, k + 1)] * dim
    r = np.sqrt(sum(a.astype(float) ** 2 for a in np.meshgrid(*axes, indexing="ij"))).ravel()
    r = r[(r > 0) & (r < re_over_l0)]
    return float(np.sum((1.0 - r / re_over_l0) ** 2))


def frame_terms(x, p, free, a):
    """Per interior-column particle: (y, p, free-surface sum, rest sum, mirror, repulsion), the
    vertical terms in Pa/m."""
    dim = x.shape[1]
    r_e, l0 = a.re * a.l0, a.l0
    c = dim / a.n0
    widths = [a.width] + ([a.width_z] if dim == 3 else [])
    horiz = [0] + ([2] if dim == 3 else [])
    inner = np.ones(len(x), bool)
    for ax, wd in zip(horiz, widths):
        inner &= (x[:, ax] >= r_e) & (x[:, ax] <= wd - r_e)
    tree = cKDTree(x)
    out = []
    for i in np.nonzero(inner)[0]:
        js = np.array([j for j in tree.query_ball_point(x[i], r_e) if j != i], dtype=int)
        d = x[js] - x[i]
        r2 = np.sum(d * d, axis=1)
        term = (p[js] + p[i]) * (1.0 - np.sqrt(r2) / r_e) ** 2 / r2 * d[:, 1]
        surf = c * np.sum(term[free[js]])
        rest = c * np.sum(term[~free[js]])
        mirror = 0.0
        if x[i, 1] < r_e:
            m = x[i].copy()
            m[1] = -m[1]
            jm = np.array(tree.query_ball_point(m, r_e), dtype=int)
            dm = x[jm] - m
            rm2 = np.sum(dm * dm, axis=1)
            mirror = -c * np.sum((p[jm] + p[i]) * (1.0 - np.sqrt(rm2) / r_e) ** 2 / rm2 * dm[:, 1])
        y = x[i, 1]
        rep = -a.alpha_rep * (0.5 * l0 / max(y, 1e-3 * 0.5 * l0) - 1.0) if y < 0.5 * l0 else 0.0
        out.append((y, p[i], surf, rest, mirror, rep))
    return np.array(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--l0", type=float, required=True)
    ap.add_argument("--depth", type=float, required=True, help="H, m")
    ap.add_argument("--width", type=float, required=True, help="tank width along x, m")
    ap.add_argument("--width-z", type=float, default=None, help="tank width along z (3-D), m")
    ap.add_argument("--re", type=float, default=3.1, help="r_e / l0")
    ap.add_argument("--alpha-rep", type=float, default=1e5)
    ap.add_argument("--rho", type=float, default=1000.0)
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--window", type=float, default=0.5, help="last seconds averaged")
    a = ap.parse_args()
    rho_g = a.rho * a.g
    with h5py.File(f"{a.dir}/fields.h5", "r") as f:
        frames = sorted(f["frames"], key=int)
        times = [f["frames"][k].attrs["time"] for k in frames]
        end = times[-1]
        chosen = [k for k, t in zip(frames, times) if t >= end - a.window - 1e-9]
        dim = f["frames"][chosen[0]]["particles/position"].shape[1]
        a.n0 = lattice_n0(dim, a.re)
        if dim == 3 and a.width_z is None:
            a.width_z = a.width
        layers = int(round(a.depth / a.l0))
        acc = np.zeros((layers, 7))  # count, y, p, surf, rest, mirror, rep
        rows = np.concatenate([frame_terms(f["frames"][k]["particles/position"][:],
                                           f["frames"][k]["particles/pressure"][:],
                                           f["frames"][k]["particles/free_surface"][:].astype(bool),
                                           a) for k in chosen])
    lay = np.clip((rows[:, 0] / a.l0).astype(int), 0, layers - 1)
    for r, li in zip(rows, lay):
        acc[li, 0] += 1
        acc[li, 1:] += r
    ref = rho_g * (a.depth - 0.5 * a.l0)
    print(f"{a.dir}: {dim}-D, H/l0 = {a.depth / a.l0:.3g}, r_e = {a.re} l0, n0 = {a.n0:.6g}, "
          f"{len(chosen)} frames over the last {a.window} s, {len(rows) / len(chosen):.0f} "
          f"particles in the interior column")
    print("layer  y/l0   p/(rho g l0)  p/(rho g (H - y))  free-surf.  rest      mirror    repulsion  balance"
          "   (terms over rho g)")
    for li in range(layers):
        n = acc[li, 0]
        if n == 0:
            continue
        y, p, surf, rest, mir, rep = acc[li, 1:] / n
        bal = (surf + rest + mir + rep) / rho_g + 1.0
        print(f"{li + 1:5d}  {y / a.l0:5.2f}  {p / (rho_g * a.l0):12.3f}  "
              f"{p / (rho_g * (a.depth - y)):17.4f}  "
              f"{surf / rho_g:+9.4f}  {rest / rho_g:+8.4f}  {mir / rho_g:+8.4f}  "
              f"{rep / rho_g:+9.4f}  {bal:+8.4f}")
    bottom = rows[:, 0] < a.l0
    p1 = np.mean(rows[bottom, 1])
    print(f"bottom layer of the column: {p1:.1f} Pa, {(p1 / ref - 1) * 100:+.2f} % of "
          f"rho g (H - l0/2) = {ref:.1f} Pa")
    support = -np.sum(rows[:, 4] + rows[:, 5]) / (len(rows) * rho_g)
    print(f"floor's support of the column over its weight: {support:.4f} (mirror "
          f"{-np.sum(rows[:, 4]) / (len(rows) * rho_g):.4f}, repulsion "
          f"{-np.sum(rows[:, 5]) / (len(rows) * rho_g):.4f})")


if __name__ == "__main__":
    main()
