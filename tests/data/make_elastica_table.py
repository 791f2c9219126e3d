#!/usr/bin/python3
"""Generate tests/data/elastica_reference.csv, the high-precision table for the elastica references.

Method (independent of the closed forms in references/src/elastica.cpp and of GSL): shooting on the
equilibrium ODEs, integrated with mpmath.odefun (Taylor-series method, tolerance ~ working epsilon)
at mp.dps = DPS, with the shooting unknown found by mpmath.findroot. No elliptic integral or Jacobi
function is used to produce a table value (mpmath.ellipk/ellipe appear only in the cross-checks
printed to stderr).

Scaling. With lambda = sqrt(P/EI) and t = lambda * s, the ODE  EI theta'' = -P sin(theta)  becomes
Theta'' = -sin(Theta) with Theta(t) = theta(t/lambda), and x, y (x' = cos, y' = sin) scale as
x(s) = X(lambda s)/lambda. The shooting parameter P then appears only as the length lambda L of the
integration interval, so each case needs one odefun integration per trial of the unknown.

  * pinned-pinned (PHYSICS.md 3.2): theta(0) = theta0, theta'(0) = 0 (pin: zero moment), y(0) = 0.
    Unknown lambda such that theta(L/2) = 0 (symmetric first mode), i.e. the first zero T of Theta:
    found with findroot (Anderson-Bjorck on a bracket from a scan), lambda = 2T/L, P = lambda^2 EI.
    Samples: theta, kappa = theta', x, y at s; y_M = y(L/2), |kappa_M|, chord = x(L),
    shortening = L - x(L), H = EI kappa_M^2/2 - P (the invariant at midspan, where cos theta = 1).
    Cross-checks: theta(L) = -theta0, theta'(L) = 0, y(L) = 0; P vs 4 K^2 EI/L^2 (mpmath.ellipk).
  * flagpole (PHYSICS.md 3.4): free tip theta = theta_tip, theta' = 0; clamp where theta = 0:
    integrate from the tip, T = first zero, lambda = T/L. delta = Y(T)/lambda,
    shortening = L - X(T)/lambda, H = EI kappa_clamp^2/2 - P.
  * cantilever with a vertical dead tip load (PHYSICS.md 3.5, Mattiasson 1981): EI phi'' = -P cos phi,
    phi(0) = 0 (clamp), phi'(L) = 0, phi(L) = phi_L. Integrate from the tip in sigma = lambda (L - s):
    Phi(0) = phi_L, Phi'(0) = 0, X' = cos Phi, W' = sin Phi. For a trial phi_L, tau(phi_L) is the first
    zero of Phi (inner findroot); the outer findroot (secant, started from a 15-digit bisection)
    solves tau(phi_L) = lambda L = sqrt(alpha). Then phi(s) = Phi(tau - lambda s),
    kappa(s) = phi'(s) = -lambda Phi'(tau - lambda s), x(s) = (X(tau) - X(tau - lambda s))/lambda,
    w(s) = (W(tau) - W(tau - lambda s))/lambda; u = L - x(L), w = w(L).
    Cross-check: sqrt(alpha) = K(k) - F(psi0, k) with mpmath (parameter m = k^2).

Every input (theta0, L, EI, P or alpha, s) is a binary64 number; the table stores its shortest
round-trip decimal form and the integration uses exactly that binary value. Values are printed with
30 significant digits. Output format (long): case,param,L,EI,s,quantity,value with param = theta0
[rad] (pinned), theta_tip [rad] (flagpole), P (cantilever; alpha = P L^2/EI); s empty for scalars.

Usage:  /usr/bin/python3 tests/data/make_elastica_table.py   (run by hand, prints progress;
        about 7 minutes on one core of a loaded 2-core machine, dominated by the cantilever rows)
"""
import math
import os
import sys
import time

import mpmath
from mpmath import mp, mpf

DPS = 36      # working precision (>= 30 required, 6 guard digits)
DIGITS = 30   # significant digits written to the table
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "elastica_reference.csv")
START = time.time()


def log(message):
    print(f"[{time.time() - START:6.1f}s] {message}", file=sys.stderr, flush=True)


def fmt(x):
    return mp.nstr(mpf(x), DIGITS, min_fixed=-mp.inf, max_fixed=mp.inf)


def fmt_input(x):
    """Shortest decimal string that round-trips to the binary64 value x."""
    return repr(float(x))


def pendulum_from_rest(theta_start):
    """odefun solution of Theta'' = -sin Theta, X' = cos Theta, Y' = sin Theta from rest."""
    rhs = lambda _t, y: [y[1], -mp.sin(y[0]), mp.cos(y[0]), mp.sin(y[0])]
    return mp.odefun(rhs, 0, [mpf(theta_start), mpf(0), mpf(0), mpf(0)])


