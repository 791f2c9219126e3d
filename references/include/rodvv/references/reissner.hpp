#pragma once
// Closed forms for the extensible, shearable planar rod (planar Reissner / special Cosserat rod;
// Reissner 1972, ZAMP 23:795-804; Simo & Vu-Quoc 1986, CMAME 58:79-116). theta is the angle of the
// cross-section (director t), r' = (1 + n.t/EA) t + (n.N/GA) N, m = EI theta', m' + r' x n = 0.
// Any consistent units. Invalid input throws rodvv::InputError naming the parameter and its range;
// EA, GA may be +infinity (rigid).
//
// 1. Bar in pure tension/compression: clamped at s = 0, an axial dead force F at s = L (F > 0
//    tension). The straight state has n.t = F, stretch F/EA on every element: end displacement
//    F L / EA, independent of GA and EI. (Any F > -EA; the straight state is an equilibrium for all
//    such F, it is stable below the critical load of case 2's clamped-free analogue.)
// 2. Critical load of the pinned-pinned column under a dead compressive end load P (first
//    bifurcation from the compressed straight state, mode theta = A cos(k pi s / L)). Linearising the
//    moment balance about theta = 0, n = -P e_x gives
//        EI theta'' = -P (1 - P/EA + P/GA) theta,
//    so the k-th bifurcation load solves P (1 + P (1/GA - 1/EA)) = P_k = k^2 pi^2 EI / L^2:
//        P_cr = 2 P_k / (1 + sqrt(1 + 4 P_k (1/GA - 1/EA))).
//    With EA = +inf this is Haringx's formula P = (GA/2)(sqrt(1 + 4 P_E/GA) - 1) (Haringx 1948,
//    Philips Res. Rep. 3; the Reissner model measures shear against the cross-section, hence
//    Haringx and not Engesser's P_E / (1 + P_E/GA)); with EA = GA it is P_E exactly (the compressive
//    shortening and the shear compliance cancel); EA = GA = +inf gives Euler's P_E. For
//    1 + 4 P_k (1/GA - 1/EA) < 0 (EA < GA, very compliant in extension) there is no bifurcation of
//    this mode: InputError.
namespace rodvv::references {

// F L / EA. F finite and > -EA (the stretch 1 + F/EA stays > 0), L > 0, EA in (0, +inf].
double reissner_bar_end_displacement(double force, double length, double axial_stiffness);

// P_cr of mode k (k >= 1) of the pinned-pinned extensible, shearable column; L, EI > 0 finite,
// EA, GA in (0, +inf].
double reissner_pinned_critical_load(double length, double bending_stiffness, double axial_stiffness,
                                     double shear_stiffness, int mode = 1);

}  // namespace rodvv::references
