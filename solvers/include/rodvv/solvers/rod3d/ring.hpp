#pragma once
// A closed discrete elastic rod: the twisted ring of Michell's instability (Michell 1889/90;
// Goriely 2006, J. Elasticity 84:281; PHYSICS.md §7.2; Bergou et al. 2008 showed it on DER).
//
// N vertices x_0 .. x_{N-1} and N edges e^j = x_{j+1} - x_j (indices mod N), one material angle per
// edge, inextensible edges (|e^j| = ebar = L/N, multipliers = edge tensions), and a bending-twisting
// stencil at every vertex (discrete_energy.cpp's stencil, indices wrapping). The total twist angle
// Phi enters through the closure of the material angles: the twist at the vertex joining edge N-1 to
// edge 0 is theta^0 + Phi - theta^{N-1} + its reference twist (a ring's material angle is
// multivalued, theta^{j+N} = theta^j + Phi: Phi is the link parameter of Goriely's analysis, a real
// number here).
//
// The equilibrium checked is the twisted circle: the regular N-gon of perimeter L in a given plane,
// reference directors = the plane's normal (parallel transport round a planar polygon has no
// holonomy), reference twists 0, uniform twist theta^j = j Phi / N, and the tension found by least
// squares from the force balance (by symmetry the polygon is an exact discrete equilibrium; the
// residual is reported).
//
// Stability: the smallest eigenvalue of the Hessian of the Lagrangian (energy + sum lambda_j c_j) on
// the null space of the constraint Jacobian, after the exact zero modes of a free ring are projected
// out explicitly - three translations (dx_i = a), three rotations (dx_i = w x (x_i - c),
// dtheta^j = w . t^j: the material frame turns with w, and the parallel-transported reference frame
// has no twist component) and, for isotropic bending (EI1 = EI2), the uniform spin dtheta^j = 1 -
// rather than by counting small eigenvalues, since the Michell mode itself passes through zero. The
// Euclidean metric is used: by Sylvester's law the sign of the smallest eigenvalue does not depend on
// it. Dense, O(N^3): N <= kMaxRingElements.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::rod3d {

inline constexpr std::size_t kMaxRingElements = 512;

struct TwistedRing {
  std::size_t elements = 32;       // N, 3 .. kMaxRingElements
  double length = 1.0;             // L > 0
  Vec3 stiffness = Vec3::Ones();   // (GJ, EI1, EI2) > 0
  double twist = 0.0;              // total twist angle Phi (finite)
  Vec3 center = Vec3::Zero();
  Mat3 frame = Mat3::Identity();   // a rotation: columns 0 and 1 span the ring's plane, column 2 its normal
};

void validate(const TwistedRing& ring);

// The twisted polygon and its linearisation (dof order: x_i (3), theta^i, for i = 0 .. N-1).
struct RingLinearization {
  std::vector<Vec3> position;
  std::vector<double> angle;
  double tension = 0.0;   // lambda (the same on every edge)
  double residual = 0.0;  // max |dE/dz + C^T lambda| / max(|dE/dz|, EI/L^2): round-off at the polygon
  VecX gradient;          // dE/dz (4N)
  MatX hessian;           // Hessian of the Lagrangian (4N x 4N)
  MatX constraints;       // C = dc/dz (N x 4N)
  MatX zero_modes;        // 4N x 7 (4N x 6 for EI1 != EI2): translations, rotations, spin
};
RingLinearization linearize_ring(const TwistedRing& ring);

// The smallest eigenvalue of the constrained Hessian without the zero modes (see above): > 0 stable,
// < 0 unstable. InputError ("stiffness") unless EI1 = EI2: with an anisotropic section the circle is
// not the ring's only equilibrium family, and the spin is not a zero mode.
double ring_stability_eigenvalue(const TwistedRing& ring);

}  // namespace rodvv::solvers::rod3d
