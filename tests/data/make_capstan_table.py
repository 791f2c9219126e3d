#!/usr/bin/python3
"""High-precision reference table for references/capstan (tests/references/test_capstan_reference.cpp).

The capstan with bending stiffness B (references/capstan.hpp), computed by another route than the C++
closed form: each free span is the tension elastica's homoclinic in closed form (angle from its tail
theta(x) = 4 atan(e^{x / lambda}), curvature (2 / lambda) sech(x / lambda), lambda = sqrt(B / T)),
left where its curvature reaches 1 / R (findroot), which gives its turn psi; the contact ends' point
forces from the vector jump of n with plane vectors (the normal part of n must vanish inside the
contact); the contact arc's dT/dphi = mu T integrated by odefun; T_hold by findroot on the mismatch of
the two contact tensions; each tail's offset from the height of its span's leaving point above the
tail line (odefun of sin theta) and its turned normal. Every parameter is the exact binary value of the double printed in its column.
Run (about 9 minutes: odefun at 40 digits along the tails): /usr/bin/python3 tests/data/make_capstan_table.py > tests/data/capstan_reference.csv
"""
import mpmath as mp

mp.mp.dps = 40


def d(text):
    return mp.mpf(float(text))


def span(B, R, T, offset=False):
    """Turn psi of a homoclinic span of tail tension T leaving a cylinder of radius R (or its tail line's
    offset from the cylinder: the axis's distance from the line, minus R)."""
    lam = mp.sqrt(B / T)
    start = -float(lam) * mp.acosh(2 * float(R / lam)) * 1.001  # a start in double, refined at 40 digits
    x = mp.findroot(lambda x: 2 / lam * mp.sech(x / lam) - 1 / R, start)  # the rising side, x < 0
    assert x < 0
    psi = 4 * mp.atan(mp.exp(x / lam))
    if not offset:
        return psi
    # distance of the leaving point from the tail line: the integral of sin(theta) from the tail (odefun)
    theta = lambda s: 4 * mp.atan(mp.exp(s / lam))
    start = x - 60 * lam  # e^-60: the tail line to 40 digits
    height = mp.odefun(lambda s, y: mp.sin(theta(s)), start, mp.mpf(0))(x)
    return height + R * mp.cos(psi) - R


def contact_tension(T, psi, mu, side):
    """n.t inside the contact next to a span of tail tension T, turned by psi; side +1 pulling, -1 holding.

    Plane vectors in the contact end's frame: t = (1, 0), outward normal nu = (0, 1). The tail lies
    ahead of the pulling end (turned further toward the cylinder: cos psi t - sin psi nu) and behind the
    holding end (cos psi t + sin psi nu). The point force F = P nu + mu P t (sliding friction along +t,
    the rod moving toward the holding side) cancels the span's normal force.
    """
    if side > 0:  # n_contact = n_span + F
        n_span = (T * mp.cos(psi), -T * mp.sin(psi))
        P = -n_span[1]
        n_contact = (n_span[0] + mu * P, n_span[1] + P)
    else:  # n_contact = n_span - F
        n_span = (T * mp.cos(psi), T * mp.sin(psi))
        P = n_span[1]
        n_contact = (n_span[0] - mu * P, n_span[1] - P)
    assert abs(n_contact[1]) < mp.mpf(10) ** -35
    return n_contact[0], P


def capstan(B, R, mu, phi, T_pull):
    psi_pull = span(B, R, T_pull)
    T_b, P_pull = contact_tension(T_pull, psi_pull, mu, +1)

    def arc(T_hold):
        phi_c = phi - span(B, R, T_hold) - psi_pull
        T = mp.odefun(lambda a, y: mu * y, 0, T_b)  # tension along the contact, from the pulling end
        return T(phi_c)

    def mismatch(T_hold):
        return contact_tension(T_hold, span(B, R, T_hold), mu, -1)[0] - arc(T_hold)

    T_hold = mp.findroot(mismatch, T_pull * mp.exp(mu * phi))
    psi_hold = span(B, R, T_hold)
    return {
        "hold_tension": T_hold,
        "contact_angle": phi - psi_hold - psi_pull,
        "hold_turn": psi_hold,
        "pull_turn": psi_pull,
        "hold_end_force": contact_tension(T_hold, psi_hold, mu, -1)[1],
        "pull_end_force": P_pull,
        "hold_offset": span(B, R, T_hold, offset=True),
        "pull_offset": span(B, R, T_pull, offset=True),
    }


ROWS = [  # B, R, mu, wrap_angle, pull_tension
    ("0.736", "0.8", "0.3", "3.141592653589793", "2.3"),
    ("0.05", "1.7", "0.45", "1.5707963267948966", "0.9"),
    ("12.5", "2.2", "0.12", "4.4", "3.7"),
    ("0.0031", "0.11", "0.8", "2.1", "0.47"),
    ("0.736", "0.8", "0.0", "3.141592653589793", "2.3"),
]


def main():
    print("quantity,B,R,mu,wrap_angle,pull_tension,value")
    for B, R, mu, phi, T in ROWS:
        solution = capstan(d(B), d(R), d(mu), d(phi), d(T))
        for name, value in solution.items():
            print(f"{name},{B},{R},{mu},{phi},{T},{mp.nstr(value, 30)}")


if __name__ == "__main__":
    main()
