#!/usr/bin/python3
"""Generate tests/data/pendulum_reference.csv, the high-precision table for the pendulum reference.

Method (independent of the closed forms in references/src/pendulum.cpp and of GSL):
  * "state" rows: integrate  theta'' = -omega^2 sin(theta)  as a first-order system with
    mpmath.odefun (Taylor-series method, tolerance ~ working epsilon) at mp.dps = DPS, starting from
    the initial data of each family (PHYSICS.md section 2):
        libration   theta(0) = theta0, theta'(0) = 0
        rotation    theta(0) = 0,      theta'(0) = v0
        separatrix  theta(0) = 0,      theta'(0) = 2 omega
    Negative times are obtained by integrating the time-reversed problem phi(s) = theta(-s), which
    solves the same equation with phi'(0) = -theta'(0) (odefun only integrates forward).
    The energy column is E = theta'^2/2 - omega^2 cos(theta) evaluated from the integrated state.
  * "period" rows: T = 4 K(m)/omega (libration, m = sin^2(theta0/2)) and T_rot = 4 K(m)/v0
    (rotation, m = (2 omega/v0)^2) with mpmath.ellipk (parameter m) at DPS digits.
  * Cross-checks printed to stderr (not written to the table): the odefun solution at the exact
    quarter period (theta = 0) resp. one rotation period (theta = 2 pi), and the closed form with
    mpmath.ellipfun for the libration rows.

Every input (omega, theta0 or v0, t) is a binary64 number; the table stores its shortest
round-trip decimal form and the integration uses exactly that binary value, so the C++ test
evaluates the reference at precisely the same input. Values are printed with 30 significant digits.

Usage:  /usr/bin/python3 tests/data/make_pendulum_table.py   (run by hand; ~8 minutes on one core,
        dominated by the t = 50, 100 libration rows and the rotation rows)
"""
import math
import os
import sys
import time

import mpmath
from mpmath import mp, mpf

DPS = 36      # working precision of the integration (>= 30 required, 6 guard digits)
DIGITS = 30   # significant digits written to the table
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "pendulum_reference.csv")


def fmt(x):
    return mp.nstr(mpf(x), DIGITS, min_fixed=-mp.inf, max_fixed=mp.inf) if x is not None else ""


def fmt_input(x):
    """Shortest decimal string that round-trips to the binary64 value x."""
    return repr(float(x))


def solve(omega, theta_init, theta_dot_init, times):
    """Return {t: (theta, theta_dot)} for t in times (binary64 values), via mpmath.odefun."""
    w = mpf(omega)
    rhs = lambda _t, y: [y[1], -w * w * mp.sin(y[0])]
    result = {}
    forward = mp.odefun(rhs, 0, [mpf(theta_init), mpf(theta_dot_init)])
    for sign in (+1, -1):
        chosen = sorted(t for t in times if (t > 0 if sign > 0 else t < 0))
        chosen = [abs(t) for t in chosen]
        if sign > 0 and 0.0 in times:
            result[0.0] = (mpf(theta_init), mpf(theta_dot_init))
        if not chosen:
            continue
        f = forward if sign > 0 else mp.odefun(rhs, 0, [mpf(theta_init), -mpf(theta_dot_init)])
        for s in chosen:  # increasing order: odefun extends its cached solution
            th, thd = f(mpf(s))
            result[sign * s] = (th, sign * thd)
    return result, forward


def energy(omega, th, thd):
    w = mpf(omega)
    return thd * thd / 2 - w * w * mp.cos(th)


