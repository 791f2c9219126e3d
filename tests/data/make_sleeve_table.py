#!/usr/bin/python3
"""Generate tests/data/sleeve_reference.csv, the high-precision table for references/sleeve.hpp.

Sliding sleeve (PHYSICS.md 6.1) and elastica arm scale (PHYSICS.md 6.2, Bosi et al. 2014).

Method (independent of references/src/sleeve.cpp: no elliptic integral, no quadrature of the first
integral, and not the tip condition P sin(beta) = N that the C++ solves). Each free arm is integrated
from the sleeve exit outwards as the initial value problem
    x' = cos phi,  w' = sin phi,  phi' = m / B,  m' = -P cos phi,
    phi(0) = theta0 (exit angle below the horizontal), m(0) = M (exit moment), x(0) = w(0) = 0,
with phi the tangent angle below the horizontal, m = B phi' the bending moment, w the downward drop.
(phi, m) are integrated with mpmath.odefun (Taylor-series method, tolerance ~ working epsilon) at
mp.dps = DPS; x and w are tanh-sinh quadratures (mpmath.quad) of cos phi, sin phi over the odefun
solution. The free tip is where the moment vanishes: the arm length l(M) is the first zero of m(s)
(m' < 0 while |phi| < pi/2), found by Anderson-Bjorck on a bracket.

  * sleeve_length rows (6.1, free length l given, theta0 = 0): shoot on M so that m(l) = 0
    (Illinois on a 15-digit bracket, then secant at 20 digits and at DPS digits). Written:
    tip_angle = phi(l), exit_moment = M, tension_jump = M^2/(2B), invariant = P sin(phi(l)),
    tip_x = x(l), tip_y = -w(l).
  * sleeve_pull rows (6.1, pull S given): M = sqrt(2 B S) from the Eshelby-like balance at the exit
    (N_in - N_out = M^2/(2B) with N_out = 0), then l = first zero of m; no shooting. Written:
    free_length, tip_angle, exit_moment, tip_x, tip_y.
  * arm_scale rows (6.2): arm 1 with theta0 = +alpha and load P1, arm 2 with theta0 = -alpha and P2.
    The axial balance of the rod inside the frictionless sleeve is imposed at the EXITS,
    (P1 + P2) sin alpha = (M2^2 - M1^2)/(2B) (PHYSICS.md 6.2), so M2 follows from M1 (or M1 from M2
    when sin alpha < 0); the unknown M1 solves l1(M1) + l2(M2(M1)) = L - sleeve_length (increasing
    in M1). Written: l1, l2, beta1, beta2 (tip angles), M1, M2, N = M1^2/(2B) + P1 sin alpha,
    tip positions: exits at -/+ (sleeve_length/2)(cos alpha, sin alpha), arm 1 towards -x, arm 2 +x:
    tip1 = (-h cos alpha - x1, -h sin alpha - w1), tip2 = (h cos alpha + x2, h sin alpha - w2).
  * Cross-checks (stderr only): P sin(beta) at the tip against M^2/(2B) + P sin(theta0) at the exit
    (the Noether invariant H along each arm; for the arm scale P1 sin beta1 = P2 sin beta2 = N),
    x(l) against M/P (moment balance of the tip load), and the PHYSICS.md 6.1 table (13 digits).

Staging (to keep the run short): each outer root (M for sleeve_length, the unknown exit moment for
arm_scale) is bracketed and refined by Illinois at 15 digits, refined by the secant method at 22
digits, and finished by ONE secant step at DPS digits through two evaluations; the written values are
interpolated linearly between those two evaluations to the secant root (errors ~1e-40, see refine()).

Every input (P, B, l, S, alpha, P1, P2, L, sleeve_length) is a binary64 number; the table stores its
shortest round-trip decimal form and the computation uses exactly that binary value (L -
sleeve_length is formed exactly, not rounded). Values are printed with DIGITS significant digits.
Long format: kind,P1,P2,B,alpha,L,sleeve_length,S,quantity,value with P1 = P, L = l for the sleeve
kinds; unused inputs are empty.

Usage:  /usr/bin/python3 tests/data/make_sleeve_table.py   (run by hand, prints progress)
"""
import os
import sys
import time

import mpmath
from mpmath import mp, mpf

DPS = 34      # working precision (30 written digits + guard digits)
DIGITS = 30   # significant digits written to the table
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "sleeve_reference.csv")
START = time.time()


def log(message):
    print(f"[{time.time() - START:6.1f}s] {message}", file=sys.stderr, flush=True)


def fmt(x):
    if not isinstance(x, (mpf, int)):
        raise TypeError(f"table value {x!r} is not real")
    return mp.nstr(mpf(x), DIGITS, min_fixed=-mp.inf, max_fixed=mp.inf)


