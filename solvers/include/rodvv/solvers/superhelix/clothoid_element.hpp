#pragma once
// Super-clothoid element kinematics (ALGORITHMS.md §2; Casati & Bertails-Descoubes 2013): material
// strains affine in the arc length on the element, kappa(sigma) = a + sigma b (components
// (twist, kappa1, kappa2)), so R' = R [a + sigma b]x, r' = R e0 has no closed form. It is
// integrated by the power series (entire, since the coefficients are polynomial)
//
//   R(sigma) = sum_k A_k sigma^k,  A_0 = I,  A_{-1} = 0,  (k+1) A_{k+1} = A_k [a]x + A_{k-1} [b]x,
//   r(sigma) = sum_k (A_k e0) sigma^(k+1) / (k+1),
//
// truncated adaptively when |A_k| h^k (and the next term) fall below `tolerance` (relative to
// |R| = 1), on sub-intervals of length h short enough that (|a| + |b| ell) h <= 2 (so that ~20-40
// terms suffice and no cancellation occurs); (R, r) are composed across sub-intervals, each
// starting from the strain a + sigma0 b at its own origin. With b = 0 it reduces to the
// Super-Helix closed form (element.hpp). Local frame: the element starts at the origin with R = I.
// Bad input: non-finite strains, ell <= 0 or non-finite, tolerance outside (0, 1e-6] -> InputError.
#include <cstddef>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::superhelix {

struct ClothoidPose {
  Mat3 R;                   // frame at sigma = ell
  Vec3 r;                   // position at sigma = ell
  std::size_t pieces = 0;   // sub-intervals used
  std::size_t max_terms = 0;  // largest number of series terms in one sub-interval
};

ClothoidPose clothoid_element(const Vec3& a, const Vec3& b, double ell, double tolerance = 1e-17);

// The pose at sigma = ell and its derivatives with respect to p = (a_0, a_1, a_2, b_0, b_1, b_2),
// in the element's own base frame: rotation.col(p) = Theta_p with dR/dp = [Theta_p]x R (§1.3),
// translation.col(p) = dr/dp. Forward-mode differentiation of the series recurrence (six derivative
// matrices per term, same subdivision), exact to round-off.
// clothoid_element_jacobian_complex_step computes the same by complex-step differentiation of the
// series itself (f'(p) = Im f(p + i t) / t, no cancellation, so t = 1e-30 and exact to round-off):
// an independent path that shares no derivative code, kept as the check of the forward mode (it is
// ~5x slower: complex arithmetic, seven series). Same InputError as clothoid_element.
struct ClothoidJacobian {
  Mat3 R;
  Vec3 r;
  Eigen::Matrix<double, 3, 6> rotation;
  Eigen::Matrix<double, 3, 6> translation;
};

ClothoidJacobian clothoid_element_jacobian(const Vec3& a, const Vec3& b, double ell, double tolerance = 1e-17);
ClothoidJacobian clothoid_element_jacobian_complex_step(const Vec3& a, const Vec3& b, double ell,
                                                        double tolerance = 1e-17);

// First and second derivatives of the pose at sigma = ell with respect to p = (a, b), for the exact
// load stiffness of the statics (clothoid_load_stiffness.hpp), in the element's base frame:
//   R, r, rotation, translation: as ClothoidJacobian (the base);
//   rotation_rate[q].col(p)       = dTheta_p / dp_q (Theta_p = axial(dR/dp_p R^T));
//   translation_hessian[q].col(p) = d2r / dp_p dp_q (symmetric in p, q).
// Forward-mode differentiation of the series recurrence (dA_{k+1}/dp and d2A_{k+1}/dp dq from
// (k+1) A_{k+1} = A_k [a]x + A_{k-1} [b]x, 27 matrices per term, same subdivision, the product
// rule across sub-intervals), so exact to round-off and sharing no code with the complex step.
// Same InputError as clothoid_element.
struct ClothoidSecondDerivatives : ClothoidJacobian {
  Eigen::Matrix<double, 3, 6> rotation_rate[6];
  Eigen::Matrix<double, 3, 6> translation_hessian[6];
};

ClothoidSecondDerivatives clothoid_element_second_derivatives(const Vec3& a, const Vec3& b, double ell,
                                                              double tolerance = 1e-17);

// Rates along strain velocities (a(t) = a + t adot, b(t) = b + t bdot), for the velocity terms of
// the dynamics, in the element's base frame at sigma = ell: dR/dt = [angular_velocity]x R,
// velocity = dr/dt, angular_bias = d(angular_velocity)/dt and bias = d2r/dt2 (at constant adot,
// bdot). The series recurrence carried to second order in t (three 3 x 3 matrices per term, same
// subdivision), so the rates are exact to round-off. Same InputError as clothoid_element, plus
// "adot" / "bdot" non-finite.
struct ClothoidRates {
  Mat3 R;
  Vec3 r;
  Vec3 angular_velocity, velocity;
  Vec3 angular_bias, bias;
};

ClothoidRates clothoid_element_rates(const Vec3& a, const Vec3& b, const Vec3& adot, const Vec3& bdot, double ell,
                                     double tolerance = 1e-17);

}  // namespace rodvv::solvers::superhelix
