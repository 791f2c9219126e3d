#!/usr/bin/python3
"""High-precision reference table for references/heavy_touchdown (tests/references/test_heavy_touchdown_reference.cpp).

A heavy inextensible elastica (EI, weight w per length) clamped horizontally at height delta over a frictionless
floor, lifted off it over an arc length l_s and lying on it beyond: the exact, large-deflection solution by
shooting (mpmath.odefun, findroot), not the C++ closed forms. Arc length s from the touchdown, where theta = 0,
m = 0 (the flat part carries no moment) and, the floor being frictionless and the flat part's end free, n_x = 0;
n_y(0) = V (the shear beyond the touchdown's point reaction):
    theta' = m / EI,  m' = -cos(theta) n_y,  n_y = V + w s,  x' = cos(theta),  y' = sin(theta),
with (V, l_s) from theta(l_s) = 0 (the clamp horizontal) and y(l_s) = delta.
Printed per row: the clamp's moment m(l_s) (sign: lifting the rod), the clamp's vertical force n_y(l_s), the
lifted arc length l_s and the horizontal distance x(l_s) from the touchdown to the clamp.
Every parameter is the exact binary value of the double printed in its column (mpf(float(text))).
Run: /usr/bin/python3 tests/data/make_heavy_touchdown_table.py > tests/data/heavy_touchdown_reference.csv
"""
import mpmath as mp

mp.mp.dps = 30


def d(text):
    """Exact value of the double nearest to text."""
    return mp.mpf(float(text))


def touchdown(EI, w, delta):
    def at_clamp(V, ls):
        f = mp.odefun(lambda s, y: [y[1] / EI, -mp.cos(y[0]) * (V + w * s), mp.sin(y[0]), mp.cos(y[0])], 0,
                      [mp.mpf(0)] * 4)
        return f(ls)

    l0 = (72 * EI * delta / w) ** mp.mpf("0.25")  # the small-deflection start
    V, ls = mp.findroot(lambda V, ls: [at_clamp(V, ls)[0], (at_clamp(V, ls)[2] - delta) / delta],
                        [-w * l0 / 3, l0])
    end = at_clamp(V, ls)
    assert abs(end[0]) < mp.mpf(10) ** -25 and abs(end[2] / delta - 1) < mp.mpf(10) ** -25
    return {"clamp_moment": -end[1], "clamp_force": V + w * ls, "lifted_arc": ls, "lifted_span": end[3]}


def main():
    print("quantity,EI,w,delta,value")
    for EI, w, delta in [("0.9", "0.0648", "1e-3"), ("0.9", "0.0648", "1e-6"), ("2.3", "17.0", "4e-3"),
                         ("4.1e5", "3.2e2", "0.05")]:
        row = touchdown(d(EI), d(w), d(delta))
        for quantity in ("clamp_moment", "clamp_force", "lifted_arc", "lifted_span"):
            print(f"{quantity},{EI},{w},{delta},{mp.nstr(row[quantity], 25)}")


if __name__ == "__main__":
    main()
