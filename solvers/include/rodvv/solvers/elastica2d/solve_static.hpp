#pragma once
// Static equilibrium of a planar elastica (problem.hpp) in the "polygon" or "arcs" discretisation
// (discretisation.hpp): Newton's method on the KKT system of the discrete Lagrangian
// (lagrangian.hpp) with analytic Hessian, a banded LU with partial pivoting (banded_lu.hpp; the
// KKT matrix has half-bandwidth <= 5, so a Newton step costs O(N)), and a backtracking line search
// on the merit function
// ||grad L||_2 (the Newton direction is a descent direction for it; Armijo constant 1e-4, step
// halved down to 2^-30).
//
// Load stepping: with load_steps = K, the dead loads and the potential are scaled by
// lambda_k = k / K and every prescribed end position moves linearly from the initial guess's value
// to the prescribed one (displacement stepping); each step starts from the previous solution.
// Prescribed angles are imposed at their full value from the start. A step whose Newton solve fails
// is retried from the last converged state in two halves, recursively down to 2^-10 of a planned
// step (then SolverError, naming the load factor reached); a problem that converges in its planned
// steps takes exactly those steps.
// Branch selection: at a bifurcation (a column beyond the Euler load) Newton converges to the branch
// nearest the initial guess, e.g. theta(s) = theta_amp cos(pi s / L) for the first mode of a
// pinned-pinned column; stepping needs a guess in the first step's basin. To follow a branch in
// the load, use trace_branch (continuation.hpp, pseudo-arc-length).
// Convergence: ||D grad L||_inf <= tolerance, or a Newton step already at round-off
// (||dz / u||_inf <= 64 eps (1 + ||z / u||_inf)), whichever comes first; D and u put the residual
// and the unknowns in the problem's own units (length L, stiffness EI(0); newton.hpp), so that a
// rod converges alike at any L and EI (at L = EI = 1, D = u = 1).
//
// Output (PlanarRodSolution, common/planar_rod.hpp), at nodes s_i = i h:
//   x, y         node positions (arcs: exact arc ends);
//   theta        polygon: mean of the two adjacent edge angles; at an end, the prescribed angle
//                (Clamped) or the edge angle extrapolated over h/2 with the end curvature below;
//                arcs: the node angles themselves;
//   kappa        polygon interior: (phi_i - phi_{i-1}) / h; arcs interior: mean of the two adjacent
//                element curvatures; at a non-clamped end kappa_hat -/+ M/EI from the end couple
//                (exact natural BC); at a clamped end the reaction moment of the discrete moment
//                balance over kappa: polygon 2 (phi_0 - a) / h (derivative of the half-cell clamp
//                term), arcs kappa_hat + mu / EI (mu = multiplier of the clamp-angle row);
//   force_x/y    internal force n: edges = the multipliers n_i; interior nodes = mean of the two
//                edges; end nodes = the edge value moved half an element with the lumped load;
//   axial_force  interior: mean of the two edge axial forces; ends: n.t at the end node;
//   edge_axial_force  n_i . t at the edge midpoint (polygon: t(phi_i); arcs: t((theta_i +
//                theta_{i+1}) / 2));
//   shear_force, edge_shear_force  n.N (N = e_z x t) at the same places as the axial force;
//   axial_stiffness, shear_stiffness  EA and GA of the problem (strains: n.t / EA, n.N / GA);
//   potential    V(x_i, y_i) (0 without a potential);
//   iterations   Newton iterations summed over all load steps; residual = final ||D grad L||_inf.
// Failure: rodvv::SolverError (Newton iterations, last residual) when Newton does not reach the
// tolerance within max_iterations in a step, the line search fails, or the KKT matrix is singular.
#include <cstddef>
#include <functional>

#include "rodvv/common/planar_rod.hpp"
#include "rodvv/solvers/elastica2d/discretisation.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"

namespace rodvv::solvers::elastica2d {

struct SolverOptions {
  double tolerance = 1e-10;         // on ||D grad L||_inf, in the problem's own units; in (0, 1)
  std::size_t max_iterations = 50;  // Newton iterations per load step, >= 1
  std::size_t load_steps = 1;       // >= 1
};

// theta(s): the initial tangent angle; empty = the start's clamp angle (0 if not clamped).
// The initial positions follow from theta by the scheme's own chords, starting from the
// prescribed start position where there is one and (x0, y0) otherwise. The edge forces start from
// the discrete force balance integrated from the end s = L, where the end's dead load fixes the
// end force (Free: both components; Sliding: x; otherwise 0); the boundary multipliers start at 0.
struct InitialGuess {
  std::function<double(double)> theta;
  double x0 = 0.0;
  double y0 = 0.0;
};

void validate(const SolverOptions& options);

PlanarRodSolution solve_static(const Problem& problem, const Discretisation& discretisation,
                               const SolverOptions& options = {}, const InitialGuess& guess = {});

}  // namespace rodvv::solvers::elastica2d
