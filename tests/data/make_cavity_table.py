#!/usr/bin/python3
"""Generate tests/data/cavity_reference.csv, the high-precision table for references/cavity.hpp.

Pinned-pinned elastica between frictionless walls y = +/- a (PHYSICS.md 4.1), L = EI = 1, a = 0.1.

Method (independent of references/src/cavity.cpp: no elliptic integral, Jacobi function or Carlson
form is used). Each half wave obeys EI phi'' = -F sin phi with phi = theta - psi (force tilted by psi)
and has the first integral phi'^2 = 2 lambda^2 (cos phi - cos phi0), lambda^2 = F/EI, where phi0 is
the turning angle at the pin (kappa = 0). With phi decreasing monotonically from phi0 to phi1 along
the arc, the arc length and the coordinates are the quadratures
    lambda s  = int_{phi1}^{phi0} dphi / R,   R = sqrt(2 (cos phi - cos phi0))
    lambda x  = int cos(phi + psi) dphi / R,  lambda y = int sin(phi + psi) dphi / R,
evaluated with mpmath.quad (tanh-sinh) at mp.dps = DPS. The inverse-square-root end singularities
are removed by phi = phi0 - t^2 on [0, phi0] and phi = -phi0 + t^2 on [phi1, 0], with
cos phi - cos phi0 = 2 sin((phi0 - phi)/2) sin((phi0 + phi)/2) written without cancellation.
Roots are found by bisection to a bracket width of 1e-3 followed by the Illinois method on that
bracket, to |f| <= 16 eps_mp (the residual is a length or a shortening of size ~0.1).

  * point contact, tilt psi: left half from the pin (phi = phi0) to the contact (theta = 0, i.e.
    phi1 = -psi) at s = L/2, so lambda = 2 T / L. Unknown phi0 in (psi, pi/2): y_c = a.
    P = F cos psi, wall force 2 F sin psi, kappa_c = lambda R(-psi), H = -F cos phi0,
    shortening = L - 2 x_c, theta0 = phi0 + psi.
  * line contact, flat length l: each side L' = (L - l)/2 runs inflection to inflection, psi = phi0,
    phi1 = -phi0, lambda = T / L'. Unknown phi0: y = a. P = F cos phi0, edge force Q = F sin phi0,
    wall force 2Q, H = -P, shortening = L - l - 2 x_side.
  * free first mode: point-contact formulas with psi = 0 and phi0 = theta0, y_M < a.
  * touch: y_M = a at psi = 0; transition: line contact with l = 0.
  * inversion from the shortening d: the regime follows from d_touch, d_transition; the free and
    line branches solve one unknown (theta0, l), the point branch nests psi (outer) and phi0 (inner).

Every input (psi = math.radians(psi_deg), l, d) is a binary64 number; the table stores its shortest
round-trip decimal form and the computation uses exactly that binary value. Values are printed with
30 significant digits. Long format: kind,param,quantity,value, kind in {point_psi, line_l,
shortening, touch, transition}; regime is 0 free, 1 point, 2 line.

Cross-checks: the PHYSICS.md 4.1 table values are reproduced to their 12-13 printed digits; a rerun
of psi = 6 deg and l = 0.3 at mp.dps = 44 agrees with the table to all 30 written digits; at the
point -> line transition (psi = phi0) the point-branch formulas give the line-branch P (logged).

Usage:  /usr/bin/python3 tests/data/make_cavity_table.py   (about 2.2 minutes on one core of a loaded
        2-core machine, dominated by the nested point-contact inversions)
"""
import math
import os
import sys
import time

import mpmath
from mpmath import mp, mpf

DPS = 34      # working precision (30 written + guard digits)
DIGITS = 30
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cavity_reference.csv")
START = time.time()
L = mpf(1)
EI = mpf(1)
A = mpf("0.1")   # the binary64 value of 0.1 is set below, after mp.dps


def log(message):
    print(f"[{time.time() - START:6.1f}s] {message}", file=sys.stderr, flush=True)


def fmt(x):
    if not isinstance(x, (mpf, int)):   # a complex value would mean a failed root solve
        raise TypeError(f"table value {x!r} is not real")
    return mp.nstr(mpf(x), DIGITS, min_fixed=-mp.inf, max_fixed=mp.inf)


