#!/usr/bin/python3
"""High-precision reference table for references/manufactured_rod (tests/references/test_manufactured_rod_reference.cpp).

The manufactured Kirchhoff rod of manufactured_rod.hpp, by another route: mpmath's Taylor-series ODE
solver (odefun, 30 digits) on r' = R e1, R' = R [u]x, with the strains, the internal force and their
derivatives written out here; then m = R K (u - u_hat), f = -n', c = -(R ([u]x K (u - u_hat) + K u')) - t x n.
One parameter set (every value the exact double printed), rows at three stations.

With the argument couple_free: the variant with c = 0 (manufactured_rod.hpp), by a route of its own: the
twist integrated with the frame from Kirchhoff's twist equation, n = T t + t x m' with m' and then f = -n'
by mpmath's numerical differentiation (mp.diff) of the integrated fields, not the C++ closed forms of
m'' and u0''; the couple c = -m' - t x n is then printed (zero to the working precision).
Run: /usr/bin/python3 tests/data/make_manufactured_rod_table.py > tests/data/manufactured_rod_reference.csv
     /usr/bin/python3 tests/data/make_manufactured_rod_table.py couple_free > tests/data/manufactured_rod_couple_free_reference.csv
"""
import sys
import mpmath as mp

mp.mp.dps = 30

L = mp.mpf(1.7)
K = [mp.mpf(0.6), mp.mpf(1.1), mp.mpf(2.3)]
U_HAT = [mp.mpf(0.3), mp.mpf(-0.2), mp.mpf(0.5)]
ROOT = [mp.mpf(0.2), mp.mpf(-0.4), mp.mpf(0.9)]
FRAME = [[0, 0, 1], [1, 0, 0], [0, 1, 0]]  # rows; columns t, d1, d2
U_MEAN = [mp.mpf(0.9), mp.mpf(1.3), mp.mpf(-0.7)]
U_SINE = [mp.mpf(-0.4), mp.mpf(0.8), mp.mpf(1.1)]
U_COSINE = [mp.mpf(0.25), mp.mpf(-0.6), mp.mpf(0.35)]
N_ROOT = [mp.mpf(1.5), mp.mpf(-0.8), mp.mpf(0.3)]
N_SLOPE = [mp.mpf(-1.2), mp.mpf(0.4), mp.mpf(0.9)]
N_SINE = [mp.mpf(0.7), mp.mpf(0.5), mp.mpf(-1.1)]


def u(s):
    return [U_MEAN[i] + U_SINE[i] * mp.sin(mp.pi * s / L) + U_COSINE[i] * mp.cos(2 * mp.pi * s / L) for i in range(3)]


def du(s):
    return [U_SINE[i] * mp.pi / L * mp.cos(mp.pi * s / L) - U_COSINE[i] * 2 * mp.pi / L * mp.sin(2 * mp.pi * s / L)
            for i in range(3)]


def n(s):
    return [N_ROOT[i] + N_SLOPE[i] * s / L + N_SINE[i] * mp.sin(mp.pi * s / L) for i in range(3)]


