#pragma once
// The planar Noether (Maddocks) invariant of an elastic rod (PHYSICS.md §0, §1.2-1.4):
//
//   H(s) = 1/2 EI (kappa^2 - kappa_hat^2) + n.t - V(r(s))
//
// H is constant along every equilibrium whose Lagrangian has no explicit s dependence (uniform EI,
// constant natural curvature, potential V(r) only), also through frictionless contact (§1.2).
// When EI(s) or kappa_hat(s) depend on s, dH/ds = -dL/ds with L = 1/2 EI (theta' - kappa_hat)^2 + ...:
//
//   dH/ds = -1/2 EI'(s) (theta' - kappa_hat)^2 + EI(s) kappa_hat'(s) (theta' - kappa_hat)      (*)
//
// which reduces to PHYSICS.md §1.3 (a) -1/2 EI' theta'^2 for a naturally straight tapered rod and
// to §1.3 (b) +EI kappa_hat' (theta' - kappa_hat) for a uniform curved rod. (The slides' signs,
// +1/2 EI' theta'^2 and -EI kappa_hat' (...), are wrong; the drift check below detects them.)
// Note: with BOTH EI' != 0 and kappa_hat != 0 the first term is -1/2 EI' (theta' - kappa_hat)^2,
// not -1/2 EI' theta'^2 (derivation in planar_noether.cpp).
//
// Extensible, shearable (planar Reissner) rod, solution.axial_stiffness EA and/or
// solution.shear_stiffness GA finite (PHYSICS.md §1.1 compact form H = n.v + m.u - W - V, planar):
// with r' = (1 + eps) t + gamma N, n.t = EA eps, n.N = GA gamma, m = EI (theta' - kappa_hat),
// W = 1/2 EI (theta' - kappa_hat)^2 + 1/2 EA eps^2 + 1/2 GA gamma^2,
//   H = n.r' + m theta' - W - V = 1/2 EI (kappa^2 - kappa_hat^2) + n.t + (n.t)^2 / (2 EA)
//       + (n.N)^2 / (2 GA) - V                                                           (R)
// (n.r' = n.t + EA eps^2 + GA gamma^2). Here t is the cross-section director, so n.t is the
// "tension" n.d3 of §1.1, not the force along r'. The functions below use (R) whenever EA or GA is
// finite (the extra terms vanish for the elastica, whose results are unchanged), and (*) still
// gives dH/ds because EA, GA are constant.
//
// All functions are pure functions of a PlanarRodSolution (rodvv/common/planar_rod.hpp). They read
// s, kappa (= theta'), bending_stiffness, natural_curvature, axial_force (n.t) and potential; every
// one of these arrays must hold nodes() values; with a finite shear_stiffness also shear_force (n.N).
// x, y, theta, force_x/y and the edge arrays are not read. Bad input throws rodvv::InputError naming
// the field:
//   fewer than 2 nodes ("solution.s"), an array of a different length ("solution.<field>"),
//   a non-finite value ("solution.<field>"), s not strictly increasing ("solution.s"),
//   EI <= 0 ("solution.bending_stiffness"), EA or GA not in (0, +inf] ("solution.axial_stiffness",
//   "solution.shear_stiffness").
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "rodvv/common/planar_rod.hpp"

