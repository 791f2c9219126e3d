#pragma once
// Closed forms for rods in self-contact (PHYSICS.md §5; pure functions, no solver code).
//
//  1. The loose-knot limit of an open trefoil under end tension T (Audoly, Clauvelin & Neukirch,
//     PRL 99:164301, 2007; Clauvelin, Audoly & Neukirch, JMPS 57:1623, 2009; PHYSICS.md §5.1). As the
//     rod thickness h -> 0 (looseness h sqrt(T/B) -> 0) the braid shrinks to a point and the loop is
//     the planar tension-elastica homoclinic, with lambda = sqrt(B/T) and u = s/lambda:
//         theta(s) = 4 arctan(e^u)  (turning from 0 to 2 pi),   kappa = (2/lambda) sech u,
//         x(s) = s - 2 lambda tanh u  (along the pull),   y(s) = 2 lambda sech u,
//         1/2 B kappa^2 + T cos theta = T  (= H, the Noether quantity, equal to T on the tails).
//     Where the tangent is perpendicular to the pull (theta = pi/2, cos theta = 0: sech^2 u = 1/2)
//     kappa_B = sqrt(2)/lambda, so T = B/(2 R_B^2) (the seed slides' "T ~ EI/R^2"); at the apex
//     (theta = pi) kappa = 2/lambda, T = B/(4 R_apex^2); the end shortening is
//     int (1 - cos theta) ds = 4 lambda; the planar loop crosses itself where x(s) = x(-s), i.e.
//     u = 2 tanh u: u_c = 1.915008048154537.
//  2. The uniform two-strand ply (PHYSICS.md §5.2; Coleman & Swigon, Phil. Trans. R. Soc. A 362:1281,
//     2004): strand 1 is r = (R cos(qs), R sin(qs), s cos theta), q = sin theta / R, strand 2 the same
//     turned by pi about the ply axis; R is the distance from a strand's axis to the ply axis (the rod
//     radius for touching rods), theta the helix angle. Curvature kappa = sin^2 theta / R, geometric
//     torsion tau_g = sin theta cos theta / R. With the internal moment m = B kappa b + M_t t, force
//     n = n_t t + n_b b and the contact force p e_r per unit length (outward), Kirchhoff's equations
//     give n_b = kappa (M_t - B tau_g) and p = n_t kappa - n_b tau_g; the total axial force F and
//     moment M of the two strands close the system:
//         M_t = -[(F R/2) sin theta - (M/2) cos theta + 2 B sin^3 theta cos theta / R] / cos 2 theta,
//         G = (M/2 - B kappa sin theta - M_t cos theta) / R,
//         n_t = (F/2) cos theta + G sin theta,   n_b = (F/2) sin theta - G cos theta.
//     With a free end loop (a plectoneme: F = M = 0):
//         p = B sin^4 theta / (R^3 cos 2 theta),  n_t = B sin^4 theta / (R^2 cos 2 theta),
//         M_t = -B sin^2 theta sin 2 theta / (R cos 2 theta),
//     and H equal in the tails and the ply gives the pulling tension of the tails
//         T_ext R^2 / B = 1/2 sin^4 theta (1 + 2 / cos 2 theta).
//     Valid for 0 < theta < pi/4 (everything diverges as theta -> 45 degrees). The signs are those of
//     a right-handed ply; a left-handed one (theta -> -theta) flips M_t and n_b.
//
// Invalid input: rodvv::InputError naming the parameter and its range.
#include "rodvv/common/eigen_types.hpp"

namespace rodvv::references {

// ---- 1. loose knot (tension-elastica homoclinic) ----------------------------------------------------
struct LooseKnot {
  double B = 1.0;  // bending stiffness, > 0
  double T = 1.0;  // end tension, > 0
};
struct LooseKnotSolution {
  double lambda = 0.0;                 // sqrt(B/T)
  double radius_perpendicular = 0.0;   // R_B = 1/kappa where the tangent is perpendicular to the pull = lambda/sqrt 2
  double apex_radius = 0.0;            // lambda / 2
  double end_shortening = 0.0;         // 4 lambda
  double crossing_arclength = 0.0;     // s_c = u_c lambda: the planar loop crosses itself at s = +-s_c
  double crossing_height = 0.0;        // y(s_c) = 2 lambda sech u_c: the crossing's distance from the tails' line
};
LooseKnotSolution loose_knot(const LooseKnot& knot);

struct LooseKnotPoint {
  double theta = 0.0;       // tangent angle from the pull direction
  double curvature = 0.0;   // kappa = theta'
  double x = 0.0, y = 0.0;  // position: along the pull, and across it (the loop's apex at s = 0)
  double H = 0.0;           // 1/2 B kappa^2 + T cos theta (= T)
};
LooseKnotPoint loose_knot_point(const LooseKnot& knot, double s);

// The root of u = 2 tanh u, u > 0 (TOMS 748): u_c = 1.915008048154537...
double loose_knot_crossing_parameter();

// ---- 2. uniform two-strand ply -----------------------------------------------------------------------
struct UniformPly {
  double B = 1.0;      // bending stiffness of each strand, > 0
  double R = 1.0;      // strand axis to ply axis, > 0
  double theta = 0.3;  // helix angle, 0 < theta < pi/4
  double F = 0.0;      // total axial force carried by the ply (finite)
  double M = 0.0;      // total axial moment carried by the ply (finite)
};
struct UniformPlySolution {
  double curvature = 0.0;        // kappa = sin^2 theta / R
  double torsion = 0.0;          // tau_g = sin theta cos theta / R
  double twisting_moment = 0.0;  // M_t = m.t
  double tension = 0.0;          // n_t = n.t, each strand
  double binormal_force = 0.0;   // n_b = n.b
  double contact_force = 0.0;    // p, per unit strand length, pushing the strands apart
};
UniformPlySolution uniform_ply(const UniformPly& ply);

struct PlectonemeSolution {
  UniformPlySolution ply;      // the uniform ply with F = M = 0
  double tail_tension = 0.0;   // T_ext = (B/R^2) 1/2 sin^4 theta (1 + 2/cos 2 theta)
};
// The ply of a plectoneme (free end loop): F = M = 0; ply.F and ply.M must be 0 (InputError otherwise).
PlectonemeSolution plectoneme(const UniformPly& ply);

}  // namespace rodvv::references
