#!/usr/bin/python3
"""High-precision reference table for references/heavy_column (tests/references/test_heavy_column_reference.cpp).

Greenhill's heavy column: (w L^3 / EI)_cr = (9/4) j^2, j the first positive zero of J_{-1/3}
(mpmath.besselj, findroot), cross-checked by shooting on the linearised slope equation
EI theta'' + w s theta = 0, theta(0) = 1, theta'(0) = 0 (mpmath.odefun, findroot on theta(1) = 0 with
EI = 1, L = 1): the two must agree to 1e-25. Not the C++ power series.
Every parameter is the exact binary value of the double printed in its column (mpf(float(text))).
Run: /usr/bin/python3 tests/data/make_heavy_column_table.py > tests/data/heavy_column_reference.csv
"""
import mpmath as mp

mp.mp.dps = 40


def d(text):
    """Exact value of the double nearest to text."""
    return mp.mpf(float(text))


def critical_weight():
    j = mp.findroot(lambda x: mp.besselj(mp.mpf(-1) / 3, x), mp.mpf("1.87"))
    by_bessel = mp.mpf(9) / 4 * j**2

    def foot_slope(x):
        # theta'' = -x s theta on [0, 1]: state (theta, theta')
        solution = mp.odefun(lambda s, y: [y[1], -x * s * y[0]], 0, [mp.mpf(1), mp.mpf(0)])
        return solution(1)[0]

    mp.mp.dps = 30
    by_shooting = mp.findroot(foot_slope, mp.mpf("7.8"))
    mp.mp.dps = 40
    assert abs(by_bessel - by_shooting) < mp.mpf(10) ** -25, (by_bessel, by_shooting)
    return by_bessel


def main():
    x = critical_weight()
    print("quantity,EI,w,value")
    print(f"critical_weight,,,{mp.nstr(x, 30)}")
    for EI, w in [("0.7", "2.3"), ("1.3", "0.05"), ("250.0", "9.81"), ("0.0021", "0.37"), ("3.5e4", "1.2e3")]:
        length = mp.cbrt(x * d(EI) / d(w))
        print(f"critical_length,{EI},{w},{mp.nstr(length, 30)}")


if __name__ == "__main__":
    main()