def half_wave(phi0, phi1, psi):
    """(lambda s, lambda x, lambda y) from phi = phi0 (turning point) down to phi = phi1 >= -phi0."""
    def pieces(g):
        # upper piece phi in [max(phi1, 0), phi0]: phi = phi0 - t^2, dphi = 2t dt
        lo = max(phi1, mpf(0))

        def up(t):
            phi = phi0 - t * t
            r2 = 4 * mp.sin(t * t / 2) * mp.sin(phi0 - t * t / 2)
            return 2 * t * g(phi) / mp.sqrt(r2)
        total = mp.quad(up, [0, mp.sqrt(phi0 - lo)])
        if phi1 < 0:
            # lower piece phi in [phi1, 0]: phi = -phi0 + t^2
            def down(t):
                phi = -phi0 + t * t
                r2 = 4 * mp.sin(phi0 - t * t / 2) * mp.sin(t * t / 2)
                return 2 * t * g(phi) / mp.sqrt(r2)
            total += mp.quad(down, [mp.sqrt(phi1 + phi0), mp.sqrt(phi0)])
        return total

    T = pieces(lambda phi: mpf(1))
    X = pieces(lambda phi: mp.cos(phi + psi))
    Y = pieces(lambda phi: mp.sin(phi + psi))
    return T, X, Y


def solve(f, lo, hi, tol=mpf("1e-3")):
    """Root of f in [lo, hi] (sign change required): bisection to a bracket of width tol, then the
    Illinois variant of regula falsi, which keeps the bracket (never leaves the real interval)."""
    flo, fhi = f(lo), f(hi)
    if flo * fhi > 0:
        raise RuntimeError(f"not bracketed: f({lo})={flo}, f({hi})={fhi}")
    while hi - lo > tol:
        mid = (lo + hi) / 2
        fm = f(mid)
        if fm == 0:
            return mid
        if (fm > 0) == (fhi > 0):
            hi, fhi = mid, fm
        else:
            lo, flo = mid, fm
    side = 0
    for _ in range(200):
        x = (lo * fhi - hi * flo) / (fhi - flo)
        fx = f(x)
        if fx == 0 or hi - lo <= mp.eps * 64 * abs(x) or abs(fx) <= mp.eps * 16:
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
    raise RuntimeError("Illinois iteration did not converge")


def point_state(psi, phi0=None, phi0_max=mp.radians(60)):
    """Point-contact (or free, psi = 0 with y < a) state; phi0 solved from y_c = a if not given."""
    def geometry(p0):
        T, X, Y = half_wave(p0, -psi, psi)
        lam = 2 * T / L
        return lam, X / lam, Y / lam
    if phi0 is None:
        # y_c grows with phi0 up to its maximum (0.403 L at psi = 0, phi0 = 1.985); the bracket
        # [psi, 60 deg] covers a = 0.1, wider gaps pass phi0_max
        phi0 = solve(lambda p: geometry(p)[2] - A, psi + mpf("1e-20"), phi0_max)
    lam, xc, yc = geometry(phi0)
    F = EI * lam ** 2
    r = mp.sqrt(4 * mp.sin((phi0 - psi) / 2) * mp.sin((phi0 + psi) / 2))
    return {"regime": 1, "P": F * mp.cos(psi), "H": -F * mp.cos(phi0), "wall_force": 2 * F * mp.sin(psi),
            "edge_force": mpf(0), "kappa_mid": lam * r, "flat_length": mpf(0), "psi": psi, "phi0": phi0,
            "theta0": phi0 + psi, "shortening": L - 2 * xc}


def line_state(l):
    side = (L - l) / 2

    def y_side(p0):
        T, X, Y = half_wave(p0, -p0, p0)
        return Y / T * side   # y = Y / lambda with lambda = T / side
    # a/L' <= 0.25 for l <= 0.6: phi0 below 60 deg, first root (y_side increases from 0)
    phi0 = solve(lambda p: y_side(p) - A, mpf("1e-6"), mp.radians(60))
    T, X, Y = half_wave(phi0, -phi0, phi0)
    lam = T / side
    F = EI * lam ** 2
    P = F * mp.cos(phi0)
    Q = F * mp.sin(phi0)
    return {"regime": 2, "P": P, "H": -P, "wall_force": 2 * Q, "edge_force": Q, "kappa_mid": mpf(0),
            "flat_length": l, "psi": phi0, "phi0": phi0, "theta0": 2 * phi0,
            "shortening": L - l - 2 * X / lam}


def free_state(theta0):
    s = point_state(mpf(0), theta0)
    s["regime"] = 0
    s["psi"] = mpf(0)
    s["wall_force"] = mpf(0)
    return s


