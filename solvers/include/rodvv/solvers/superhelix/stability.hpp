#pragma once
// Linear stability of a Super-Helix equilibrium (statics.hpp): the smallest eigenvalue of the
// symmetric part of the static Jacobian J = dr/dq = K - dF_ext/dq, made dimensionless by the
// generalised stiffness, K^-1/2 J K^-1/2 (K = diag(GJ, EI1, EI2) ell per element). > 0: stable,
// < 0: unstable; it crosses zero at a bifurcation (buckling). By Sylvester's law of inertia the
// scaling does not change its sign; it makes the eigenvalue O(1) whatever the stiffnesses.
//
// J is the exact Jacobian of statics.hpp (load_stiffness.hpp), symmetric to round-off for
// conservative loads (gravity, a dead end force). A dead end moment is not conservative (Ziegler)
// and its load stiffness is unsymmetric: if the relative asymmetry max |J - J^T| / max |J| exceeds
// symmetry_tolerance (1e-7, kept from the central-difference Jacobian this replaced, whose noise was
// ~1e-11), InputError ("end_moment"): a non-self-adjoint problem has no such criterion.
// The state must be an equilibrium: the scaled residual max |r| / max(|K (q - q0)|, |F|, |K q|) must be
// below equilibrium_tolerance (InputError "q" otherwise; |K q| because a rest shape recovered by the
// inverse statics holds q only to eps |K q|). Dense, O(N^3).
#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct StabilityOptions {
  double symmetry_tolerance = 1e-7;
  double equilibrium_tolerance = 1e-8;
};

double stability_eigenvalue(const RodModel& model, const VecX& q, const StabilityOptions& options = {});

}  // namespace rodvv::solvers::superhelix