def main():
    mp.dps = DPS
    start = time.time()
    rows = []          # (kind, family, omega, param, t, theta, theta_dot, energy, period)
    worst_check = mpf(0)

    # --- libration, released from rest at theta0 ---------------------------------------------
    libration = [(1.0, 1.0), (1.0, 30.0), (1.0, 90.0), (1.0, 120.0), (1.0, 170.0),
                 (1.0, 179.0), (1.0, 179.9), (2.0, 90.0), (0.5, 170.0)]
    for omega, deg in libration:
        theta0 = math.radians(deg)   # binary64 input (what a C++ caller would pass)
        m = mp.sin(mpf(theta0) / 2) ** 2
        period = 4 * mp.ellipk(m) / mpf(omega)
        times = [0.0, 0.5, 1.0, 2.0, 5.0,
                 float(period / 8), float(period / 4), float(period / 2), float(period)]
        if deg in (30.0, 90.0) and omega == 1.0:
            times += [50.0, 100.0, -1.0, -5.0]
        times = sorted(set(times))
        sol, f = solve(omega, theta0, 0.0, times)
        # Cross-check 1: odefun theta at the exact quarter period must vanish.
        q = abs(f(period / 4)[0])
        worst_check = max(worst_check, q)
        # Cross-check 2: closed form with mpmath (parameter m) at the table times.
        for t in times:
            th, thd = sol[t]
            u = mpf(omega) * mpf(t)
            closed = 2 * mp.asin(mp.sqrt(m) * mp.ellipfun('cd', u, m=m))
            worst_check = max(worst_check, abs(closed - th))
            rows.append(("state", "libration", omega, theta0, t, th, thd, energy(omega, th, thd), None))
        rows.append(("period", "libration", omega, theta0, None, None, None,
                     -mpf(omega) ** 2 * mp.cos(mpf(theta0)), period))
        print(f"libration omega={omega} theta0={deg} deg: |theta(T/4)|={mp.nstr(q, 3)}  "
              f"t={time.time() - start:.0f}s", file=sys.stderr)

    # --- rotation, theta(0) = 0, theta'(0) = v0 > 2 omega -------------------------------------
    rotation = [(1.0, 2.5), (1.0, 3.0), (1.0, 5.0), (2.0, 5.0), (2.0, 8.0)]
    for omega, v0 in rotation:
        m = (2 * mpf(omega) / mpf(v0)) ** 2
        period = 4 * mp.ellipk(m) / mpf(v0)
        times = [0.0, 0.5, 1.0, 2.0, 5.0, float(period / 2), float(period), float(3 * period / 2),
                 float(2 * period), float(3 * period)]
        if omega == 1.0 and v0 == 3.0:
            times += [20.0, -1.0]
        times = sorted(set(times))
        sol, f = solve(omega, 0.0, v0, times)
        q = abs(f(period)[0] - 2 * mp.pi)   # one full turn after T_rot
        worst_check = max(worst_check, q)
        for t in times:
            th, thd = sol[t]
            rows.append(("state", "rotation", omega, v0, t, th, thd, energy(omega, th, thd), None))
        rows.append(("period", "rotation", omega, v0, None, None, None,
                     mpf(v0) ** 2 / 2 - mpf(omega) ** 2, period))
        print(f"rotation omega={omega} v0={v0}: |theta(T_rot)-2pi|={mp.nstr(q, 3)}  "
              f"t={time.time() - start:.0f}s", file=sys.stderr)

    # --- separatrix, theta(0) = 0, theta'(0) = 2 omega -----------------------------------------
    for omega, times in [(1.0, [0.0, 0.5, 1.0, 2.0, 5.0, 10.0, -2.0]), (2.0, [0.5, 1.0, 2.5])]:
        times = sorted(set(times))
        sol, _ = solve(omega, 0.0, 2.0 * omega, times)
        for t in times:
            th, thd = sol[t]
            rows.append(("state", "separatrix", omega, 2.0 * omega, t, th, thd,
                         energy(omega, th, thd), None))
        print(f"separatrix omega={omega}  t={time.time() - start:.0f}s", file=sys.stderr)

    print(f"worst cross-check discrepancy: {mp.nstr(worst_check, 3)}", file=sys.stderr)

    with open(OUT, "w", encoding="utf-8") as out:
        out.write("# Pendulum reference table for tests/references/test_pendulum_reference.cpp\n")
        out.write("# Generated by tests/data/make_pendulum_table.py (mpmath %s, mp.dps = %d); do not edit.\n"
                  % (mpmath.__version__, DPS))
        out.write("# state rows: theta'' = -omega^2 sin(theta) integrated with mpmath.odefun (Taylor series)\n")
        out.write("#   from the initial data (libration: theta0 at rest; rotation: 0, v0; separatrix: 0, 2 omega);\n")
        out.write("#   energy = theta_dot^2/2 - omega^2 cos(theta) of the integrated state.\n")
        out.write("# period rows: 4 K(m)/omega (libration) or 4 K(m)/v0 (rotation) with mpmath.ellipk; energy exact.\n")
        out.write("# param = theta0 [rad] (libration), v0 (rotation), 2 omega (separatrix). Inputs are binary64\n")
        out.write("#   values in shortest round-trip form; outputs have %d significant digits.\n" % DIGITS)
        out.write("kind,family,omega,param,t,theta,theta_dot,energy,period\n")
        for kind, family, omega, param, t, th, thd, e, per in rows:
            out.write(",".join([kind, family, fmt_input(omega), fmt_input(param),
                                "" if t is None else fmt_input(t),
                                fmt(th) if th is not None else "", fmt(thd) if thd is not None else "",
                                fmt(e), fmt(per) if per is not None else ""]) + "\n")
    print(f"wrote {len(rows)} rows to {OUT} in {time.time() - start:.0f}s", file=sys.stderr)


if __name__ == "__main__":
    main()
