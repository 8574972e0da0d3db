"""The Mindlin reference of the clamped T10 plate (scripts/mindlin_square_plate.py): its Ritz code
reproduces the exact hard simply supported solution (Kirchhoff's Navier series plus the Marcus moment
over the shear stiffness) to 1e-7, gives Taylor & Govindjee's clamped Kirchhoff value in the thin
limit, and its clamped value at a/h = 10 is converged to the digits test_clamped_plate_t10.cpp uses."""
import os
import sys
import unittest

from common import SOURCE

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
import mindlin_square_plate as plate  # noqa: E402

# w D / (q a^4) at the centre of a clamped square Kirchhoff plate (Taylor & Govindjee, Solution of
# clamped rectangular plate problems, Commun. Numer. Meth. Engng 20, 2004, 757-765).
TAYLOR_GOVINDJEE = 1.265319087e-3
# test_clamped_plate_t10.cpp's mindlin_coefficient (a/h = 10, nu = 0.3, k = 5/6).
T10_TEST_MINDLIN = 0.00150463


class MindlinPlate(unittest.TestCase):
    def test_simple_support_equals_the_exact_relation(self):
        for a_over_h, nu in ((10.0, 0.3), (5.0, 0.3), (20.0, 0.25)):
            with self.subTest(a_over_h=a_over_h, nu=nu):
                self.assertLess(abs(plate.check(a_over_h, nu)), 1.0e-7)

    def test_clamped_thin_limit_is_kirchhoff(self):
        # at a/h = 1e4 the shear term adds about 2e-7 (19 % at a/h = 10, times (h/a)^2)
        w = plate.centre_deflection(1.0e4, 0.3, 24)
        self.assertLess(abs(w / TAYLOR_GOVINDJEE - 1.0), 1.0e-6)

    def test_clamped_value_is_converged(self):
        w24 = plate.centre_deflection(10.0, 0.3, 24)
        w32 = plate.centre_deflection(10.0, 0.3, 32)
        self.assertLess(abs(w32 / w24 - 1.0), 1.0e-8)
        self.assertLess(abs(w32 / T10_TEST_MINDLIN - 1.0), 5.0e-6)


if __name__ == "__main__":
    unittest.main()