def dn(s):
    return [N_SLOPE[i] / L + N_SINE[i] * mp.pi / L * mp.cos(mp.pi * s / L) for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def rhs(s, y):
    # y = r (3), then R row-major (9). (R [u]x)_ij = sum_k R_ik eps_kjl... written as R times the skew matrix.
    R = [[y[3 + 3 * i + j] for j in range(3)] for i in range(3)]
    w = u(s)
    S = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
    dR = [[sum(R[i][k] * S[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return [R[0][0], R[1][0], R[2][0]] + [dR[i][j] for i in range(3) for j in range(3)]


def main():
    y0 = ROOT + [mp.mpf(FRAME[i][j]) for i in range(3) for j in range(3)]
    solution = mp.odefun(rhs, 0, y0)
    print("s,quantity,component,value")
    for fraction in ("0.25", "0.6", "1"):
        s = mp.mpf(float(fraction)) * L if fraction != "1" else L
        y = solution(s)
        R = [[y[3 + 3 * i + j] for j in range(3)] for i in range(3)]
        w, dw = u(s), du(s)
        Kw = [K[i] * (w[i] - U_HAT[i]) for i in range(3)]
        m = [sum(R[i][k] * Kw[k] for k in range(3)) for i in range(3)]
        inner = [a + K[i] * dw[i] for i, a in enumerate(cross(w, Kw))]
        dm = [sum(R[i][k] * inner[k] for k in range(3)) for i in range(3)]
        t = [R[i][0] for i in range(3)]
        tn = cross(t, n(s))
        c = [-dm[i] - tn[i] for i in range(3)]
        f = [-x for x in dn(s)]
        rows = [("position", y[0:3]), ("moment", m), ("force_density", f), ("couple_density", c)]
        rows += [(f"frame_col{j}", [R[i][j] for i in range(3)]) for j in range(3)]
        for name, values in rows:
            for k, value in enumerate(values):
                print(f"{fraction},{name},{k},{mp.nstr(value, 25)}")


T_ROOT, T_SLOPE, T_SINE = mp.mpf(0.9), mp.mpf(-0.6), mp.mpf(0.45)


def couple_free_main():
    # Central differences with explicit steps (mp.diff's default step left 4e-10 in the derivative of the
    # integrated twist): O(h^2) truncation, 1e-50 / h rounding. m' with h = 1e-15 (1e-30, 1e-35), f = -n'
    # (n through m') with h = 1e-12 (1e-24, 1e-30 / 1e-12 = 1e-18): f to about 1e-18.
    mp.mp.dps = 50
    def rhs_free(s, y):
        R = [[y[3 + 3 * i + j] for j in range(3)] for i in range(3)]
        w = u(s)
        w[0] = y[12]
        S = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
        dR = [[sum(R[i][k] * S[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
        a = [K[i] * (w[i] - U_HAT[i]) for i in range(3)]
        twist = -(w[1] * a[2] - w[2] * a[1]) / K[0]
        return [R[0][0], R[1][0], R[2][0]] + [dR[i][j] for i in range(3) for j in range(3)] + [twist]

    y0 = ROOT + [mp.mpf(FRAME[i][j]) for i in range(3) for j in range(3)] + [U_MEAN[0] + U_COSINE[0]]
    solution = mp.odefun(rhs_free, 0, y0)

    def fields(s):
        y = solution(s)
        R = [[y[3 + 3 * i + j] for j in range(3)] for i in range(3)]
        w = u(s)
        w[0] = y[12]
        a = [K[i] * (w[i] - U_HAT[i]) for i in range(3)]
        return y, R, [sum(R[i][k] * a[k] for k in range(3)) for i in range(3)]

    def moment(s, k):
        return fields(s)[2][k]

    def force(s, k):
        y, R, _ = fields(s)
        t = [R[i][0] for i in range(3)]
        dm = [mp.diff(lambda x: moment(x, i), s, h=mp.mpf('1e-15')) for i in range(3)]
        T = T_ROOT + T_SLOPE * s / L + T_SINE * mp.sin(mp.pi * s / L)
        return (T * mp.matrix(t) + mp.matrix(cross(t, dm)))[k]

    print("s,quantity,component,value")
    for fraction in ("0.25", "0.6"):  # interior stations: mp.diff takes points on both sides
        s = mp.mpf(float(fraction)) * L
        y, R, m = fields(s)
        t = [R[i][0] for i in range(3)]
        n = [force(s, k) for k in range(3)]
        f = [-mp.diff(lambda x: force(x, k), s, h=mp.mpf('1e-12')) for k in range(3)]
        dm = [mp.diff(lambda x: moment(x, i), s, h=mp.mpf('1e-15')) for i in range(3)]
        tn = cross(t, n)
        c = [-dm[i] - tn[i] for i in range(3)]
        rows = [("position", y[0:3]), ("twist", [y[12]]), ("moment", m), ("force", n), ("force_density", f),
                ("couple_density", c)]
        rows += [(f"frame_col{j}", [R[i][j] for i in range(3)]) for j in range(3)]
        for name, values in rows:
            for k, value in enumerate(values):
                print(f"{fraction},{name},{k},{mp.nstr(value, 20)}")


if __name__ == "__main__":
    couple_free_main() if sys.argv[1:] == ["couple_free"] else main()
