#pragma once
// Energy, static residual and its Jacobian of the discrete elastic rod (model.hpp, ALGORITHMS.md §5).
//
// Derivatives are exact: the bending-twisting energy of each interior vertex is a function of the 11
// degrees of freedom of its stencil (x_{i-1}, theta^{i-1}, x_i, theta^i, x_{i+1}), with the reference
// directors parallel-transported from the state's tangents to the trial tangents and the reference
// twist continued from the state's value, and it is differentiated twice by forward-mode automatic
// differentiation (a second-order jet type, solvers/rod3d/taylor2.hpp, applied to the integrated
// strains k(e, f, theta) in 8 variables and mapped to the 11 dofs; the energy's gradient and Hessian
// follow from k's Jacobian and Hessians): no finite differences, no approximation of the
// reference-frame terms (at the state itself the gradient is the DER gradient of ALGORITHMS.md §5,
// holonomy term included). Stretching, the inextensibility constraints |e^j| - ebar = 0 and the loads
// are differentiated by hand. The Jacobian is banded (one vertex stencil spans 11 consecutive degrees
// of freedom, DofLayout), so a Newton step costs O(N).
//
// Residual r (DofLayout order): position and angle rows dE/dz + sum_j lambda_j dc_j/dz - Q(z), with
// Q the generalised loads (gravity, tip force, tip moment) times the load factor; multiplier rows c_j.
// E includes the self-contact barrier (not scaled by the load factor); its Hessian couples vertices
// far apart along the rod, so with self-contact the Jacobian is sparse but not banded.
// At an equilibrium r = 0 and lambda_j is the tension n.t of edge j.
#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::solvers::rod3d {

struct EnergyParts {
  double bending = 0.0;    // 1/2 sum (1/lbar) (EI1 (k1 - lbar uh1)^2 + EI2 (k2 - lbar uh2)^2)
  double twisting = 0.0;   // 1/2 sum (1/lbar) GJ (m - lbar uh0)^2
  double stretching = 0.0; // 0 for an inextensible rod
  double gravity = 0.0;    // - sum m_i g.x_i
  double tip_force = 0.0;  // - F.x_N
  double vertex_forces = 0.0;  // - sum f_i.x_i (the model's vertex_forces; edge moments have no potential)
  double contact = 0.0;    // the self-contact barrier (self_contact.hpp), 0 without self-contact
  double elastic() const noexcept { return bending + twisting + stretching; }
  double potential() const noexcept { return elastic() + contact + gravity + tip_force + vertex_forces; }
};

// The integrated strains (twist angle, kb.m1avg, kb.m2avg) at interior vertices 1 .. N-1 (entries 0
// and N are zero): the strains u of the rod are these divided by the Voronoi length.
std::vector<Vec3> integrated_strains(const RodModel& model, const RodState& state);

EnergyParts energy(const RodModel& model, const RodState& state);

// Static residual (see above); load_factor scales every dead load (gravity, the tip force and moment,
// the vertex forces and edge moments).
VecX static_residual(const RodModel& model, const RodState& state, double load_factor);

// The residual at base + dz in the chart of `base` (its reference frames transported from its
// tangents, its reference twists continued): the function whose derivative static_system's
// Jacobian is. (At base + dz re-based, static_residual differs from it by terms proportional to
// dz times the twisting moments dE/dtheta - the holonomy of parallel transport - which vanish at
// an equilibrium, so Newton in the current chart stays quadratic.)
VecX chart_residual(const RodModel& model, const RodState& base, const VecX& dz, double load_factor);

// Residual and its Jacobian d r / d z at z = the state (z in DofLayout order).
void static_system(const RodModel& model, const RodState& state, double load_factor, VecX& residual,
                   Eigen::SparseMatrix<double>& jacobian);
// The same at base + dz in the chart of `base` (dz empty: at base): Newton iterates in one chart.
void chart_system(const RodModel& model, const RodState& base, const VecX& dz, double load_factor, VecX& residual,
                  Eigen::SparseMatrix<double>& jacobian);

// The state displaced by dz (DofLayout order): positions and angles moved, multipliers replaced by
// lambda + dlambda, reference frames transported to the new tangents. largest_twist_change (optional)
// receives the largest change of a reference twist (the energy's chart needs it below pi/2).
RodState displaced(const RodModel& model, const RodState& state, const VecX& dz,
                   double* largest_twist_change = nullptr);

// Generalised vertex forces of the elastic rod on the world: g_i = dE_elastic/dx_i + sum_j
// lambda_j dc_j/dx_i (i = 0 .. N). At an equilibrium g_i equals the external force on vertex i.
std::vector<Vec3> elastic_vertex_forces(const RodModel& model, const RodState& state);

}  // namespace rodvv::solvers::rod3d
