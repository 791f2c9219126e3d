#!/usr/bin/python3
"""High-precision reference table for references/twisted_rod (tests/references/test_twisted_rod_reference.cpp).

Every parameter is the exact binary value of the double printed in its column (mpf(float(text))), so
the table measures the C++ algorithm, not the rounding of its inputs. 40 digits; independent methods:
  * localized helical buckling (PHYSICS.md §7.3), B, T, M: the curve r(s) is evaluated from the
    closed form in mpmath; the tangent, cos phi = t.e_z, cos phi_max = t(0).e_z and the envelope
    (cos phi - cos phi_max)/(1 - cos phi_max) come from mpmath.diff of r(s) (not from the C++
    derivative formulas); amplitude = |(x, y)(0)|; end shortening = mpmath.quad of 1 - t.e_z over the
    whole line. Asserted: |r'| = 1 and the Kirchhoff balance m' + t x n = 0 with m = B t x t' + M t,
    n = T e_z (mpmath.diff to third order) at every tabulated s.
  * finite-rod relations (Neukirch, van der Heijden & Thompson 2002, eqs. 13-15; PyElastica's helical
    buckling case), B, C, L, Phi, D: mpmath.findroot (2-D Newton) directly on
        D/L = sqrt(16/t (1 - m^2/(4t))),   Phi = m B/C + 4 arccos(m/(2 sqrt t)),
    not the one-dimensional angle equation of the C++ code. Starting points: the twist-dominated
    guess m = Phi C/B with t the smaller root of the first equation (PyElastica's case), or, for the
    manufactured cases, the (m, t) from which Phi and D were made. Asserted: on the branch that
    starts at the onset (d Phi/d phi_max > 0 at fixed D, m > 0).
  * Greenhill: shooting on the complex deflection w = u + i v of the linearised pinned column,
    B w'' - i M w' + P w = 0, w(0) = 0, w'(0) = 1 (mpmath.odefun), findroot on w(L; M) = 0 for the
    smallest M > 0 (a simple zero in complex M, started from 0.98 x the closed form; the imaginary
    part of the root is asserted ~0).
  * Greenhill with semi-tangential end torques: shooting on the third-order moment balance
    B w''' - i M w'' + P w' = -N (two shots for the unknown slope and lateral force), findroot on
    the 2 x 2 determinant of the end conditions in complex M (the C++ code uses the closed-form
    exponential solution and a real scan instead). Clamped ends (w = w' = 0): the same shooting.
  * Michell ring: the cited criterion (Goriely 2006) evaluated in mpmath; no independent method.
  * Prandtl/Michell cantilever: gamma = 2 j, j the first positive zero of mpmath.besselj(-1/4, x),
    cross-checked against odefun shooting on phi'' + gamma^2 (1 - s)^2 phi = 0, phi(0) = 0,
    phi'(0) = 1, findroot on phi'(1) = 0 (asserted to agree to 1e-25).
Run: /usr/bin/python3 tests/data/make_twisted_rod_table.py > tests/data/twisted_rod_reference.csv (~1 min).
"""
import mpmath as mp

mp.mp.dps = 40
TOL = mp.mpf(10) ** -30


def d(text):
    """Exact value of the double nearest to text."""
    return mp.mpf(float(text))


def cross(x, y):
    return [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]


def norm(x):
    return mp.sqrt(sum(c * c for c in x))