namespace rodvv::invariants {

// H at one node. The difference of squares is formed as (kappa - kappa_hat)(kappa + kappa_hat),
// which has no cancellation when kappa ~ kappa_hat. Templated on the scalar so that a test can
// evaluate it in long double.
template <class Scalar>
Scalar planar_noether_density(Scalar bending_stiffness, Scalar kappa, Scalar natural_curvature,
                              Scalar axial_force, Scalar potential) {
  return Scalar(0.5) * bending_stiffness * ((kappa - natural_curvature) * (kappa + natural_curvature)) +
         axial_force - potential;
}

// H at one node of an extensible, shearable rod, formula (R) above; axial_compliance = 1/EA and
// shear_compliance = 1/GA (0 = rigid) give back planar_noether_density exactly.
template <class Scalar>
Scalar planar_reissner_density(Scalar bending_stiffness, Scalar kappa, Scalar natural_curvature,
                               Scalar axial_force, Scalar shear_force, Scalar axial_compliance,
                               Scalar shear_compliance, Scalar potential) {
  return planar_noether_density(bending_stiffness, kappa, natural_curvature, axial_force, potential) +
         Scalar(0.5) * (axial_compliance * axial_force * axial_force +
                        shear_compliance * shear_force * shear_force);
}

// dH/ds at one node, formula (*) above: -1/2 EI' (kappa - kappa_hat)^2 + EI kappa_hat' (kappa - kappa_hat).
template <class Scalar>
Scalar planar_noether_drift_density(Scalar bending_stiffness, Scalar bending_stiffness_derivative,
                                    Scalar kappa, Scalar natural_curvature,
                                    Scalar natural_curvature_derivative) {
  const Scalar strain = kappa - natural_curvature;
  return -Scalar(0.5) * bending_stiffness_derivative * strain * strain +
         bending_stiffness * natural_curvature_derivative * strain;
}

// H_i at every node i.
std::vector<double> planar_noether_h(const PlanarRodSolution& solution);

struct HSpread {
  double spread = 0.0;             // max_i |H_i - mean| / scale
  double max_abs_deviation = 0.0;  // max_i |H_i - mean| (unscaled)
  std::size_t worst_index = 0;     // the i attaining max_abs_deviation (first one on ties)
  double mean = 0.0;               // mean of H_i over the nodes (compensated sum)
  double at_start = 0.0;           // H(0) = H_0
  double at_end = 0.0;             // H(L) = H_N
  double scale = 1.0;              // the scale used (given, or natural, or the fallback 1)
  bool scale_is_fallback = false;  // true: natural scale was 0 (a rod with no load or bending), 1 used
};

// Natural scale of H: max_i ( 1/2 EI_i (kappa_i^2 + kappa_hat_i^2) + |n.t_i| + |V_i| ) (plus
// (n.t_i)^2 / (2 EA) + (n.N_i)^2 / (2 GA) for an extensible, shearable rod), the sum of
// the magnitudes of the terms of H, so that round-off in H is a few eps times it. (For a naturally
// straight rod this is max_i |1/2 EI kappa^2| + |n.t| + |V|.) Returns 0 for a load- and bending-free rod.
double planar_noether_natural_scale(const PlanarRodSolution& solution);

// scale: if given, must be finite and > 0 (InputError "scale"); if absent the natural scale above
// is used, or 1 when that is 0 (scale_is_fallback = true).
HSpread planar_noether_spread(const PlanarRodSolution& solution,
                              std::optional<double> scale = std::nullopt);

// Derivatives of the s-dependent coefficients, as callables of s or sampled on the nodes.
// An empty callable / empty array means "identically zero" (e.g. no natural curvature change).
using ScalarFunction = std::function<double(double)>;

// predicted_i = integral_0^{s_i} dH/ds ds with dH/ds from (*), kappa = theta' and kappa_hat, EI
// taken from the solution, integrated with the composite trapezoidal rule on the solution's nodes:
// the quadrature error is O(h^2) (at most s_i h_max^2 / 12 max |d^2/ds^2 (dH/ds)|).
// predicted_0 = 0. A sampled array must hold nodes() values (InputError naming it otherwise, and
// for non-finite entries); a callable must return finite values.
std::vector<double> planar_noether_predicted_drift(const PlanarRodSolution& solution,
                                                   const ScalarFunction& bending_stiffness_derivative,
                                                   const ScalarFunction& natural_curvature_derivative);
std::vector<double> planar_noether_predicted_drift(const PlanarRodSolution& solution,
                                                   std::span<const double> bending_stiffness_derivative,
                                                   std::span<const double> natural_curvature_derivative);

struct HDriftCheck {
  double max_abs_residual = 0.0;   // max_i |(H_i - H_0) - predicted_i|
  std::size_t worst_index = 0;     // the i attaining it
  double max_abs_drift = 0.0;      // max_i |H_i - H_0|: how much H actually moves
  double max_abs_predicted = 0.0;  // max_i |predicted_i|
  // max_abs_residual / max_abs_drift: << 1 when the prediction explains the drift. When H does not
  // move at all (max_abs_drift == 0) it is 0 if the residual is 0 too, +infinity otherwise.
  double relative_residual = 0.0;
  double scale = 1.0;                // natural scale of H (planar_noether_natural_scale, or 1 if 0)
  double residual_over_scale = 0.0;  // max_abs_residual / scale
};

HDriftCheck planar_noether_drift_check(const PlanarRodSolution& solution,
                                       const ScalarFunction& bending_stiffness_derivative,
                                       const ScalarFunction& natural_curvature_derivative);
HDriftCheck planar_noether_drift_check(const PlanarRodSolution& solution,
                                       std::span<const double> bending_stiffness_derivative,
                                       std::span<const double> natural_curvature_derivative);

}  // namespace rodvv::invariants