def first_zero(f, component=0, start=mpf("0.05"), step=mpf("0.25")):
    """First t > 0 where f(t)[component] changes sign from + to -, by a scan and Anderson-Bjorck."""
    a = start
    assert f(a)[component] > 0
    b = a + step
    while f(b)[component] > 0:
        a, b = b, b + step
    return mp.findroot(lambda t: f(t)[component], (a, b), solver="anderson", verify=False)


def pinned(theta0, L, EI, s_fractions, rows):
    f = pendulum_from_rest(theta0)
    T = first_zero(f, start=mpf(1.5))            # K >= pi/2 > 1.5: Theta(1.5) > 0
    lam = 2 * T / mpf(L)
    P = lam * lam * mpf(EI)
    # Cross-checks: the other pin.
    th_end, thd_end, X_end, Y_end = f(2 * T)
    check = max(abs(th_end + mpf(theta0)), abs(thd_end), abs(Y_end))
    m = mp.sin(mpf(theta0) / 2) ** 2
    check_p = abs(P - 4 * mp.ellipk(m) ** 2 * mpf(EI) / mpf(L) ** 2) / P
    th_m, thd_m, X_m, Y_m = f(T)
    kappa_m = lam * thd_m
    scalars = {"P": P, "y_M": Y_m / lam, "kappa_M": abs(kappa_m), "chord": X_end / lam,
               "shortening": mpf(L) - X_end / lam, "H": mpf(EI) * kappa_m ** 2 / 2 - P}
    for name, value in scalars.items():
        rows.append(("pinned", theta0, L, EI, None, name, value))
    for frac in s_fractions:
        s = float(frac * L)                      # binary64 sample point
        t = lam * mpf(s)
        th, thd, X, Y = f(t)
        for name, value in (("theta", th), ("kappa", lam * thd), ("x", X / lam), ("y", Y / lam)):
            rows.append(("pinned", theta0, L, EI, s, name, value))
    return max(check, check_p)


def flagpole(theta_tip, L, EI, rows):
    f = pendulum_from_rest(theta_tip)
    T = first_zero(f, start=mpf(1.5))
    lam = T / mpf(L)
    P = lam * lam * mpf(EI)
    th, thd, X, Y = f(T)
    m = mp.sin(mpf(theta_tip) / 2) ** 2
    check = abs(P - mp.ellipk(m) ** 2 * mpf(EI) / mpf(L) ** 2) / P
    for name, value in (("P", P), ("delta", Y / lam), ("shortening", mpf(L) - X / lam),
                        ("H", mpf(EI) * (lam * thd) ** 2 / 2 - P)):
        rows.append(("flagpole", theta_tip, L, EI, None, name, value))
    return check


def cantilever_from_tip(phi_tip):
    """Integrate from the free tip: Phi'' = -cos Phi, Phi(0) = phi_tip, Phi'(0) = 0, X' = cos, W' = sin."""
    rhs = lambda _t, y: [y[1], -mp.cos(y[0]), mp.cos(y[0]), mp.sin(y[0])]
    return mp.odefun(rhs, 0, [mpf(phi_tip), mpf(0), mpf(0), mpf(0)])


_TAU_CACHE = {}


def cantilever_tau(phi_tip):
    """(tau, solution): tau is the first zero of Phi (the scaled rod length for this tip angle).
    Memoised on (precision, phi_tip): the final secant iterate is not integrated twice."""
    key = (mp.prec, phi_tip)
    if key not in _TAU_CACHE:
        f = cantilever_from_tip(phi_tip)
        # Phi decreases from phi_tip to 0; Phi ~ phi_tip - t^2 cos(phi_tip)/2 near the tip.
        _TAU_CACHE[key] = (first_zero(f, start=mpf("1e-3"), step=mpf("0.25")), f)
    return _TAU_CACHE[key]