# ---- localized helical buckling --------------------------------------------------------------
def helical_rows(Bs, Ts, Ms, stations):
    B, T, M = d(Bs), d(Ts), d(Ms)
    alpha = mp.sqrt(4 * B * T - M * M) / (2 * B)
    A = 2 * B * alpha / T
    w = M / (2 * B)

    def r(s):
        return [A * mp.sin(w * s) / mp.cosh(alpha * s), -A * mp.cos(w * s) / mp.cosh(alpha * s),
                s - A * mp.tanh(alpha * s)]

    def deriv(s, k):
        return [mp.diff(lambda x: r(x)[i], s, k) for i in range(3)]

    cos_phi_max = deriv(mp.mpf(0), 1)[2]
    shortening = mp.quad(lambda s: 1 - mp.diff(lambda x: r(x)[2], s), [-mp.inf, 0, mp.inf])
    rows = [("helical_alpha", "", "", alpha), ("helical_amplitude", "", "", norm(r(mp.mpf(0))[:2])),
            ("helical_cos_phi_max", "", "", cos_phi_max), ("helical_end_shortening", "", "", shortening)]
    for s_text in stations:
        s = d(s_text)
        t, t1, t2 = deriv(s, 1), deriv(s, 2), deriv(s, 3)
        assert abs(norm(t) - 1) < TOL, (Bs, Ts, Ms, s_text)
        # m' = B t x t'' + M t' (t' x t' = 0); m' + t x (T e_z) = 0
        residual = [B * c + M * t1[i] + e for i, (c, e) in enumerate(zip(cross(t, t2), cross(t, [0, 0, T])))]
        assert norm(residual) < TOL, (Bs, Ts, Ms, s_text, residual)
        position = r(s)
        rows += [("helical_position", i, s_text, position[i]) for i in range(3)]
        rows += [("helical_tangent", i, s_text, t[i]) for i in range(3)]
        rows += [("helical_cos_phi", "", s_text, t[2]),
                 ("helical_envelope", "", s_text, (t[2] - cos_phi_max) / (1 - cos_phi_max))]
    return rows


# ---- finite-rod relations ----------------------------------------------------------------------
def finite_equations(B, C, dL, Phi):
    def F(m, t):
        return [mp.sqrt(16 / t * (1 - m * m / (4 * t))) - dL, m * B / C + 4 * mp.acos(m / (2 * mp.sqrt(t))) - Phi]
    return F


def finite_rows(Bs, Cs, Ls, Phis, Ds, start):
    B, C, L, Phi, D = d(Bs), d(Cs), d(Ls), d(Phis), d(Ds)
    dL = D / L
    m, t = mp.findroot(finite_equations(B, C, dL, Phi), start)
    assert all(abs(v) < TOL for v in finite_equations(B, C, dL, Phi)(m, t))
    cos_phi_max = m * m / (2 * t) - 1
    # branch check: Phi as a function of phi_max/2 at fixed D/L increases (onset branch), m > 0
    half = mp.acos(cos_phi_max) / 2
    assert m > 0 and 4 + 8 * B / (C * dL) * mp.cos(2 * half) > 0, (Bs, Cs, Phis, Ds)
    alpha_L = mp.sqrt(4 * t - m * m) / 2
    return [("finite_m", m), ("finite_t", t), ("finite_M", m * B / L), ("finite_T", t * B / L**2),
            ("finite_alpha", alpha_L / L), ("finite_cos_phi_max", cos_phi_max)]


def twist_dominated_start(Bs, Cs, Ls, Phis, Ds):
    B, C, Phi, dL = d(Bs), d(Cs), d(Phis), d(Ds) / d(Ls)
    m = Phi * C / B
    # (16/t)(1 - m^2/(4t)) = dL^2  <=>  dL^2 t^2 - 16 t + 4 m^2 = 0: the smaller root
    t = (16 - mp.sqrt(256 - 16 * dL * dL * m * m)) / (2 * dL * dL)
    return (m, t)


def manufactured(Bs, Cs, Ls, half_angle, scale):
    """Phi and D (rounded to doubles) made from m = scale sin(2 h), t = scale^2 sin^2(h)
    (then m/(2 sqrt t) = cos h, D/L = 4/scale)."""
    B, C, h, scale = d(Bs), d(Cs), mp.mpf(half_angle), mp.mpf(scale)
    m, t = scale * mp.sin(2 * h), (scale * mp.sin(h)) ** 2
    Phi = m * B / C + 4 * mp.acos(m / (2 * mp.sqrt(t)))
    dL = mp.sqrt(16 / t * (1 - m * m / (4 * t)))
    return repr(float(Phi)), repr(float(dL * d(Ls))), (m, t)


# ---- Greenhill ---------------------------------------------------------------------------------
def greenhill_moment(Bs, Ls, Ps, guess):
    B, L, P = d(Bs), d(Ls), d(Ps)

    def end_deflection(M):
        sol = mp.odefun(lambda z, y: [y[1], (1j * M * y[1] - P * y[0]) / B], 0, [mp.mpc(0), mp.mpc(1)])
        return sol(L)[0]

    M = mp.findroot(end_deflection, mp.mpc(guess, 0.01))
    assert abs(M.imag) < TOL, M
    return M.real


