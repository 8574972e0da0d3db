"""Centre deflection w D / (q a^4) of a clamped square Mindlin plate under uniform load q.

The reference of tests/structure_fem/test_clamped_plate_t10.cpp. Ritz method on the energy
  U = 1/2 int D [tx,x^2 + ty,y^2 + 2 nu tx,x ty,y + (1 - nu)/2 (tx,y + ty,x)^2]
    + 1/2 int k G h [(w,x + tx)^2 + (w,y + ty)^2] - int q w
with w, tx, ty = (1 - xi^2)(1 - eta^2) sum c_ij P_i(xi) P_j(eta) (Legendre P, x = a xi / 2), so
w = tx = ty = 0 on the edges; w even in x and y, tx odd in x, ty odd in y. Prints the value at
three degrees (converged when they agree) and the thin limit, 0.00126532 (Timoshenko &
Woinowsky-Krieger, Table 35: 0.00126).
Usage: python3 scripts/mindlin_clamped_plate.py [a/h] [nu]   (defaults 10, 0.3; k = 5/6)
"""
import sys

import numpy as np
from numpy.polynomial import legendre


def centre_deflection(a_over_h, nu, degree, k=5.0 / 6.0, points=80):
    a, E, q = 1.0, 1.0, 1.0
    h = a / a_over_h
    D = E * h**3 / (12.0 * (1.0 - nu**2))
    S = k * E / (2.0 * (1.0 + nu)) * h
    xi, weight = legendre.leggauss(points)
    jac = 0.5 * a

    def bubbles(parity):
        """(1 - xi^2) P_i(xi) and its x derivative for the degrees i of the given parity."""
        B, dB = [], []
        for i in range(parity, degree, 2):
            c = np.zeros(i + 1)
            c[i] = 1.0
            P, dP = legendre.legval(xi, c), legendre.legval(xi, legendre.legder(c))
            B.append((1.0 - xi**2) * P)
            dB.append((-2.0 * xi * P + (1.0 - xi**2) * dP) / jac)
        return np.array(B), np.array(dB)

    def field(bx, by):
        """Products f(x) g(y), with their x and y derivatives, at the Gauss points."""
        (Bx, dBx), (By, dBy) = bx, by
        outer = lambda f, g: np.einsum("ia,jb->ijab", f, g).reshape(-1, points, points)
        return outer(Bx, By), outer(dBx, By), outer(Bx, dBy)

    even, odd = bubbles(0), bubbles(1)
    W2 = np.outer(weight, weight) * jac * jac
    inner = lambda f, g: np.einsum("iab,jab,ab->ij", f, g, W2)
    w, w_x, w_y = field(even, even)
    tx, tx_x, tx_y = field(odd, even)
    ty, ty_x, ty_y = field(even, odd)
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


if __name__ == "__main__":
    a_over_h = float(sys.argv[1]) if len(sys.argv) > 1 else 10.0
    nu = float(sys.argv[2]) if len(sys.argv) > 2 else 0.3
    for degree in (16, 24, 32):
        print(f"a/h = {a_over_h:g}, degree {degree}: "
              f"{centre_deflection(a_over_h, nu, degree):.8f}")
    print(f"thin limit (a/h = 1e4): {centre_deflection(1.0e4, nu, 24):.8f}")
