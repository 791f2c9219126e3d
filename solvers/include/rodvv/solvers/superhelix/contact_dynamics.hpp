#pragma once
// Super-Helix dynamics against rigid frictionless obstacles: the semi-implicit Euler step of
// dynamics.hpp (dense path) with velocity-level contact at the Gauss points (ALGORITHMS.md §4.3; the
// step of Levin et al., SIGGRAPH 2011, on the reduced coordinates as in Bertails et al. 2006's hair).
//
// Without contact the step solves A dv = rhs, A = M_n + D (dynamics.hpp). With candidate contacts g
// (the Gauss points whose gap to an obstacle is <= contact_distance at q_n) it solves the convex QP
//
//     dv = argmin 1/2 dv^T A dv - rhs^T dv   subject to   gap_g + h n_g^T J_g (qdot_n + dv) >= 0,
//
// i.e. the gap linearised at q_n stays open at the end of the step (q_{n+1} = q_n + h qdot_{n+1}),
// with the shared dense solver contact::solve_velocity_qp (Cholesky of A, the Delassus matrix
// W = J A^-1 J^T, Lemke or projected Gauss-Seidel on its dual LCP). The multipliers are the contact
// impulses over the step: A dv = rhs + sum_g (n_g^T J_g)^T lambda_g, so the force at point g is
// lambda_g / h along the obstacle's normal n_g. At rest (qdot = 0, dv = 0) this is the static
// equilibrium K (q - q0) = F_ext + sum_g J_g^T n_g lambda_g / h with lambda_g >= 0, gap_g >= 0 and
// lambda_g gap_g = 0: the frictionless contact equilibrium at the Gauss points, the same discrete
// problem as frictional_statics.hpp with mu = 0 (a rod settled by damping lands on it exactly).
// Penetration: the linearised gap is kept; the true one misses it by O(h^2 |qdot|^2 curvature) per
// step, reported as the largest penetration at q_{n+1}.
//
// Obstacles are those of frictional_statics.hpp (plane, ball, cylinder; `radius` to the centreline)
// with mu = 0: friction is the quasi-static solver's. The root is the model's, at rest (a moving root:
// dynamics.hpp's RootMotion, not yet offered with contact).
// Bad input (InputError naming it): as step() of dynamics.hpp; obstacles as validate_obstacles, and
// mu != 0 ("obstacles"); options out of range ("contact_distance", "lcp.tolerance", "compliance"). A
// contact problem the LCP solver cannot solve (no feasible impulse, PGS not converged, a Lemke solution
// still inaccurate after the Jacobi-scaled retry of contact::solve_lcp_verified): SolverError from the
// LCP solver naming its method, iterations and residual.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/contact/lcp.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/frictional_statics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct ContactStepOptions {
  double contact_distance = 0.0;  // candidates: gap <= this at q_n; 0: one element length
  contact::LcpMethod method = contact::LcpMethod::Lemke;
  contact::LcpSettings lcp = {};
  // Constraint compliance relative to the Delassus matrix's largest diagonal (velocity_qp.hpp), in [0, 1]: a
  // rod lying on a plane touches it at every Gauss point, more contacts than it has ways to leave the plane,
  // so W is singular and Lemke's pivoting fails on its round-off. Measured on a heavy rod settling on a floor
  // (four Gauss points, N = 8, 16, 32, h = 0.01 and 0.1): with compliance 0 and 1e-12 some steps end on
  // inaccurate LCP solutions even after the Jacobi-scaled retry (N = 32; 1e-12 also at N = 8 and 16); 1e-9
  // settles in every run, within 2e-11 (h = 0.01) .. 1.3e-7 (h = 0.1, N = 32) of the frictionless static
  // equilibrium, relative.
  double compliance = 1e-9;
};

struct ImpulsiveContact {
  std::size_t point = 0;     // Gauss point (Kinematics::points() order)
  std::size_t obstacle = 0;  // index into the obstacles
  double gap = 0.0;          // at q_n
  Vec3 normal;               // the obstacle's outward normal at the point, at q_n
  double impulse = 0.0;      // lambda >= 0 over the step; the force is impulse / h along normal
};

struct ContactStepResult {
  DynamicState state;                     // at t + h
  std::vector<ImpulsiveContact> contacts;  // every candidate (impulse 0: it stayed open)
  std::size_t lcp_iterations = 0;         // pivots (Lemke) or sweeps (PGS)
  double lcp_residual = 0.0;              // natural-map residual of the dual LCP
  double penetration = 0.0;               // max(0, -gap) over the Gauss points at q_{n+1}
};

ContactStepResult step_with_obstacles(const RodModel& model, const DynamicState& state, double h,
                                      const std::vector<RigidObstacle>& obstacles,
                                      const ContactStepOptions& options = {});

}  // namespace rodvv::solvers::superhelix
