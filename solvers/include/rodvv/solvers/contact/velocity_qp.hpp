#pragma once
// The velocity-level contact step as a convex QP (Levin et al., SIGGRAPH 2011; seed slides 001,
// "Collision"; ALGORITHMS.md §4.3 and §6.2):
//
//     v = argmin 1/2 v^T M v + R^T v    subject to  J v >= c
//
// M symmetric positive definite, J (k x n) the constraint rows, c their bounds. Its KKT conditions
// M v + R = J^T lambda, 0 <= lambda _|_ J v - c >= 0 reduce, with v = M^-1 (J^T lambda - R), to the
// dual LCP of lcp.hpp with W = J M^-1 J^T and b = -J M^-1 R - c. The multipliers lambda are the
// constraint impulses. The LCP is solved by solve_lcp_verified (lcp.hpp) with accuracy 1e-6: a result
// whose natural-map residual exceeds 1e-6 max|b| after the Jacobi-scaled retry is a SolverError.
#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/contact/lcp.hpp"

namespace rodvv::solvers::contact {

struct VelocityQpSolution {
  VecX v;
  VecX lambda;  // impulses, >= 0
  VecX gap;     // J v - c, >= 0 up to round-off
  std::size_t iterations = 0;
  double residual = 0.0;  // of the dual LCP
};

// Dense M (Cholesky); throws InputError if M is not symmetric positive definite or sizes disagree.
// `compliance` (>= 0, InputError otherwise) softens every constraint to J v - c + eps lambda >= 0 with
// eps = compliance x max_i W_ii (constraint-force mixing): redundant constraints - a rod lying on a plane
// at more points than it has ways to leave it - make W singular, where Lemke's pivoting stalls on its
// round-off; a small compliance makes W definite and moves the gaps by eps lambda.
VelocityQpSolution solve_velocity_qp(const MatX& M, const VecX& R, const MatX& J, const VecX& c,
                                     LcpMethod method = LcpMethod::Lemke, const LcpSettings& settings = {},
                                     double compliance = 0.0);

// Lumped (diagonal) M given by its diagonal m > 0: O(k^2 n) to form W, the case of the Eulerian solid.
VelocityQpSolution solve_velocity_qp_lumped(const VecX& m, const VecX& R, const MatX& J, const VecX& c,
                                            LcpMethod method = LcpMethod::Lemke,
                                            const LcpSettings& settings = {});

}  // namespace rodvv::solvers::contact
