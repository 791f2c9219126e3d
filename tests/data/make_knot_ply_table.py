#!/usr/bin/python3
"""High-precision reference table for references/knot_and_ply (tests/references/test_knot_and_ply_reference.cpp).

Every parameter is the exact binary value of the double printed in its column (mpf(float(text))), so
the table measures the C++ algorithm, not the rounding of its inputs. 32 digits; independent methods:
  * loose knot (PHYSICS.md §5.1): the homoclinic is integrated as an ODE with mpmath.odefun, not
    evaluated from its closed form:
        theta' = 2 sqrt(T/B) sin(theta/2)   (the first integral 1/2 B theta'^2 + T cos theta = T),
        x' = cos theta,  y' = sin theta,
    from the apex s = 0 (theta = pi, x = 0 by symmetry), with y shifted so that y -> 0 on the tail
    (y(S), S = 64 lambda; beyond, < e^-64) and the end shortening 2 int_0^S (1 - cos theta) ds as a
    fourth ODE component; s < 0 by the loop's symmetry (theta(-s) = 2 pi - theta(s), x odd, y even).
    Curvature = theta' from the ODE's right-hand side. Crossing: mpmath.findroot on x(s) = 0, s > 0;
    R_B: findroot on theta(s) = pi/2.
  * uniform ply (PHYSICS.md §5.2): the three linear equations for (n_t, n_b, M_t)
        n_b - kappa M_t = -kappa B tau_g,
        n_t cos(theta) + n_b sin(theta) = F/2,
        M_t cos(theta) + R (n_t sin(theta) - n_b cos(theta)) = M/2 - B kappa sin(theta)
    solved by mpmath.lu_solve (not the closed-form solution of the C++ code), p = n_t kappa - n_b tau_g;
    the plectoneme's tail tension from H equal in tail and ply, T_ext = 1/2 B kappa^2 + n_t (F = M = 0).
Run: /usr/bin/python3 tests/data/make_knot_ply_table.py > tests/data/knot_ply_reference.csv (~3 min).
"""
import mpmath as mp

mp.mp.dps = 32


def d(text):
    """Exact value of the double nearest to text."""
    return mp.mpf(float(text))


def fmt(value):
    return mp.nstr(value, 25)


def knot_rows(Bs, Ts, stations):
    B, T = d(Bs), d(Ts)
    lam = mp.sqrt(B / T)
    mu = 1 / lam
    far = 64 * lam

    # (theta, x, y - y0, shortening so far) from the apex
    sol = mp.odefun(lambda s, v: [2 * mu * mp.sin(v[0] / 2), mp.cos(v[0]), mp.sin(v[0]), 1 - mp.cos(v[0])], 0,
                    [mp.pi, mp.mpf(0), mp.mpf(0), mp.mpf(0)])
    tail = sol(far)
    y0 = -tail[2]  # y -> 0 on the tail

    def state(s):
        if s >= 0:
            th, x, y, _ = sol(s)
            return [th, x, y + y0]
        th, x, y, _ = sol(-s)  # theta(-s) = 2 pi - theta(s), x odd, y even
        return [2 * mp.pi - th, -x, y + y0]

    rows = []
    for ss in stations:
        th, x, y = state(d(ss))
        kappa = 2 * mu * mp.sin(th / 2)
        rows += [("knot_theta", ss, th), ("knot_curvature", ss, kappa), ("knot_x", ss, x), ("knot_y", ss, y)]
    crossing = mp.findroot(lambda s: sol(s)[1], 1.9 * lam)
    rows += [("knot_end_shortening", "", 2 * tail[3]), ("knot_crossing_arclength", "", crossing),
             ("knot_crossing_height", "", state(crossing)[2])]
    # where the tangent is perpendicular to the pull (theta = pi/2 on s < 0): R_B = 1/kappa
    s_perp = mp.findroot(lambda s: state(s)[0] - mp.pi / 2, -0.88 * lam)
    rows += [("knot_radius_perpendicular", "", 1 / (2 * mu * mp.sin(state(s_perp)[0] / 2)))]
    return rows


def ply_rows(Bs, Rs, thetas, Fs, Ms):
    B, R, th, F, M = d(Bs), d(Rs), d(thetas), d(Fs), d(Ms)
    s, c = mp.sin(th), mp.cos(th)
    kappa, tau = s * s / R, s * c / R
    A = mp.matrix([[0, 1, -kappa], [c, s, 0], [R * s, -R * c, c]])
    rhs = mp.matrix([-kappa * B * tau, F / 2, M / 2 - B * kappa * s])
    nt, nb, Mt = mp.lu_solve(A, rhs)
    p = nt * kappa - nb * tau
    rows = [("ply_twisting_moment", Mt), ("ply_tension", nt), ("ply_binormal_force", nb), ("ply_contact_force", p)]
    if F == 0 and M == 0:
        rows.append(("plectoneme_tail_tension", B * kappa * kappa / 2 + nt))
    return rows


def main():
    print("# knot and ply references at 32 digits (make_knot_ply_table.py); columns: quantity, B, T, s,")
    print("# R, theta, F, M, value (empty where the quantity does not depend on the column)")
    print("quantity,B,T,s,R,theta,F,M,value")
    for (Bs, Ts, stations) in [("1.0", "1.0", ["0.0", "0.5", "-1.3", "4.0"]),
                               ("2.3", "0.37", ["0.0", "1.7", "-6.2", "12.5"])]:
        for name, ss, value in knot_rows(Bs, Ts, stations):
            print(f"{name},{Bs},{Ts},{ss},,,,,{fmt(value)}")
    for (Bs, Rs, thetas, Fs, Ms) in [("1.0", "1.0", "0.3", "0.0", "0.0"), ("1.7", "0.05", "0.61", "0.0", "0.0"),
                                     ("0.4", "2.5", "0.12", "0.0", "0.0"), ("1.3", "0.8", "0.45", "0.37", "-0.21"),
                                     ("2.0", "0.3", "0.7", "-1.5", "0.9")]:
        for name, value in ply_rows(Bs, Rs, thetas, Fs, Ms):
            print(f"{name},{Bs},,,{Rs},{thetas},{Fs},{Ms},{fmt(value)}")


main()
