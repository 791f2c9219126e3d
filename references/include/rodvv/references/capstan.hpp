#pragma once
// The capstan with bending stiffness: an inextensible, unshearable planar rod (bending stiffness B)
// wrapped around a rigid cylinder (radius R, measured to the rod's centreline) with Coulomb friction
// mu, its two straight tails pulled along directions that turn by the wrap angle phi, the rod sliding
// over the cylinder toward the holding tail. The pulling tail carries the tension T_pull, the holding
// tail T_hold. For a flexible rope (B -> 0) this is Euler's capstan, T_hold = T_pull e^{mu phi}.
//
// With bending, derived from the Noether quantity H = 1/2 B kappa^2 + n.t (PHYSICS.md §1.2; constant on
// each free span, which carries no load) and the equilibrium of the contact region:
//  - on the cylinder kappa = 1/R, so m = B/R is constant, the shear is zero, n = T t, the pressure is
//    p = T/R and sliding friction mu p gives dT/dphi = mu T (T rising toward the holding side);
//  - kappa is continuous at the contact's ends (no point couple), so each free span leaves the cylinder
//    with kappa = 1/R and straightens into its tail: a tension-elastica homoclinic whose H = T_i (its
//    tail's tension) gives n.t = T_i - beta there, beta = B / (2 R^2), i.e. the span's tangent turns by
//    psi_i, cos psi_i = 1 - beta / T_i, and its shear T_i sin psi_i is taken by a point contact force
//    P_i = T_i sin psi_i at the contact's end, with its sliding friction mu P_i;
//  - the contact arc is phi_c = phi - psi_hold - psi_pull, and with the end forces' jumps of n.t
//      T_hold (cos psi_hold - mu sin psi_hold) = e^{mu phi_c} T_pull (cos psi_pull + mu sin psi_pull).
// T_hold is its root (TOMS 748, bracketed_root.hpp; the left side grows with T_hold faster than the
// right). Tails are taken infinitely long (the homoclinic's tails straighten exponentially, on the
// length sqrt(B / T_i)); each tail's line passes at R + B / (2 R T_i) from the axis (the homoclinic
// leaves the cylinder lambda^2 / R off its tail line, lambda^2 = B / T_i, with its normal turned by psi:
// lambda^2 / R + R cos psi). [DERIVED here; mu = 0 gives T_hold = T_pull, B = 0 Euler's capstan.]
// tests/data/make_capstan_table.py computes it independently (mpmath: the homoclinic in closed form,
// the end forces as vector jumps, the contact arc's ODE by odefun).
//
// InputError for B, R, T_pull not finite and > 0, mu not finite and >= 0, phi not finite and > 0; for
// beta >= 2 T_pull ("B": the pulling span cannot reach the cylinder's curvature: the rod does not
// wrap), or for a tension entering the contact on the pulling side, T_pull cos psi_pull + mu P_pull, that
// is not > 0 ("B": the pull cannot hold so stiff a rod on the cylinder); and for a contact arc phi_c <= 0 ("wrap_angle": the free spans alone turn by phi or more).
// The root is searched above the T_hold at which the tension entering the contact on the holding side,
// T_hold (cos psi_hold - mu sin psi_hold), vanishes: there is no sliding equilibrium below it.
namespace rodvv::references {

struct Capstan {
  double B = 1.0;             // bending stiffness, > 0
  double R = 1.0;             // cylinder radius to the rod's centreline, > 0
  double mu = 0.3;            // friction coefficient, >= 0
  double wrap_angle = 3.14;   // phi, the turn between the tails' directions (radians), > 0
  double pull_tension = 1.0;  // T_pull, the tension of the tail that is pulled in (low side), > 0
};

struct CapstanSolution {
  double hold_tension = 0.0;    // T_hold, the tension of the holding tail
  double contact_angle = 0.0;   // phi_c
  double hold_turn = 0.0;       // psi_hold: the holding span's turn from the cylinder to its tail
  double pull_turn = 0.0;       // psi_pull
  double hold_end_force = 0.0;  // P_hold = T_hold sin psi_hold: the point contact force where it leaves
  double pull_end_force = 0.0;  // P_pull
  double hold_offset = 0.0;     // the holding tail's line passes at R + hold_offset from the axis
  double pull_offset = 0.0;
};

CapstanSolution capstan_with_bending(const Capstan& capstan);

}  // namespace rodvv::references
