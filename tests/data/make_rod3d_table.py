#!/usr/bin/python3
"""High-precision reference table for references/rod3d (tests/references/test_rod3d_reference.cpp).

Independent of the C++ formulas:
  * beta_n L: mpmath.findroot (secant, 40 digits) on 1 + cos(x) cosh(x) = 0 from (n - 1/2) pi
    (the C++ code bisects cos x + sech x in double precision);
  * the clamped-free mode shape phi(x) / phi(1) in the textbook form and its slope by mpmath.diff (the C++
    code rewrites the hyperbolic part so that it cancels no digits, and differentiates by hand);
  * helix under an axial wrench: the helix r(s) = (R cos phi, R sin phi, s cos a), phi = s sin a / R,
    is differentiated numerically by mpmath.diff (curvature |r''|, torsion (r' x r'').r''' / k^2);
    the force n = lambda Omega follows from body equilibrium u x K(u - u_hat) + lambda e0 x u = 0
    solved for lambda by least squares with K = diag(C, B, B), u = (tau, kappa, 0),
    u_hat0 = tau - M_t / C; the axial moment is (m + (r - r_axis) x n) . e_z evaluated at s = 0.37
    with m = B kappa b + M_t t, and H = n.t + m.u - W.
  * special Cosserat helix (shear and extension, constant body strains u; material components with
    index 0 along the rod: K = diag(C, B, B), S = diag(EA, GA, GA), v = e0 + S^-1 N): the body
    force N (3 unknowns) by mpmath.findroot on the body equilibrium (u x N = 0 in the two directions
    normal to u, u x K u + v(N) x N = 0 along e0 x u), started from the inextensible limit, not by
    the quadratic for lambda of the C++ code; lambda = N.u/|u|^2, and the full 3-vector moment
    residual is checked to vanish. The geometry by mpmath.odefun on r' = R v, R' = R [u]x from
    r = 0, R = I (12 unknowns): the position and frame at s = 1.3, the advance r(1.3).a / 1.3
    (a = u/|u|), the radius and the axis point as the circumcircle of the projections of r(0),
    r(1.3), r(2.9) on the plane normal to a, the axial moment (m + (r - r_axis) x n).a at
    s = 1.3 with m = R K u, n = R N, and H = N.v + M.u - W_bend - W_shear.
Run: /usr/bin/python3 tests/data/make_rod3d_table.py > tests/data/rod3d_reference.csv (~10 s).
"""
import mpmath as mp

mp.mp.dps = 40


def beta_root(n):
    return mp.findroot(lambda x: 1 + mp.cos(x) * mp.cosh(x), (n - mp.mpf(1) / 2) * mp.pi)


def mode_shape(n, x):
    """The clamped-free mode in the textbook form (40 digits leave it no cancellation), scaled to 1 at the tip,
    and its slope by mpmath.diff."""
    b = beta_root(n)
    sigma = (mp.cosh(b) + mp.cos(b)) / (mp.sinh(b) + mp.sin(b))

    def phi(y):
        return mp.cosh(b * y) - mp.cos(b * y) - sigma * (mp.sinh(b * y) - mp.sin(b * y))

    return phi(mp.mpf(x)) / phi(1), mp.diff(phi, mp.mpf(x)) / phi(1)


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


def cross(x, y):
    return mp.matrix([x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]])


def dot(x, y):
    return sum(x[i] * y[i] for i in range(3))


COSSERAT_S = mp.mpf("1.3")  # station of the tabulated position and frame
COSSERAT_S2 = mp.mpf("2.9")  # third point of the circumcircle


