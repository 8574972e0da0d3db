"""Centre deflection w D / (q a^4) of a square Mindlin plate under uniform load q.

The reference of tests/structure_fem/test_clamped_plate_t10.cpp. Ritz method on the energy
  U = 1/2 int D [tx,x^2 + ty,y^2 + 2 nu tx,x ty,y + (1 - nu)/2 (tx,y + ty,x)^2]
    + 1/2 int k G h [(w,x + tx)^2 + (w,y + ty)^2] - int q w
with w, tx, ty sums of c_ij f_i(xi) g_j(eta), f and g Legendre polynomials P_i, or (1 - xi^2) P_i
where the field vanishes on those edges (x = a xi / 2); w even in x and y, tx odd in x, ty odd in y.
  clamped: w = tx = ty = 0 on every edge.
  simple (hard simple support, SS2): w = 0 and the rotation along each edge (ty on x = +-a/2, tx on
  y = +-a/2) = 0; the normal moment vanishes naturally. Its exact solution is Kirchhoff's plus the
  Marcus moment over the shear stiffness, w = w_K + M / (k G h) with lap M = -q, M = 0 on the edges
  (Wang, Reddy & Lee, Shear Deformable Beams and Plates, 2000, eq. 5.3.21), summed here as
  Navier series: the check of this Ritz code (`check`).
Prints the values at three degrees (converged when they agree) and the clamped thin limit,
0.00126532 (Taylor & Govindjee 2004: 1.265319087e-3; Timoshenko & Woinowsky-Krieger, Table 35: 0.00126).
Usage: python3 scripts/mindlin_square_plate.py [a/h] [nu]   (defaults 10, 0.3; k = 5/6)
"""
import sys

import numpy as np
from numpy.polynomial import legendre

K_SHEAR = 5.0 / 6.0


def centre_deflection(a_over_h, nu, degree, support="clamped", k=K_SHEAR, points=80):
    a, E, q = 1.0, 1.0, 1.0
    h = a / a_over_h
    D = E * h**3 / (12.0 * (1.0 - nu**2))
    S = k * E / (2.0 * (1.0 + nu)) * h
    xi, weight = legendre.leggauss(points)
    jac = 0.5 * a
    clamped = support == "clamped"

    def basis(parity, vanishes):
        """f_i(xi) and its x derivative for the degrees i of the given parity."""
        B, dB = [], []
        for i in range(parity, degree, 2):
            c = np.zeros(i + 1)
            c[i] = 1.0
            P, dP = legendre.legval(xi, c), legendre.legval(xi, legendre.legder(c))
            if vanishes:
                B.append((1.0 - xi**2) * P)
                dB.append((-2.0 * xi * P + (1.0 - xi**2) * dP) / jac)
            else:
                B.append(P)
                dB.append(dP / jac)
        return np.array(B), np.array(dB)

    def field(bx, by):
        """Products f(x) g(y), with their x and y derivatives, at the Gauss points."""
        (Bx, dBx), (By, dBy) = bx, by
        outer = lambda f, g: np.einsum("ia,jb->ijab", f, g).reshape(-1, points, points)
        return outer(Bx, By), outer(dBx, By), outer(Bx, dBy)

    W2 = np.outer(weight, weight) * jac * jac
    inner = lambda f, g: np.einsum("iab,jab,ab->ij", f, g, W2)
    w, w_x, w_y = field(basis(0, True), basis(0, True))
    tx, tx_x, tx_y = field(basis(1, clamped), basis(0, True))
    ty, ty_x, ty_y = field(basis(0, True), basis(1, clamped))
    Kww = S * (inner(w_x, w_x) + inner(w_y, w_y))
    Kwx, Kwy = S * inner(w_x, tx), S * inner(w_y, ty)
    Kxx = D * (inner(tx_x, tx_x) + 0.5 * (1 - nu) * inner(tx_y, tx_y)) + S * inner(tx, tx)
    Kyy = D * (inner(ty_y, ty_y) + 0.5 * (1 - nu) * inner(ty_x, ty_x)) + S * inner(ty, ty)
    Kxy = D * (nu * inner(tx_x, ty_y) + 0.5 * (1 - nu) * inner(tx_y, ty_x))
    K = np.block([[Kww, Kwx, Kwy], [Kwx.T, Kxx, Kxy], [Kwy.T, Kxy.T, Kyy]])
    f = np.concatenate([q * np.einsum("iab,ab->i", w, W2), np.zeros(len(tx) + len(ty))])
    c = np.linalg.solve(K, f)
    P0 = np.array([legendre.legval(0.0, np.eye(i + 1)[i]) for i in range(0, degree, 2)])
    return np.outer(P0, P0).reshape(-1) @ c[: len(w)] * D / (q * a**4)


def simple_support_exact(a_over_h, nu, k=K_SHEAR, terms=2001):
    """w D / (q a^4) at the centre of the hard simply supported plate: Navier's w_K plus the
    Marcus moment M / (k G h), both as double sine series (m, n odd) at the centre."""
    m = np.arange(1, terms + 1, 2, dtype=float)
    M, N = np.meshgrid(m, m, indexing="ij")
    sign = (-1.0) ** ((M + N) / 2 - 1)
    w_kirchhoff = 16.0 / np.pi**6 * np.sum(sign / (M * N * (M**2 + N**2) ** 2))
    marcus = 16.0 / np.pi**4 * np.sum(sign / (M * N * (M**2 + N**2)))  # M / (q a^2)
    shear = 6.0 * k * (1.0 - nu) * a_over_h**2  # k G h a^2 / D
    return w_kirchhoff + marcus / shear


def check(a_over_h, nu, degree=24):
    """Relative difference of the Ritz simple-support value from the exact one."""
    exact = simple_support_exact(a_over_h, nu)
    return (centre_deflection(a_over_h, nu, degree, "simple") - exact) / exact


if __name__ == "__main__":
    a_over_h = float(sys.argv[1]) if len(sys.argv) > 1 else 10.0
    nu = float(sys.argv[2]) if len(sys.argv) > 2 else 0.3
    for degree in (16, 24, 32):
        print(f"clamped, a/h = {a_over_h:g}, degree {degree}: "
              f"{centre_deflection(a_over_h, nu, degree):.8f}")
    print(f"clamped, thin limit (a/h = 1e4): {centre_deflection(1.0e4, nu, 24):.8f}")
    for degree in (16, 24, 32):
        print(f"simple (SS2), a/h = {a_over_h:g}, degree {degree}: "
              f"{centre_deflection(a_over_h, nu, degree, 'simple'):.8f}")
    print(f"simple (SS2), exact w_K + M/(k G h): {simple_support_exact(a_over_h, nu):.8f}")
