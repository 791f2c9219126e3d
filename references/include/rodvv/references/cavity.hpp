#pragma once
// Euler buckling of a pinned-pinned elastica between two frictionless rigid walls y = +/- a, under
// end-shortening control (PHYSICS.md §4.1; Domokos, Holmes & Royce 1997, J. Nonlinear Sci.
// 7:281-314; Holmes, Domokos, Schmitt & Szeberenyi 1999, CMAME 170:175-207). Pins at (0, 0) and
// (L - d, 0); the column bows towards +y and only the wall y = +a is touched.
//
// Regimes, as the shortening d grows:
//   Free          the first mode of PHYSICS.md §3.2 while y_max = L k / K(k) < a;
//   PointContact  one contact at midspan: each half is an inflexional elastica carrying the tilted
//                 force n = -F (cos psi, +/- sin psi), EI phi'' = -F sin phi with phi = theta - psi;
//                 the pin is a turning point phi = phi0, the contact is theta = 0, y = a. With
//                 k = sin(phi0/2), sn(v) = sin(psi/2)/k, lambda L/2 = K + v:
//                   x_c = xi cos psi - eta sin psi, y_c = xi sin psi + eta cos psi,
//                   xi = (2(E + E(am v)) - (K + v)) / lambda, eta = 2 k cn(v) / lambda,
//                 F = EI lambda^2, P = F cos psi, wall force 2 F sin psi, |kappa_c| = 2 k lambda cn v,
//                 H = -F cos phi0 (= 1/2 EI kappa_c^2 - P);
//   LineContact   a flat segment of length l on the wall; each free side (length L' = (L - l)/2) is
//                 an inflection-to-inflection half wave with phi0 = psi:
//                   sin phi0 (2E/K - 1) = a / L',  F = EI (2K/L')^2,  P = F cos phi0,
//                 edge forces Q = F sin phi0 at the two ends of the flat segment, H = -P.
// Units: any consistent set; forces in EI/L^2 when L = EI = 1.
// Errors: InputError for L, EI, a not finite and > 0 ("L", "EI", "wall_gap"), for a shortening
// outside (0, d(l = 0.6 L)) ("shortening") or psi / flat_length out of range; SolverError if a
// root solve fails.
namespace rodvv::references {

struct CavityColumn {
  double L = 1.0;
  double EI = 1.0;
  double gap = 0.1;  // walls at y = +/- gap
};

enum class CavityRegime { Free, PointContact, LineContact };

struct CavityState {
  CavityRegime regime = CavityRegime::Free;
  double shortening = 0.0;     // L - chord
  double P = 0.0;              // compressive axial end load, n_x = -P
  double H = 0.0;              // Noether invariant 1/2 EI kappa^2 + n.t (constant along s)
  double wall_force = 0.0;     // total force of the wall on the rod (2 F sin psi)
  double edge_force = 0.0;     // LineContact: force at each end of the flat segment (Q); else 0
  double kappa_mid = 0.0;      // |kappa| at midspan (Free: kappa_M; PointContact: kappa_c; Line: 0)
  double flat_length = 0.0;    // LineContact: l; else 0
  double psi = 0.0;            // tilt of the force in each half [rad]
  double phi0 = 0.0;           // turning angle phi(0) = theta(0) - psi [rad]
  double theta0 = 0.0;         // end rotation theta(0) = phi0 + psi [rad]
};

// Contact starts (y_max = a) and the point contact becomes a line contact (kappa_c = 0).
double cavity_touch_shortening(const CavityColumn& column);
double cavity_transition_shortening(const CavityColumn& column);
// The end of the line branch: flat length min(0.6 L, the longest whose side waves still reach the
// walls, to 0.999 of the tallest inflexional half wave). The branches exist for wall_gap up to
// 0.321 L (beyond it the point contact never flattens; cavity_point_contact refuses it).
double cavity_max_shortening(const CavityColumn& column);
double cavity_max_flat_length(const CavityColumn& column);

// The point-contact branch parametrised by the tilt psi in [0, psi_transition].
CavityState cavity_point_contact(const CavityColumn& column, double psi);
// The line-contact branch parametrised by the flat length l in [0, min(0.6 L, reachable)].
CavityState cavity_line_contact(const CavityColumn& column, double flat_length);
// The equilibrium at an imposed shortening d in (0, cavity_max_shortening].
CavityState cavity_from_shortening(const CavityColumn& column, double shortening);

}  // namespace rodvv::references