def cosserat_values(B, C, GA, EA, u0, u1, u2):
    B, C, GA, EA = map(mp.mpf, (B, C, GA, EA))
    u = mp.matrix([mp.mpf(u0), mp.mpf(u1), mp.mpf(u2)])
    K = [C, B, B]
    S = [EA, GA, GA]
    Ku = mp.matrix([K[i] * u[i] for i in range(3)])
    e0 = mp.matrix([1, 0, 0])
    norm_u = mp.sqrt(dot(u, u))
    a = u / norm_u
    # orthonormal directions normal to u, and the direction e0 x u of the moment balance
    q = cross(e0, u)
    q = q / mp.sqrt(dot(q, q))
    p2 = cross(a, q)

    def v_of(N):
        return mp.matrix([e0[i] + N[i] / S[i] for i in range(3)])

    def equations(n0, n1, n2):
        N = mp.matrix([n0, n1, n2])
        f = cross(u, N)
        g = cross(u, Ku) + cross(v_of(N), N)
        return [dot(f, q), dot(f, p2), dot(g, q)]

    start = (C - B) * u[0] * u
    N = mp.matrix(mp.findroot(equations, (start[0], start[1], start[2])))
    v = v_of(N)
    residual = cross(u, Ku) + cross(v, N)
    assert mp.sqrt(dot(residual, residual)) < mp.mpf(10) ** (-35), residual
    assert mp.sqrt(dot(cross(u, N), cross(u, N))) < mp.mpf(10) ** (-35)
    lam = dot(N, u) / dot(u, u)

    def rhs(s, y):
        R = mp.matrix(3, 3)
        for i in range(3):
            for j in range(3):
                R[i, j] = y[3 + 3 * i + j]
        ux = mp.matrix([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
        dR = R * ux
        dr = R * v
        return [dr[0], dr[1], dr[2]] + [dR[i, j] for i in range(3) for j in range(3)]

    y0 = [mp.mpf(0)] * 3 + [mp.mpf(1) if i == j else mp.mpf(0) for i in range(3) for j in range(3)]
    sol = mp.odefun(rhs, 0, y0)
    y1, y2 = sol(COSSERAT_S), sol(COSSERAT_S2)
    r1 = mp.matrix(y1[:3])
    r2 = mp.matrix(y2[:3])
    R1 = mp.matrix(3, 3)
    for i in range(3):
        for j in range(3):
            R1[i, j] = y1[3 + 3 * i + j]
    advance = dot(r1, a) / COSSERAT_S

    # circumcircle of the three points projected on the plane normal to a (origin = r(0))
    def project(x):
        return x - dot(x, a) * a

    P0, P1, P2 = project(mp.matrix([0, 0, 0])), project(r1), project(r2)
    d1, d2 = P1 - P0, P2 - P0
    # centre c = P0 + x d1 + y d2 with |c - P0| = |c - P1| = |c - P2|
    A = mp.matrix([[dot(d1, d1), dot(d1, d2)], [dot(d1, d2), dot(d2, d2)]])
    rhs2 = mp.matrix([dot(d1, d1) / 2, dot(d2, d2) / 2])
    xy = mp.lu_solve(A, rhs2)
    centre = P0 + xy[0] * d1 + xy[1] * d2
    radius = mp.sqrt(dot(centre - P0, centre - P0))
    n_world = R1 * N
    m_world = R1 * Ku
    wrench = m_world + cross(r1 - centre, n_world)
    perp = wrench - dot(wrench, a) * a
    assert mp.sqrt(dot(perp, perp)) < mp.mpf(10) ** (-30), perp
    W_bend = dot(u, Ku) / 2
    W_shear = sum(S[i] * (v[i] - e0[i]) ** 2 for i in range(3)) / 2
    H = dot(N, v) + dot(Ku, u) - W_bend - W_shear
    rows = [("lambda", "", lam), ("advance", "", advance), ("radius", "", radius),
            ("axial_force", "", dot(n_world, a)), ("axial_moment", "", dot(wrench, a)), ("H", "", H)]
    rows += [("position", i, r1[i]) for i in range(3)]
    rows += [("frame", 3 * i + j, R1[i, j]) for i in range(3) for j in range(3)]
    return rows


print("# rod3d references at 40 digits (make_rod3d_table.py); columns: quantity, index, B, C, radius,")
print("# pitch_angle, twisting_moment (axial-wrench helix), GA, EA, u0, u1, u2 (special Cosserat helix),")
print("# s (station of cosserat_position / cosserat_frame), value; index: mode number for beta_l,")
print("# component for cosserat_position (0..2) and cosserat_frame (3 row + column), else empty")
print("quantity,index,B,C,radius,pitch_angle,twisting_moment,GA,EA,u0,u1,u2,s,value")
for n in range(1, 7):
    print(f"beta_l,{n},,,,,,,,,,,,{mp.nstr(beta_root(n), 25)}")
for n in (1, 2, 3, 7):
    for x in (0.13, 0.45, 0.87, 1.0):
        shape, slope = mode_shape(n, x)
        print(f"mode_shape,{n},,,,,,,,,,,{x!r},{mp.nstr(shape, 25)}")
        print(f"mode_slope,{n},,,,,,,,,,,{x!r},{mp.nstr(slope, 25)}")
for (B, C, R, a, Mt) in [(1.3, 0.9, 0.7, 0.6, 0.37), (1.0, 0.7, 1.0, 0.3, 0.0), (2.0, 1.5, 0.25, 1.2, -0.8),
                         (1.3, 0.8, 2.0, 0.05, 0.1)]:
    values = helix_values(repr(B), repr(C), repr(R), repr(a), repr(Mt))
    for name, value in values.items():
        print(f"helix_{name},,{B!r},{C!r},{R!r},{a!r},{Mt!r},,,,,,,{mp.nstr(value, 25)}")
# PHYSICS.md §7.1 example (its u = (0.8, 0, 0.5) with d3 along the rod), a general one, and C > B with EA < GA
for (B, C, GA, EA, u0, u1, u2) in [(1.0, 0.7, 50.0, 200.0, 0.5, 0.8, 0.0), (2.0, 1.3, 20.0, 80.0, -0.7, 0.4, 0.9),
                                   (0.8, 1.5, 10.0, 5.0, 1.2, -0.6, 0.3)]:
    for name, index, value in cosserat_values(repr(B), repr(C), repr(GA), repr(EA), repr(u0), repr(u1), repr(u2)):
        s = repr(float(COSSERAT_S)) if name in ("position", "frame") else ""
        print(f"cosserat_{name},{index},{B!r},{C!r},,,,{GA!r},{EA!r},{u0!r},{u1!r},{u2!r},{s},{mp.nstr(value, 25)}")
