#pragma once
// Generalised forces of the Super-Helix (ALGORITHMS.md §1.4): the virtual work of point forces at
// the Gauss points and of a wrench at the tip, projected on the generalised coordinates in O(N) by
// a tip-to-root pass that carries the downstream wrench (moment about the next element's base
// point, force):
//   F_iQ = Theta_iQ(ell) . M_{Q+1} + T_iQ(ell) . F_{Q+1} + sum_{g in Q} T_g,i . f_g,
// which equals sum_points (dr_g/dq)^T f_g + (dr_tip/dq)^T F + Theta_tip^T M (the dense form).
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

// point_forces: one force per Gauss point (Kinematics::points() order), or empty for none.
VecX generalised_force(const Kinematics& kinematics, const std::vector<Vec3>& point_forces,
                       const Vec3& tip_force, const Vec3& tip_moment);

// The forces at the Gauss points (points() order): gravity m_g g plus the model's dead point_forces,
// scaled by load_factor; empty when there are none.
std::vector<Vec3> gauss_point_loads(const RodModel& model, const Kinematics& kinematics, double load_factor = 1.0);

// Those and the dead end force and moment, all scaled by load_factor.
VecX external_generalised_force(const RodModel& model, const Kinematics& kinematics,
                                double load_factor = 1.0);

// Elastic energy 1/2 (q - q0)^T K (q - q0) (K = generalised_stiffness).
double elastic_energy(const RodModel& model, const VecX& q);
// Gravity potential -sum_g m_g g . r_g (the Gauss-point quadrature of -int rho S g . r ds).
double gravity_energy(const RodModel& model, const Kinematics& kinematics);

}  // namespace rodvv::solvers::superhelix
