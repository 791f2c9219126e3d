#pragma once
// Small oscillations of the discrete elastic rod (model.hpp, discrete_energy.hpp) about an
// equilibrium at load factor 1: natural frequencies, mode shapes and the stability eigenvalue.
//
// The linearisation: with z the free positions and material angles (DofLayout order, the dofs the
// supports hold removed: statics.hpp held_dofs) and M the lumped mass on them (lumped_mass below),
//     M z'' + K z + C^T lambda' = 0,   C z = 0,
// K the block of the static Jacobian (static_system at the equilibrium: the Hessian of the energy in
// the state's chart, including sum_j lambda_j d^2 c_j, the tension terms that load the rod
// geometrically) on the free positions and angles, C the rows of the free inextensibility
// multipliers on them (absent for an extensible rod). The motion lies on the null space of C:
// with W = M^{-1/2} and Q an orthonormal basis of the null space of C W (Eigen's column-pivoted
// Householder QR of (C W)^T, so the rank is measured, not assumed), z = B y with B = W Q, and
//     y'' + A y = 0,   A = B^T K B = Q^T W K W Q,
// the constrained Hessian in the mass metric. Its eigenvalues are omega^2 (K v = omega^2 M v on the
// constraint manifold), its eigenvectors the mode shapes B y, which are M-orthonormal.
//
// Symmetry: K is the Hessian of a potential (symmetric up to round-off) unless a dead tip moment
// loads the rod - a dead moment is not conservative for 3-D rotations (model.hpp), and its load
// stiffness is unsymmetric. A is then replaced by its symmetric part only if its relative asymmetry
// max |A - A^T| / max |A| is below options.symmetry_tolerance (round-off); otherwise InputError
// ("end_moment"): the problem is non-self-adjoint (flutter is possible) and has no real modes.
//
// Cost and size limit: dense matrices, O(n^3) with n ~ 4N free dofs (the QR's full Q and the
// symmetric eigensolver): N <= kMaxModalElements = 512 (n ~ 2050, a few seconds); beyond,
// InputError ("elements").
//
// Mode shapes are returned in DofLayout order with zero entries on held dofs and multipliers (the
// multiplier perturbation of a mode, (C M^-1 C^T)^-1 C M^-1 (omega^2 M - K) v, is not formed).
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::solvers::rod3d {

inline constexpr std::size_t kMaxModalElements = 512;

// The lumped mass on the DofLayout: rho S ebar on each coordinate of vertex i (half at i = 0 and
// i = N, as the gravity load of discrete_energy.cpp: the Voronoi cells of the vertices), rho I0 ebar
// on each material angle, 0 on the multipliers. Requires twist_inertia > 0 (InputError naming it):
// with a massless angle the twist is quasi-static and K v = omega^2 M v is singular.
VecX lumped_mass(const RodModel& model);

struct LinearizationOptions {
  // The state must be an equilibrium at load factor 1: statics.hpp scaled_residual below this, or
  // below its round-off floor 8 N^3 eps max(1, |x|_max / L) if larger (1.5e-8 at N = 256, 2.4e-7 at
  // N = 512; InputError "state" otherwise). The default lets through any Newton-converged
  // equilibrium (StaticOptions::tolerance 1e-10) and rejects states that are not at rest.
  double equilibrium_tolerance = 1e-8;
  // Largest relative asymmetry max |A - A^T| / max |A| accepted as round-off. The Hessian comes
  // from second-order forward-mode jets (each entry a sum of O(100) products): measured <= 2e-15 for
  // N <= 128; 1e-11 leaves 4 decades of margin and still rejects any dead moment whose load
  // stiffness |M| / ebar^2 is not negligible.
  double symmetry_tolerance = 1e-11;
};

struct LinearizedRod {
  std::vector<std::size_t> free_dofs;  // DofLayout indices of the free positions and angles
  MatX basis;                          // B (free_dofs.size() x r): z = B y, C B = 0, B^T M B = I
  MatX hessian;                        // A = B^T K B (r x r), symmetrised: the constrained Hessian in the mass metric
  double asymmetry = 0.0;              // max |A - A^T| / max |A| before symmetrising
  std::size_t constraint_rank = 0;     // rank of C (0 for an extensible rod)
};

// Throws InputError ("elements", "twist_inertia", "state", "end_moment") as described above.
LinearizedRod linearize(const RodModel& model, const RodState& equilibrium, const LinearizationOptions& options = {});

struct LinearModes {
  VecX omega_squared;  // eigenvalues of A, ascending (negative: an unstable direction)
  VecX frequencies;    // sqrt(max(omega^2, 0)) (rigid-body modes of a free rod: ~0)
  MatX shapes;         // column k: mode k in DofLayout order (held dofs and multipliers 0), v^T M v = 1
};

LinearModes linear_modes(const RodModel& model, const RodState& equilibrium, const LinearizationOptions& options = {});

// The smallest eigenvalue of A (omega_1^2, 1/time^2): > 0 the equilibrium is (linearly) stable,
// < 0 unstable; it crosses zero at a bifurcation (buckling). A free rod has six zero
// eigenvalues (rigid motions) at round-off of either sign.
double stability_eigenvalue(const RodModel& model, const RodState& equilibrium, const LinearizationOptions& options = {});

// How a mode's kinetic norm v^T M v splits: translation along each column of `frame` (an
// orthonormal basis) and rotation of the cross-sections (the angles). The four parts sum to v^T M v
// (1 for the shapes above).
struct ModalContent {
  Vec3 translation = Vec3::Zero();
  double rotation = 0.0;
};
ModalContent modal_content(const RodModel& model, const VecX& shape, const Mat3& frame);

}  // namespace rodvv::solvers::rod3d
