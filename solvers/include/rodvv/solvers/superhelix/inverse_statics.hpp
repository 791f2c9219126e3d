#pragma once
// Inverse statics of a Super-Helix without contact (ALGORITHMS.md §3.1; Derouet-Jourdan,
// Bertails-Descoubes & Thollot, "Stable inverse dynamic curves", SIGGRAPH Asia 2010): given a
// configuration q, the natural strains that make q an equilibrium under the model's loads (gravity,
// dead end force and moment),
//
//   K (q - q0) = F_ext(q)   =>   q0 = q - K^-1 F_ext(q),
//
// one O(N) evaluation of F_ext; it exists and is unique for any q.
//
// Stability. The Hessian of the potential, K - D (D = dF_ext/dq, load_stiffness.hpp, exact), does
// not depend on q0. Scale the stiffnesses (GJ, EI1, EI2 together, their ratios kept) by alpha and
// recompute q0 for the same q: the Hessian is alpha K - D, positive definite iff
//   alpha > alpha_c = lambda_max(K^-1/2 sym(D) K^-1/2)   (the generalised eigenvalue of (D, K)),
// alpha_c = 0 when D is negative semidefinite (q is then stable at any stiffness). The stability
// eigenvalue of stability.hpp at alpha = 1 is 1 - alpha_c. A dead end moment makes D unsymmetric
// (Ziegler): q0 is still defined (natural_strain_for), stability is not (InputError "end_moment", as
// stability_eigenvalue, asymmetry above 1e-7 relative).
//
// stable_rest_model: the model with stiffnesses scaled by max(1, (1 + margin) alpha_c) and the q0
// that holds q there: the least stiffening that makes q a stable equilibrium with a relative
// margin (the 2010 paper raises EI above the threshold the same way). margin in (0, 10).
// Bad input: as validate(model), q of size 3N and finite (InputError "q"); margin out of range.
#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct InverseStatics {
  VecX natural_strain;                    // q0, 3N values (element Q: segment 3Q)
  double critical_stiffness_factor = 0;   // alpha_c
  double stability_eigenvalue = 0;        // smallest eigenvalue of K^-1/2 (K - sym D) K^-1/2 = 1 - lambda_max
  double residual = 0;  // |K (q - q0) - F|_inf / max(|K q|_inf, |F|_inf, max K / L) after rounding: O(eps)
};

VecX natural_strain_for(const RodModel& model, const VecX& q);
InverseStatics inverse_statics(const RodModel& model, const VecX& q);

// The model with natural_strain_per_element = q0 (natural_strain unchanged but unused) and the
// stiffnesses multiplied by stiffness_factor (> 0): q is its equilibrium.
RodModel model_at_rest_in(const RodModel& model, const VecX& q, double stiffness_factor = 1.0);
RodModel stable_rest_model(const RodModel& model, const VecX& q, double margin = 0.1);

}  // namespace rodvv::solvers::superhelix