def fmt_input(x):
    """Shortest decimal string that round-trips to the binary64 value x ('' for None)."""
    return "" if x is None else repr(float(x))


_ARM_CACHE = {}


def make_arm(theta0, P, B, M):
    """Arm(...) memoised on (precision, inputs): a secant iterate is not integrated twice."""
    key = (mp.prec, mpf(theta0), mpf(P), mpf(B), mpf(M))
    if key not in _ARM_CACHE:
        _ARM_CACHE[key] = Arm(theta0, P, B, M)
    return _ARM_CACHE[key]


class Arm:
    """One free arm integrated from the exit: phi(0) = theta0, m(0) = M (binary64 or mpf inputs)."""

    def __init__(self, theta0, P, B, M):
        self.theta0, self.P, self.B, self.M = mpf(theta0), mpf(P), mpf(B), mpf(M)
        P_, B_ = self.P, self.B
        self.f = mp.odefun(lambda _s, y: [y[1] / B_, -P_ * mp.cos(y[0])], 0, [self.theta0, self.M])

    def moment(self, s):
        return self.f(s)[1]

    def length(self, cap):
        """First zero of m in (0, cap], or None if m > 0 on (0, cap] (the arm is longer than cap).
        Scanned upwards in steps of cap/32 (odefun integrates only up to the bracket), then
        Anderson-Bjorck on the bracket."""
        step = mpf(cap) / 32
        lo = mpf(0)
        while True:
            hi = min(lo + step, mpf(cap))
            if self.moment(hi) <= 0:
                return mp.findroot(self.moment, (lo, hi), solver="anderson", verify=False)
            if hi >= cap:
                return None
            lo = hi

    def tip(self, l):
        """(beta, m(l), x(l), w(l)) with x, w by tanh-sinh quadrature over the odefun solution."""
        phi_l, m_l = self.f(l)
        x = mp.quad(lambda s: mp.cos(self.f(s)[0]), [0, l])
        w = mp.quad(lambda s: mp.sin(self.f(s)[0]), [0, l])
        return phi_l, m_l, x, w


def illinois(f, lo, hi, tol):
    """Root of an increasing-or-decreasing f on [lo, hi] (sign change required) to |step| <= tol."""
    flo, fhi = f(lo), f(hi)
    if flo * fhi > 0:
        raise RuntimeError(f"not bracketed: f({lo})={flo}, f({hi})={fhi}")
    side = 0
    x = lo
    for _ in range(300):
        x = (lo * fhi - hi * flo) / (fhi - flo)
        fx = f(x)
        if fx == 0 or hi - lo <= tol:
            return x
        if (fx > 0) == (fhi > 0):
            hi, fhi = x, fx
            if side == 1:
                flo /= 2
            side = 1
        else:
            lo, flo = x, fx
            if side == -1:
                fhi /= 2
            side = -1
        if abs(hi - lo) <= tol:
            return x
    raise RuntimeError("Illinois iteration did not converge")


def refine(evaluate, guess):
    """From a 15-digit guess: secant at 22 digits on the residual, then ONE secant step at full
    precision through u0 = guess and u1 = u0 (1 + 1e-18); the written outputs are interpolated
    linearly to that step's root u2. evaluate(u) returns (residual, [outputs]) at the current
    precision. With |u0 - u*| ~ 1e-22 |u*| the secant root has an error ~ C 1e-22 1e-18 and the
    interpolation an error ~ |g''| |u2 - u0| |u2 - u1| ~ 1e-40 relative, both far below 1e-DPS.
    Returns (u2, outputs, residuals at u0 and u1)."""
    with mp.workdps(22):
        guess = mp.findroot(lambda u: evaluate(u)[0], (mpf(guess), mpf(guess) * (1 + mpf("1e-9"))),
                            solver="secant", verify=False)
    u0 = mpf(guess)
    u1 = u0 * (1 + mpf("1e-18"))
    r0, out0 = evaluate(u0)
    r1, out1 = evaluate(u1)
    u2 = u1 - r1 * (u1 - u0) / (r1 - r0)
    t = (u2 - u0) / (u1 - u0)
    return u2, [o0 + t * (o1 - o0) for o0, o1 in zip(out0, out1)], (r0, r1)


