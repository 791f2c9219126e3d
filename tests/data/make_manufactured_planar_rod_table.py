#!/usr/bin/python3
"""High-precision reference table for references/manufactured_planar_rod (tests/references/test_manufactured_rod_reference.cpp).

The planar manufactured elastica of manufactured_planar_rod.hpp, by mpmath (30 digits): r(L) by quadrature
of the closed-form tangent (mp.quad), then n and m by odefun in sigma = L - s from the tip loads (the C++
integrates r forward and all five fields backward with GSL's rk8pd). Every parameter is the exact double
printed. Rows at three stations.
Run: /usr/bin/python3 tests/data/make_manufactured_planar_rod_table.py > tests/data/manufactured_planar_rod_reference.csv
"""
import mpmath as mp

mp.mp.dps = 30
d = lambda v: mp.mpf(float(v))
L = d(1.6)
ROOT = (d(0.3), d(-0.5))
TH = dict(root=d(0.4), slope=d(1.1), sine=d(-0.7), cosine=d(0.35))
EI, VAR = d(0.9), d(0.25)
VXX, VXY, VY = d(1.3), d(-0.6), d(2.2)
F = (d(-0.8), d(1.7))
M = d(0.45)


def theta(s):
    return TH["root"] + TH["slope"] * s / L + TH["sine"] * mp.sin(mp.pi * s / L) + TH["cosine"] * (mp.cos(2 * mp.pi * s / L) - 1)


def kappa(s):
    return TH["slope"] / L + TH["sine"] * mp.pi / L * mp.cos(mp.pi * s / L) - TH["cosine"] * 2 * mp.pi / L * mp.sin(2 * mp.pi * s / L)


def main():
    xL = ROOT[0] + mp.quad(lambda s: mp.cos(theta(s)), [0, L / 2, L])
    yL = ROOT[1] + mp.quad(lambda s: mp.sin(theta(s)), [0, L / 2, L])

    def rhs(sigma, y):  # y = (x, y, nx, ny, m) as functions of sigma = L - s: d/dsigma = -d/ds
        s = L - sigma
        c, sn = mp.cos(theta(s)), mp.sin(theta(s))
        return [-c, -sn, -(VXX * y[0] + VXY * y[1]), -(VXY * y[0] + VY), (c * y[3] - sn * y[2])]

    solution = mp.odefun(rhs, 0, [xL, yL, F[0], F[1], M])
    print("s,quantity,value")
    for fraction in ("0", "0.35", "0.8"):
        s = d(fraction) * L
        x, y, nx, ny, m = solution(L - s)
        ei = EI * (1 + VAR * mp.sin(mp.pi * s / L))
        for name, value in (("x", x), ("y", y), ("force_x", nx), ("force_y", ny), ("moment", m),
                            ("natural_curvature", kappa(s) - m / ei)):
            print(f"{fraction},{name},{mp.nstr(value, 25)}")


if __name__ == "__main__":
    main()
