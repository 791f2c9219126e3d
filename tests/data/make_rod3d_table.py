#!/usr/bin/python3
"""High-precision reference table for references/rod3d (tests/references/test_rod3d_reference.cpp).

Independent of the C++ formulas:
  * beta_n L: mpmath.findroot (secant, 40 digits) on 1 + cos(x) cosh(x) = 0 from (n - 1/2) pi
    (the C++ code bisects cos x + sech x in double precision);
  * helix under an axial wrench: the helix r(s) = (R cos phi, R sin phi, s cos a), phi = s sin a / R,
    is differentiated numerically by mpmath.diff (curvature |r''|, torsion (r' x r'').r''' / k^2);
    the force n = lambda Omega follows from body equilibrium u x K(u - u_hat) + lambda e0 x u = 0
    solved for lambda by least squares with K = diag(C, B, B), u = (tau, kappa, 0),
    u_hat0 = tau - M_t / C; the axial moment is (m + (r - r_axis) x n) . e_z evaluated at s = 0.37
    with m = B kappa b + M_t t, and H = n.t + m.u - W.
Run: /usr/bin/python3 tests/data/make_rod3d_table.py > tests/data/rod3d_reference.csv (~2 s).
"""
import mpmath as mp

mp.mp.dps = 40


def beta_root(n):
    return mp.findroot(lambda x: 1 + mp.cos(x) * mp.cosh(x), (n - mp.mpf(1) / 2) * mp.pi)


def helix_values(B, C, R, a, Mt):
    B, C, R, a, Mt = map(mp.mpf, (B, C, R, a, Mt))
    s0 = mp.mpf("0.37")

    def r(s):
        phi = s * mp.sin(a) / R
        return mp.matrix([R * mp.cos(phi), R * mp.sin(phi), s * mp.cos(a)])

    d1 = mp.matrix([mp.diff(lambda s: r(s)[i], s0, 1) for i in range(3)])
    d2 = mp.matrix([mp.diff(lambda s: r(s)[i], s0, 2) for i in range(3)])
    d3 = mp.matrix([mp.diff(lambda s: r(s)[i], s0, 3) for i in range(3)])

    def cross(x, y):
        return mp.matrix([x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]])

    def dot(x, y):
        return sum(x[i] * y[i] for i in range(3))

    kappa = mp.sqrt(dot(d2, d2))
    c12 = cross(d1, d2)
    tau = dot(c12, d3) / kappa**2
    t = d1
    b = c12 / mp.sqrt(dot(c12, c12))
    u = [tau, kappa, mp.mpf(0)]
    uhat0 = tau - Mt / C
    Ku = [C * (u[0] - uhat0), B * u[1], B * u[2]]
    lhs = cross(mp.matrix(u), mp.matrix(Ku))          # u x K(u - u_hat)
    e0xu = cross(mp.matrix([1, 0, 0]), mp.matrix(u))  # e0 x u
    lam = -dot(lhs, e0xu) / dot(e0xu, e0xu)
    omega_world = tau * t + kappa * b
    n = lam * omega_world
    m = B * kappa * b + Mt * t
    rr = r(s0)
    arm = mp.matrix([rr[0], rr[1], 0])  # r - r_axis (axis = e_z through the origin)
    wrench = m + cross(arm, n)
    W = (B * kappa**2 + C * (u[0] - uhat0) ** 2) / 2
    H = dot(n, t) + (B * kappa**2 + Mt * tau) - W
    return {"kappa": kappa, "tau": tau, "axial_force": n[2], "axial_moment": wrench[2], "H": H}


print("# rod3d references at 40 digits (make_rod3d_table.py); columns: quantity, index, B, C, radius,")
print("# pitch_angle, twisting_moment, value (index: mode number for beta_l, else empty)")
print("quantity,index,B,C,radius,pitch_angle,twisting_moment,value")
for n in range(1, 7):
    print(f"beta_l,{n},,,,,,{mp.nstr(beta_root(n), 25)}")
for (B, C, R, a, Mt) in [(1.3, 0.9, 0.7, 0.6, 0.37), (1.0, 0.7, 1.0, 0.3, 0.0), (2.0, 1.5, 0.25, 1.2, -0.8),
                         (1.3, 0.8, 2.0, 0.05, 0.1)]:
    values = helix_values(repr(B), repr(C), repr(R), repr(a), repr(Mt))
    for name, value in values.items():
        print(f"helix_{name},,{B!r},{C!r},{R!r},{a!r},{Mt!r},{mp.nstr(value, 25)}")
