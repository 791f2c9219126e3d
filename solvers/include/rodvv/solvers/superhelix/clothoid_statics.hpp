#pragma once
// Static equilibrium of a super-clothoid rod (ALGORITHMS.md §2 on top of §1.4): nodal strains q in
// R^{3(N+1)} (clothoid_kinematics.hpp), the same RodModel, loads and Newton (newton.hpp) as the
// Super-Helix; only the element and the stiffness differ.
//
// Elastic energy: U = 1/2 int (kappa - kappa0)^T C (kappa - kappa0) ds with C = diag(GJ, EI1, EI2)
// and kappa affine per element, integrated exactly: the element stiffness on (q_Q, q_{Q+1}) is
//   K_Q = ell/6 [[2 C, C], [C, 2 C]]  (linear finite-element mass matrix times C),
// so K is block tridiagonal, SPD. The natural strain kappa0 = model.natural_strain at every node
// (natural_strain_per_element must be empty: InputError otherwise).
// Generalised forces of gravity and the model's dead point forces (Gauss points) and the dead end force
// and moment by the same tip-to-root wrench pass as loads.hpp, with 6 columns per element scattered to its
// two nodes. (Point forces are statics loads: the clothoid dynamics refuse them.)
// Residual r(q) = K (q - q0) - lambda F_ext(q); its Jacobian K - lambda dF_ext/dq exact, O(N^2).
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/newton.hpp"

namespace rodvv::solvers::superhelix {

// validate(model) plus the clothoid restriction above; InputError "self_contact" or "tip_guide" (which the
// clothoid does not take).
void validate_clothoid(const RodModel& model);
// Whether the model loads its Gauss points (gravity or point forces): the kinematics must then have them.
bool clothoid_loads_at_points(const RodModel& model);

VecX clothoid_natural_strain_vector(const RodModel& model);
MatX clothoid_stiffness(const RodModel& model);  // 3(N+1) square, dense storage of the tridiagonal K

// point_forces: one per Gauss point (points() order) or empty.
VecX clothoid_generalised_force(const ClothoidKinematics& kinematics, const std::vector<Vec3>& point_forces,
                                const Vec3& tip_force, const Vec3& tip_moment);
// The loads at the Gauss points (gravity m_g g plus the dead point forces, times load_factor), empty when
// the model has none; InputError "kinematics" if they are non-zero and the kinematics has no points.
std::vector<Vec3> clothoid_point_loads(const RodModel& model, const ClothoidKinematics& kinematics,
                                       double load_factor);
VecX clothoid_external_force(const RodModel& model, const ClothoidKinematics& kinematics, double load_factor = 1.0);

double clothoid_elastic_energy(const RodModel& model, const VecX& q);
double clothoid_gravity_energy(const RodModel& model, const ClothoidKinematics& kinematics);

VecX clothoid_static_residual(const RodModel& model, const VecX& q, double load_factor = 1.0);
// d(residual)/dq = K - lambda D, exact (clothoid_load_stiffness.hpp); the Newton of solve_clothoid_static
// uses it (it used central differences: 2.4 s at N = 32).
MatX clothoid_static_jacobian(const RodModel& model, const VecX& q, double load_factor = 1.0);
StaticResult solve_clothoid_static(const RodModel& model, const StaticOptions& options = {});

}  // namespace rodvv::solvers::superhelix
