#pragma once
// The dense path's linear system of one semi-implicit Euler step of the Super-Helix (dynamics.hpp):
//   (M_n + D) dv = rhs,  D = (h^2 + h gamma) K,  rhs = h (-K (q_n - q0) + B_n) - D qdot_n,
// assembled but not solved, for the steps that add constraints to it (contact_dynamics.hpp: the
// velocity-level contact QP has this matrix as its metric and -rhs as its linear term).
#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/root_motion.hpp"

namespace rodvv::solvers::superhelix::detail {

// InputError for what no step accepts: the model (validate), statics-only loads, h <= 0 or not finite,
// a state of the wrong size or not finite.
void check_step_input(const RodModel& model, const DynamicState& state, double h);

struct DenseStepSystem {
  MatX matrix;  // M_n + D, symmetric (positive definite when M_n is, or when gamma, h > 0 and K > 0)
  VecX rhs;
};

// `root` is the root's pose and motion at state.time (RootMotion::state_at); the caller has checked
// the state and h.
DenseStepSystem dense_step_system(const RodModel& model, const DynamicState& state, double h, const RootState& root);

}  // namespace rodvv::solvers::superhelix::detail