# ---------------------------------------------------------------------------------------------
def sleeve_length_row(P, B, l, rows):
    l_ = mpf(l)
    shoot = lambda M: make_arm(0, P, B, M).moment(l_)      # m(l; M), increasing in M
    with mp.workdps(15):
        # M = P x_tip lies in (0, P l); near 0 the rod is straight, at P l it is over-bent
        guess = illinois(shoot, mpf(P) * l_ * mpf("0.05"), mpf(P) * l_, mpf("1e-10") * mpf(P) * l_)

    def evaluate(M):
        arm = make_arm(0, P, B, M)
        if mp.prec <= 80:               # the 22-digit stage needs the residual only
            return arm.moment(l_), []
        phi_l, m_l, x, w = arm.tip(l_)
        return m_l, [M, phi_l, x, w]

    _, (M, phi_l, x, w), (r0, r1) = refine(evaluate, guess)
    invariant = mpf(P) * mp.sin(phi_l)
    jump = M * M / (2 * mpf(B))
    check = max(abs(invariant - jump), abs(x - M / mpf(P)))
    key = ("sleeve_length", P, None, B, None, l, None, None)
    for name, value in (("tip_angle", phi_l), ("invariant", invariant), ("exit_moment", M),
                        ("tension_jump", jump), ("tip_x", x), ("tip_y", -w)):
        rows.append(key + (name, value))
    return check, phi_l, invariant, M, x


def sleeve_pull_row(P, B, S, rows):
    M = mp.sqrt(2 * mpf(B) * mpf(S))
    arm = Arm(0, P, B, M)
    # l < 40 sqrt(B/P) for S/P <= 0.9999 (l ~ sqrt(B/P) ln(...) grows slowly)
    l = arm.length(40 * mp.sqrt(mpf(B) / mpf(P)))
    phi_l, m_l, x, w = arm.tip(l)
    check = max(abs(mpf(P) * mp.sin(phi_l) - mpf(S)), abs(x - M / mpf(P)))
    key = ("sleeve_pull", P, None, B, None, None, None, S)
    for name, value in (("free_length", l), ("tip_angle", phi_l), ("exit_moment", M), ("tip_x", x),
                        ("tip_y", -w)):
        rows.append(key + (name, value))
    return check


def arm_scale_row(alpha, P1, P2, B, L, sleeve, rows):
    a, p1, p2, b = mpf(alpha), mpf(P1), mpf(P2), mpf(B)
    free = mpf(L) - mpf(sleeve)                  # exact: both binary64
    jump = 2 * b * (p1 + p2) * mp.sin(a)          # M2^2 - M1^2
    # The unknown is the moment of the arm whose square is the smaller one.
    unknown_is_m1 = jump >= 0

    def moments(u):
        other = mp.sqrt(u * u + abs(jump))
        return (u, other) if unknown_is_m1 else (other, u)

    def lengths(u, cap):
        m1, m2 = moments(u)
        return make_arm(a, p1, b, m1).length(cap), make_arm(-a, p2, b, m2).length(cap)

    def residual(u):
        l1, l2 = lengths(u, free)
        if l1 is None or l2 is None:
            return free          # one arm alone is longer than the free length: positive
        return l1 + l2 - free

    # Bracket: u in (0, u_max), where an arm with H >= P would never reach m = 0 (it loops).
    u_max = min(mp.sqrt(max(mpf(0), 2 * b * p1 * (1 - mp.sin(a)))) if unknown_is_m1 else mp.inf,
                mp.sqrt(max(mpf(0), 2 * b * p2 * (1 + mp.sin(a)) - abs(jump))) if unknown_is_m1 else mp.inf,
                mp.sqrt(max(mpf(0), 2 * b * p2 * (1 + mp.sin(a)))) if not unknown_is_m1 else mp.inf,
                mp.sqrt(max(mpf(0), 2 * b * p1 * (1 - mp.sin(a)) - abs(jump))) if not unknown_is_m1 else mp.inf)
    with mp.workdps(15):
        guess = illinois(residual, mpf("1e-6") * u_max, u_max * (1 - mpf("1e-6")), mpf("1e-10") * u_max)

    def evaluate(u):
        if mp.prec <= 80:               # the 22-digit stage needs the residual only
            return residual(u), []
        m1, m2 = moments(u)
        arm1, arm2 = make_arm(a, p1, b, m1), make_arm(-a, p2, b, m2)
        l1, l2 = arm1.length(free), arm2.length(free)
        beta1, _, x1, w1 = arm1.tip(l1)
        beta2, _, x2, w2 = arm2.tip(l2)
        return l1 + l2 - free, [m1, m2, l1, l2, beta1, beta2, x1, w1, x2, w2]

    u, (m1, m2, l1, l2, beta1, beta2, x1, w1, x2, w2), (r0, r1) = refine(evaluate, guess)
    N = m1 * m1 / (2 * b) + p1 * mp.sin(a)
    h = mpf(sleeve) / 2
    check = max(abs(l1 + l2 - free), abs(p1 * mp.sin(beta1) - N), abs(p2 * mp.sin(beta2) - N),
                abs(x1 - m1 / p1), abs(x2 - m2 / p2))
    key = ("arm_scale", P1, P2, B, alpha, L, sleeve, None)
    for name, value in (("l1", l1), ("l2", l2), ("beta1", beta1), ("beta2", beta2), ("M1", m1),
                        ("M2", m2), ("N", N),
                        ("tip1_x", -h * mp.cos(a) - x1), ("tip1_y", -h * mp.sin(a) - w1),
                        ("tip2_x", h * mp.cos(a) + x2), ("tip2_y", h * mp.sin(a) - w2)):
        rows.append(key + (name, value))
    return check


