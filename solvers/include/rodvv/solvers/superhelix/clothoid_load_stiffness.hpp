#pragma once
// The load stiffness of a super-clothoid, D = dF_ext/dq, exactly (no step size) and in O(N^2): the
// Super-Helix's construction (load_stiffness.hpp) with six columns per element. With the elements'
// nodal strains taken as independent, x_Q = (q_Q, q_{Q+1}) in R^6, element Q's kinematics depends on
// x_Q alone, so dF_x/dx has exactly the Super-Helix's block structure (6 x 6 blocks: an element's own
// second derivatives on the diagonal, one product of its end Jacobians with the downstream suffix
// sums W off it), and the nodal Jacobian is S^T (dF_x/dx) S with S the scatter of nodes to elements:
// each 6 x 6 block is added at rows (Q, Q + 1) and columns (Q', Q' + 1).
// The element's second derivatives come from clothoid_element_second_derivatives (forward-mode
// series) by the chain rule of a = q_Q, b = (q_{Q+1} - q_Q) / ell, linear, applied on both sides.
// Symmetric for gravity and dead forces (conservative); a dead end moment adds the Ziegler part.
// tests/solvers/test_superhelix_clothoid_load_stiffness.cpp checks D against central differences
// of clothoid_generalised_force, and the element's derivatives against the complex step.
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

// point_forces: one per Gauss point (points() order) or empty; 3(N+1) square. InputError
// "point_forces" on a count other than the Gauss points'.
MatX clothoid_generalised_force_jacobian(const ClothoidKinematics& kinematics, const std::vector<Vec3>& point_forces,
                                         const Vec3& tip_force, const Vec3& tip_moment);

// Gravity, the dead point forces and the dead end force and moment of the model, scaled by load_factor
// (the loads of clothoid_external_force).
MatX clothoid_load_stiffness(const RodModel& model, const ClothoidKinematics& kinematics, double load_factor = 1.0);

}  // namespace rodvv::solvers::superhelix