def greenhill_semitangential_moment(Bs, Ls, Ps, guess):
    # Semi-tangential end torques: i B w'' + (M/2) w' = 0 at both pins (twisted_rod.hpp 3b).
    # Shooting on B w''' - i M w'' + P w' = -N from w(0) = 0, w'(0) = beta, w''(0) = i M beta/(2B)
    # for the two unknowns (beta, N) = (1, 0) and (0, 1); the 2 x 2 determinant of (w(L),
    # i B w''(L) + (M/2) w'(L)) vanishes at the critical M (findroot in complex M; the imaginary part
    # is asserted ~0).
    B, L, P = d(Bs), d(Ls), d(Ps)

    def end_conditions(M, beta, N):
        sol = mp.odefun(lambda z, y: [y[1], y[2], (1j * M * y[2] - P * y[1] - N) / B], 0,
                        [mp.mpc(0), mp.mpc(beta), 1j * M * beta / (2 * B)])
        w, dw, ddw = sol(L)
        return w, 1j * B * ddw + M / 2 * dw

    def determinant(M):
        a, b = end_conditions(M, 1, 0), end_conditions(M, 0, 1)
        return a[0] * b[1] - a[1] * b[0]

    M = mp.findroot(determinant, mp.mpc(guess, 0.01))
    assert abs(M.imag) < TOL, M
    return M.real


def clamped_column_moment(Bs, Ls, Ps, guess):
    # Clamped ends (twisted_rod.hpp 3c): shooting on B w''' - i M w'' + P w' = -N from w(0) = w'(0) = 0,
    # w''(0) = gamma for the unknowns (gamma, N) = (1, 0) and (0, 1); the 2 x 2 determinant of
    # (w(L), w'(L)) vanishes at the critical M.
    B, L, P = d(Bs), d(Ls), d(Ps)

    def end_values(M, gamma, N):
        sol = mp.odefun(lambda z, y: [y[1], y[2], (1j * M * y[2] - P * y[1] - N) / B], 0,
                        [mp.mpc(0), mp.mpc(0), mp.mpc(gamma)])
        w, dw, _ = sol(L)
        return w, dw

    def determinant(M):
        a, b = end_values(M, 1, 0), end_values(M, 0, 1)
        return a[0] * b[1] - a[1] * b[0]

    M = mp.findroot(determinant, mp.mpc(guess, 0.01))
    assert abs(M.imag) < TOL, M
    return M.real


# ---- Prandtl cantilever ------------------------------------------------------------------------
def prandtl_gamma():
    gamma = 2 * mp.findroot(lambda x: mp.besselj(mp.mpf(-1) / 4, x), 2)

    def end_slope(g):
        sol = mp.odefun(lambda s, y: [y[1], -g * g * (1 - s) ** 2 * y[0]], 0, [mp.mpf(0), mp.mpf(1)])
        return sol(1)[1]

    shooting = mp.findroot(end_slope, 4)
    assert abs(shooting - gamma) < mp.mpf(10) ** -25, (gamma, shooting)
    return gamma


def fmt(value):
    return mp.nstr(value, 25)