def cantilever(P, L, EI, s_fractions, rows):
    alpha = mpf(P) * mpf(L) ** 2 / mpf(EI)
    target = mp.sqrt(alpha)
    # Stage 1: 15-digit bisection for a starting value (tau is monotone in phi_L on (0, pi/2)).
    with mp.workdps(15):
        lo, hi = mpf("1e-4"), mp.pi / 2 - mpf("1e-3")   # tau(hi) ~ 9 > sqrt(alpha) for alpha <= 80
        assert cantilever_tau(lo)[0] < target < cantilever_tau(hi)[0], "bracket"
        for _ in range(20):
            mid = (lo + hi) / 2
            if cantilever_tau(mid)[0] < target:
                lo = mid
            else:
                hi = mid
        guess = (lo + hi) / 2
    # Stage 2: secant at 20 digits (cheap), then stage 3: secant at full precision from there
    # (the costly 36-digit integrations are then needed for ~3 iterations only).
    with mp.workdps(20):
        guess = mp.findroot(lambda p: cantilever_tau(p)[0] - target,
                            (guess, guess * (1 + mpf("1e-7"))), solver="secant", verify=False)
    phi_l = mp.findroot(lambda p: cantilever_tau(p)[0] - target, (mpf(guess), guess * (1 + mpf("1e-17"))),
                        solver="secant", verify=False)
    tau, f = cantilever_tau(phi_l)
    residual = abs(tau - target)
    lam = mp.sqrt(mpf(P) / mpf(EI))
    _, _, X_tau, W_tau = f(tau)
    # Cross-check with the closed form (mpmath, parameter m = k^2).
    m = (1 + mp.sin(phi_l)) / 2
    psi0 = mp.asin(1 / mp.sqrt(2 * m))
    check = abs(mp.ellipk(m) - mp.ellipf(psi0, m) - target)
    x_tip = X_tau / lam
    for name, value in (("phi_L", phi_l), ("w", W_tau / lam), ("u", mpf(L) - x_tip),
                        ("x_tip", x_tip), ("H", mpf(P) * mp.sin(phi_l))):
        rows.append(("cantilever", P, L, EI, None, name, value))
    for frac in s_fractions:
        s = float(frac * L)
        sigma = max(tau - lam * mpf(s), mpf(0))   # tau = lambda L up to the ~1e-36 residual
        ph, phd, X, W = f(sigma)
        for name, value in (("phi", ph), ("kappa", -lam * phd), ("x", (X_tau - X) / lam),
                            ("w", (W_tau - W) / lam)):
            rows.append(("cantilever", P, L, EI, s, name, value))
    return max(residual, check)


def main():
    mp.dps = DPS
    rows = []
    worst = mpf(0)
    fractions = [0.0, 0.1, 0.25, 0.4, 0.5, 0.75, 0.9, 1.0]

    for deg, L, EI in [(10, 1.0, 1.0), (30, 1.0, 1.0), (60, 1.0, 1.0), (90, 1.0, 1.0),
                       (120, 1.0, 1.0), (150, 1.0, 1.0), (170, 1.0, 1.0), (60, 2.5, 0.7)]:
        check = pinned(math.radians(deg), L, EI, fractions, rows)
        worst = max(worst, check)
        log(f"pinned theta0={deg} deg L={L} EI={EI}: cross-check {mp.nstr(check, 3)}")

    for deg, L, EI in [(60, 1.0, 1.0), (60, 2.0, 3.0)]:
        check = flagpole(math.radians(deg), L, EI, rows)
        worst = max(worst, check)
        log(f"flagpole theta_tip={deg} deg L={L} EI={EI}: cross-check {mp.nstr(check, 3)}")

    for P, L, EI in [(0.5, 1.0, 1.0), (1.0, 1.0, 1.0), (2.0, 1.0, 1.0), (3.0, 1.0, 1.0),
                     (4.0, 1.0, 1.0), (5.0, 1.0, 1.0), (10.0, 1.0, 1.0), (20.0, 1.0, 1.0),
                     (1.5, 2.0, 3.0)]:
        check = cantilever(P, L, EI, [0.0, 0.25, 0.5, 0.75, 1.0], rows)
        worst = max(worst, check)
        log(f"cantilever P={P} L={L} EI={EI}: residual/cross-check {mp.nstr(check, 3)}")

    log(f"worst cross-check discrepancy: {mp.nstr(worst, 3)}")
    with open(OUT, "w", encoding="utf-8") as out:
        out.write("# Elastica reference table for tests/references/test_elastica_reference.cpp\n")
        out.write("# Generated by tests/data/make_elastica_table.py (mpmath %s, mp.dps = %d); do not edit.\n"
                  % (mpmath.__version__, DPS))
        out.write("# Shooting on EI theta'' = -P sin theta (pinned, flagpole) and EI phi'' = -P cos phi\n")
        out.write("#   (cantilever, dead vertical tip load) with mpmath.odefun + findroot; no elliptic functions.\n")
        out.write("# param: theta0 [rad] (pinned), theta_tip [rad] (flagpole), P (cantilever). s empty: scalar.\n")
        out.write("# Inputs are binary64 values in shortest round-trip form; values have %d significant digits.\n"
                  % DIGITS)
        out.write("case,param,L,EI,s,quantity,value\n")
        for case, param, L, EI, s, name, value in rows:
            out.write(",".join([case, fmt_input(param), fmt_input(L), fmt_input(EI),
                                "" if s is None else fmt_input(s), name, fmt(value)]) + "\n")
    log(f"wrote {len(rows)} rows to {OUT}")


if __name__ == "__main__":
    main()