def main():
    global A
    mp.dps = DPS
    A = mpf(0.1)   # exactly the binary64 gap used by the C++ CavityColumn default
    rows = []

    def emit(kind, param, state, quantities):
        for q in quantities:
            rows.append((kind, param, q, state[q]))

    allq = ["regime", "P", "H", "wall_force", "edge_force", "kappa_mid", "flat_length", "psi", "phi0",
            "theta0", "shortening"]

    touch = point_state(mpf(0))
    log(f"touch d = {touch['shortening']}")
    rows.append(("touch", "", "shortening", touch["shortening"]))
    line0 = line_state(mpf(0))
    psi_t = line0["phi0"]
    log(f"transition d = {line0['shortening']}, psi_t = {mp.degrees(psi_t)} deg")
    rows.append(("transition", "", "shortening", line0["shortening"]))
    # Cross-check of the transition with the point branch at psi = phi0 = psi_t (kappa_c = 0).
    pt = point_state(psi_t, psi_t)
    log(f"  point branch at psi_t: y check via P {pt['P']} vs line {line0['P']}")

    for deg in [0, 2, 4, 6, 8, 10, 11, 11.5]:
        psi = math.radians(deg)
        s = point_state(mpf(psi))
        emit("point_psi", repr(psi), s, ["P", "H", "wall_force", "kappa_mid", "phi0", "theta0", "shortening"])
        log(f"psi = {deg} deg: P = {mp.nstr(s['P'], 15)}, d = {mp.nstr(s['shortening'], 15)}")

    for l in [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6]:
        s = line_state(mpf(l))
        emit("line_l", repr(l), s, ["P", "H", "wall_force", "edge_force", "phi0", "theta0", "shortening"])
        log(f"l = {l}: P = {mp.nstr(s['P'], 15)}, d = {mp.nstr(s['shortening'], 15)}")

    d_touch, d_line = touch["shortening"], line0["shortening"]
    for d in [0.005, 0.015, 0.025, 0.0255, 0.026, 0.027, 0.03, 0.0345, 0.05, 0.08]:
        D = mpf(d)
        if D <= d_touch:
            t0 = solve(lambda t: free_state(t)["shortening"] - D, mpf("1e-3"), touch["phi0"])
            s = free_state(t0)
        elif D <= d_line:
            psi = solve(lambda p: point_state(p)["shortening"] - D, mpf(0), psi_t * (1 - mpf("1e-9")))
            s = point_state(psi)
        else:
            lf = solve(lambda x: line_state(x)["shortening"] - D, mpf(0), mpf("0.6"))
            s = line_state(lf)
        emit("shortening", repr(d), s, allq)
        log(f"d = {d}: regime {s['regime']}, P = {mp.nstr(s['P'], 15)}, H = {mp.nstr(s['H'], 15)}")

    # Wider gaps (the touch needs phi0 past 60 deg; at 0.3 past the 0.95 pi bracket's monotone part):
    # touch and transition shortenings, param = the gap.
    for gap in [0.2, 0.3]:
        A = mpf(gap)
        rows.append(("touch_gap", repr(gap), "shortening", point_state(mpf(0), None, mpf("1.98"))["shortening"]))
        rows.append(("transition_gap", repr(gap), "shortening", line_state(mpf(0))["shortening"]))
        log(f"gap {gap}: touch {mp.nstr(rows[-2][3], 15)}, transition {mp.nstr(rows[-1][3], 15)}")
    A = mpf(0.1)

    with open(OUT, "w") as out:
        out.write("# Cavity reference table for tests/references/test_cavity_reference.cpp\n")
        out.write(f"# Generated by tests/data/make_cavity_table.py (mpmath {mpmath.__version__}, "
                  f"mp.dps = {DPS}); do not edit.\n")
        out.write("# Pinned-pinned elastica between walls y = +/- a, L = EI = 1, a = 0.1 (binary64);\n")
        out.write("#   quadrature of the first integral with mpmath.quad + bisection/Illinois; no elliptic functions.\n")
        out.write("# kind: point_psi (param psi [rad]), line_l (param flat length), shortening (param d),\n")
        out.write("#   touch / transition (no param), touch_gap / transition_gap (param: the gap a).\n")
        out.write("#   regime: 0 free, 1 point, 2 line.\n")
        out.write("kind,param,quantity,value\n")
        for kind, param, q, v in rows:
            out.write(f"{kind},{param},{q},{fmt(v)}\n")
    log(f"wrote {len(rows)} rows to {OUT}")


if __name__ == "__main__":
    main()
