#pragma once
// A heavy inextensible cantilever (bending stiffness EI, weight w = rho S |g| per length) clamped horizontally at
// height delta over a rigid frictionless floor: lifted off the floor over a length l, lying on it beyond (the
// "heavy elastica on a table"; Timoshenko & Gere's beam on a rigid foundation in the small-deflection limit).
//
// Exact at any deflection, from the Noether invariant of the planar rod (PHYSICS.md §1.2),
// H = 1/2 EI kappa^2 + n.t - w y, constant along the lifted part: at the touchdown kappa = 0 (the flat part
// carries no moment), n.t = n_x = 0 (a frictionless floor, a free far end) and y = 0, so H = 0; at the
// horizontal clamp n.t = n_x = 0 and y = delta, so the clamp's moment is
//   M = sqrt(2 EI w delta).
// Small deflection (EI y'''' = -w on the lifted part; y = y' = y'' = 0 at the touchdown, y = delta, y' = 0
// at the clamp), with xi = l - x the horizontal distance from the touchdown:
//   l = (72 EI delta / w)^(1/4),  y(xi) = w l xi^3 / (18 EI) - w xi^4 / (24 EI),
//   the clamp's vertical force 2 w l / 3, a point reaction w l / 3 at the touchdown (and M = w l^2 / 6, the
//   exact value above).
// Their relative error against the exact elastica is (3/7) (delta / l)^2 for the span l and the clamp's force
// (tests/data/make_heavy_touchdown_table.py: shooting in mpmath at delta / l = 5.6e-6 .. 9e-3).
// InputError for EI, w or delta not finite and > 0.
namespace rodvv::references {

struct HeavyTouchdown {
  double EI = 1.0;     // bending stiffness in the vertical plane, > 0
  double w = 1.0;      // weight per unit length, > 0
  double delta = 1.0;  // height of the clamp above the floor, > 0
};

double touchdown_clamp_moment(const HeavyTouchdown& rod);      // exact: sqrt(2 EI w delta)
double touchdown_lifted_span(const HeavyTouchdown& rod);       // small deflection: l
double touchdown_clamp_force(const HeavyTouchdown& rod);       // small deflection: 2 w l / 3
double touchdown_height(const HeavyTouchdown& rod, double x);  // small deflection: y(x), x from the clamp; 0 at x >= l

}  // namespace rodvv::references
