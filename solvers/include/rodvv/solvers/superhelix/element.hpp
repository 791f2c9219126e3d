#pragma once
// Closed form of one Super-Helix element in its own base frame (ALGORITHMS.md §1.2-1.3), in the
// singularity-free form: with X = [q]x, x = sigma |q|,
//
//   E(sigma) = exp(sigma X)          = I + sigma s0(x) X + sigma^2 f1(x) X^2           (frame)
//   G(sigma) = int_0^sigma exp(u X) du = sigma I + sigma^2 f1(x) X + sigma^3 f2(x) X^2
//
//   s0 = sin x / x,  f1 = (1 - cos x)/x^2,  f2 = (x - sin x)/x^3,
//
// so that on element Q with base frame R_Q and base point p_Q:
//   R(sigma) = R_Q E(sigma),   r(sigma) = p_Q + R_Q G(sigma) e0,
//   Theta_iQ(sigma) = R_Q G(sigma) e_i   (rotation per unit q_i, §1.3),
//   T_iQ(sigma) = dr/dq_iQ = R_Q (dG/dq_i)(sigma) e0, with
//   dG/dq_i = sigma^4 g1 q_i X + sigma^2 f1 [e_i]x + sigma^5 g2 q_i X^2 + sigma^3 f2 ([e_i]x X + X [e_i]x),
//   g1 = f1'(x)/x, g2 = f2'(x)/x  (d x / d q_i = sigma^2 q_i / x).
// All five coefficients are even entire functions of x, evaluated from x^2: by their Taylor series
// below x^2 = 1 (10 terms: truncation below 1/22! ~ 1e-21) and by the trigonometric formulas above
// (where their cancellation error is at most ~eps / x^2 <= eps). A straight element (q = 0) is
// therefore exact: E = I, G = sigma I.
#include <Eigen/Geometry>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::superhelix {

struct HelixCoefficients {
  double s0 = 1.0, f1 = 0.5, f2 = 1.0 / 6.0, g1 = -1.0 / 12.0, g2 = -1.0 / 60.0;
};

HelixCoefficients helix_coefficients(double x_squared);

struct ElementMaps {
  Mat3 E;    // exp(sigma [q]x)
  Mat3 G;    // int_0^sigma exp(u [q]x) du
  Mat3 dG0;  // column i = (dG/dq_i) e0, the local position Jacobian
};

ElementMaps element_maps(const Vec3& q, double sigma);

// What a mass point needs (no frame): the local offset G(sigma) e0 and dG0 (a cheaper subset).
struct PointMaps {
  Vec3 Ge0;
  Mat3 dG0;
};
PointMaps element_point_maps(const Vec3& q, double sigma);

// Rates along a coordinate velocity (q(t) = q + t qdot, qddot = 0), for the velocity terms of the
// dynamics (ALGORITHMS.md §1.4: zeta = Jdot qdot), in the element's base frame, in closed form:
//   velocity = dG0 qdot = dc/dt with c = G(sigma) e0,
//   bias     = d/dt (dG0) qdot = d2c/dt2, the second directional derivative of c along qdot,
//   angular_velocity = G(sigma) qdot (the frame's rate relative to the base, dR/dt = [.]x R),
//   angular_bias     = d/dt (G) qdot,
// by differentiating the formulas above along qdot: d(x^2)/dt = 2 sigma^2 q.qdot, df1/d(x^2) = g1/2,
// df2/d(x^2) = g2/2, and dg1/d(x^2), dg2/d(x^2) from helix_coefficient_rates. Exact (no step size),
// checked against a central difference in the tests.
struct HelixCoefficientRates {
  double dg1 = 1.0 / 180.0, dg2 = 1.0 / 1260.0;  // d g1 / d(x^2), d g2 / d(x^2)
};
HelixCoefficientRates helix_coefficient_rates(double x_squared);

struct ElementRates {
  Vec3 offset;    // c = G(sigma) e0
  Mat3 jacobian;  // dG0 (column i = dc/dq_i)
  Vec3 velocity;  // dG0 qdot
  Vec3 bias;      // d/dt(dG0) qdot
};
ElementRates element_point_rates(const Vec3& q, const Vec3& qdot, double sigma);

struct ElementEndRates {
  ElementRates point;
  Mat3 E;  // exp(sigma [q]x)
  Mat3 G;  // int_0^sigma exp(u [q]x) du
  Vec3 angular_velocity;  // G qdot
  Vec3 angular_bias;      // d/dt(G) qdot
};
ElementEndRates element_end_rates(const Vec3& q, const Vec3& qdot, double sigma);

// Second derivatives, for the load stiffness dF/dq of the statics (load_stiffness.hpp) and the
// Hessian of the potential (inverse_statics.hpp, stability.hpp), in the element's base frame:
//   frame_rate[j]       = dG/dq_j (column i = d(G e_i)/dq_j: the rate of the rotation Jacobian
//                          Theta_i = G e_i, §1.3), from the dG/dq_j formula above;
//   offset_hessian[j]   : column k = d2(G e0)/dq_j dq_k (symmetric in j, k), by differentiating the
//                          dG/dq_j e0 formula once more with d(x^2)/dq_k = 2 sigma^2 q_k,
//                          df1/dq_k = sigma^2 g1 q_k, df2/dq_k = sigma^2 g2 q_k,
//                          dg1/dq_k = 2 sigma^2 dg1 q_k, dg2/dq_k = 2 sigma^2 dg2 q_k (dg from
//                          helix_coefficient_rates).
// Exact (no step size); tests/solvers/test_superhelix_load_stiffness.cpp checks both against
// central differences of element_maps and against the directional second derivative
// (element_point_rates().bias = qdot^T offset_hessian qdot).
struct ElementSecondDerivatives {
  Mat3 frame_rate[3];
  Mat3 offset_hessian[3];
};
ElementSecondDerivatives element_second_derivatives(const Vec3& q, double sigma);

inline Mat3 skew(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

}  // namespace rodvv::solvers::superhelix