# PHYSICS.md 6.1 table: alpha -> (phi_tip, S/P, M_e l/B, x_tip/l) at l = B = 1, P = alpha.
PHYSICS_61 = {
    0.5: ("0.2445336471332", "0.2421038721061", "0.4920405187646", "0.9840810375292"),
    1.0: ("0.4613519497119", "0.4451591187953", "0.9435667637166", "0.9435667637166"),
    2.0: ("0.7817498315565", "0.7045223208193", "1.678716558350", "0.8393582791748"),
    5.0: ("1.215368117612", "0.9374975614726", "3.061858196378", "0.6123716392756"),
    10.0: ("1.430285538804", "0.9901445900927", "4.450044022462", "0.4450044022462"),
}


def main():
    mp.dps = DPS
    rows = []
    worst = mpf(0)
    for P in (0.5, 1.0, 2.0, 5.0, 10.0):
        check, phi, inv, M, x = sleeve_length_row(P, 1.0, 1.0, rows)
        printed = [mpf(v) for v in PHYSICS_61[P]]
        table = max(abs(phi - printed[0]) / phi, abs(inv / P - printed[1]) / printed[1],
                    abs(M - printed[2]) / M, abs(x - printed[3]) / x)
        worst = max(worst, check)
        log(f"sleeve l=1 P={P}: check {mp.nstr(check, 3)}, vs PHYSICS 6.1 table {mp.nstr(table, 3)}")
    for P, B, S in ((1.0, 1.0, 0.25), (1.0, 1.0, 0.5), (1.0, 1.0, 0.9), (3.0, 0.7, 2.0)):
        check = sleeve_pull_row(P, B, S, rows)
        worst = max(worst, check)
        log(f"sleeve S={S} P={P} B={B}: check {mp.nstr(check, 3)}")
    for alpha, P1, P2, B, L, sleeve in ((0.0, 1.0, 1.0, 1.0, 2.0, 0.2), (0.0, 0.7, 1.0, 1.0, 2.0, 0.2),
                                        (0.1, 1.0, 1.0, 1.0, 2.0, 0.2), (0.1, 1.5, 1.0, 1.0, 2.0, 0.2),
                                        (0.3, 0.7, 1.0, 1.0, 2.0, 0.2),
                                        (0.3, 1.5, 1.0, 1.0, 2.0, 0.2), (-0.3, 0.7, 1.0, 1.0, 2.0, 0.2),
                                        (0.2, 2.0, 3.0, 0.5, 3.0, 0.5)):
        check = arm_scale_row(alpha, P1, P2, B, L, sleeve, rows)
        worst = max(worst, check)
        log(f"arm scale alpha={alpha} P1={P1} P2={P2} B={B} L={L} sleeve={sleeve}: check {mp.nstr(check, 3)}")
    log(f"worst cross-check discrepancy: {mp.nstr(worst, 3)}")
    with open(OUT, "w", encoding="utf-8") as out:
        out.write("# Sliding sleeve / elastica arm scale reference table for "
                  "tests/references/test_sleeve_reference.cpp\n")
        out.write("# Generated by tests/data/make_sleeve_table.py (mpmath %s, mp.dps = %d); do not edit.\n"
                  % (mpmath.__version__, DPS))
        out.write("# Arms integrated from the exit (phi' = m/B, m' = -P cos phi) with mpmath.odefun; x, w by\n")
        out.write("#   mpmath.quad of cos phi, sin phi; tip where m = 0; shooting on the exit moment M.\n")
        out.write("# sleeve_length: P1 = P, L = free length l. sleeve_pull: P1 = P, S = pull. arm_scale: all but S.\n")
        out.write("# Inputs are binary64 values in shortest round-trip form; values have %d significant digits.\n"
                  % DIGITS)
        out.write("kind,P1,P2,B,alpha,L,sleeve_length,S,quantity,value\n")
        for kind, P1, P2, B, alpha, L, sleeve, S, name, value in rows:
            out.write(",".join([kind, fmt_input(P1), fmt_input(P2), fmt_input(B), fmt_input(alpha),
                                fmt_input(L), fmt_input(sleeve), fmt_input(S), name, fmt(value)]) + "\n")
    log(f"wrote {len(rows)} rows to {OUT}")


if __name__ == "__main__":
    main()