def main():
    print("# twisted-rod references at 40 digits (make_twisted_rod_table.py); columns: quantity, index,")
    print("# B (bending stiffness; EI_weak for ltb_critical_load), C (twisting stiffness; GJ for")
    print("# ltb_critical_load), T (tension), M (twisting moment), L, Phi (imposed end rotation), D (end")
    print("# shortening), P (compressive load), s (station), value; index: vector component, else empty")
    print("quantity,index,B,C,T,M,L,Phi,D,P,s,value")
    # PHYSICS.md §7.3 example, a planar loop (M = 0), negative M, and closer to the threshold M^2 = 4BT
    for (Bs, Ts, Ms, stations) in [("1.345", "2.0", "1.9", ["0.0", "0.3", "-1.7", "4.0", "25.0"]),
                                   ("1.0", "1.0", "0.0", ["0.0", "0.8", "-3.1"]),
                                   ("0.7", "3.2", "-2.5", ["0.0", "0.45", "-2.2", "6.5"]),
                                   ("2.5", "0.4", "1.9", ["0.0", "1.3", "-9.0"])]:
        for name, index, s, value in helical_rows(Bs, Ts, Ms, stations):
            print(f"{name},{index},{Bs},,{Ts},{Ms},,,,,{s},{fmt(value)}")
    # PyElastica's case at L = 1 and at its L = 100 (D = 0.03 L), then manufactured cases: phi_max/2
    # below pi/4, between pi/4 and the branch end, and C D/(2 B L) >= 1 (branch up to phi_max = pi)
    phi27 = repr(27 * 2 * float(mp.pi))
    cases = [("1.345", "0.789", "1.0", phi27, "0.03", None), ("1.345", "0.789", "100.0", phi27, "3.0", None)]
    for (Bs, Cs, Ls, h, scale) in [("1.0", "1.0", "2.0", "0.3", 40), ("0.5", "2.0", "0.5", "0.9", mp.mpf(40) / 3),
                                   ("1.0", "10.0", "1.0", "1.3", 8)]:
        Phis, Ds, start = manufactured(Bs, Cs, Ls, h, scale)
        cases.append((Bs, Cs, Ls, Phis, Ds, start))
    for (Bs, Cs, Ls, Phis, Ds, start) in cases:
        start = start or twist_dominated_start(Bs, Cs, Ls, Phis, Ds)
        for name, value in finite_rows(Bs, Cs, Ls, Phis, Ds, start):
            print(f"{name},,{Bs},{Cs},,,{Ls},{Phis},{Ds},,,{fmt(value)}")
    for (Bs, Ls, Ps) in [("1.0", "1.0", "0.0"), ("1.3", "2.0", "2.0"), ("0.8", "0.5", "-5.0"), ("2.0", "3.0", "1.5")]:
        # start: 0.98 x the closed form (only a starting point; the root is the ODE's)
        guess = mp.mpf("0.98") * 2 * d(Bs) * mp.sqrt((mp.pi / d(Ls)) ** 2 - d(Ps) / d(Bs))
        print(f"greenhill_moment,,{Bs},,,,{Ls},,,{Ps},,{fmt(greenhill_moment(Bs, Ls, Ps, guess))}")
    # semi-tangential: start at 0.78 x the axial closed form (the ratio at P = 0 is 4.911/2 pi)
    for (Bs, Ls, Ps) in [("1.0", "1.0", "0.0"), ("1.3", "2.0", "2.0"), ("0.8", "0.5", "-5.0"), ("2.0", "3.0", "1.5"),
                         ("0.9", "1.7", "-0.6")]:
        guess = mp.mpf("0.78") * 2 * d(Bs) * mp.sqrt((mp.pi / d(Ls)) ** 2 - d(Ps) / d(Bs))
        value = greenhill_semitangential_moment(Bs, Ls, Ps, guess)
        print(f"greenhill_semitangential_moment,,{Bs},,,,{Ls},,,{Ps},,{fmt(value)}")
    # clamped: start at 1.43 x the pinned axial closed form (the ratio at P = 0 is 8.987/2 pi), the
    # Euler load of the clamped column being 4 pi^2 B/L^2
    for (Bs, Ls, Ps) in [("1.0", "1.0", "0.0"), ("1.3", "2.0", "2.0"), ("0.8", "0.5", "-5.0"), ("2.0", "3.0", "6.0"),
                         ("0.9", "1.7", "-0.6")]:
        B, L, P = d(Bs), d(Ls), d(Ps)
        guess = mp.mpf("1.43") * 2 * B * mp.sqrt((mp.pi / L) ** 2 - P / (4 * B))
        print(f"clamped_column_moment,,{Bs},,,,{Ls},,,{Ps},,{fmt(clamped_column_moment(Bs, Ls, Ps, guess))}")
    for (Bs, Cs, Ls) in [("1.0", "1.0", repr(2 * float(mp.pi))), ("1.0", "0.5", "1.0"), ("1.3", "0.9", "3.7")]:
        B, C, L = d(Bs), d(Cs), d(Ls)
        print(f"michell_twist_angle,,{Bs},{Cs},,,{Ls},,,,,{fmt(2 * mp.pi * mp.sqrt(3) * B / C)}")
        print(f"michell_twisting_moment,,{Bs},{Cs},,,{Ls},,,,,{fmt(mp.sqrt(3) * B / (L / (2 * mp.pi)))}")
    gamma = prandtl_gamma()
    print(f"ltb_gamma,,,,,,,,,,,{fmt(gamma)}")
    for (Bs, Cs, Ls) in [("1.0", "1.0", "1.0"), ("2.5", "0.7", "3.0")]:
        print(f"ltb_critical_load,,{Bs},{Cs},,,{Ls},,,,,{fmt(gamma * mp.sqrt(d(Bs) * d(Cs)) / d(Ls) ** 2)}")


main()
