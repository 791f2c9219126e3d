#pragma once
// Frictionless unilateral contact as a linear complementarity problem (ALGORITHMS.md §4.2 (v), §4.3):
//
//     find lambda with  0 <= lambda  _|_  w = W lambda + b >= 0
//
// W is a symmetric positive semidefinite Delassus matrix (J A^-1 J^T), b the free relative
// velocities (or gaps / h). Two solvers share this interface:
//  - projected Gauss-Seidel (Cottle, Pang & Stone, "The Linear Complementarity Problem", 1992,
//    §5.2): lambda_i <- max(0, lambda_i - w_i / W_ii), sweeping until the residual is small;
//  - Lemke's complementary pivoting with covering vector d = 1 and a lexicographic ratio test
//    (Lemke 1965, Management Science 11:681; Cottle-Pang-Stone §4.4), exact up to round-off, for
//    the small problems of a few active contacts.
// Both report iterations (sweeps / pivots) and two residuals. Infeasible problems (no lambda >= 0
// makes w >= 0) have no solution: Lemke ends on a secondary ray, PGS does not converge; both throw
// SolverError. Malformed input (sizes, non-finite entries, W not symmetric, W_ii < 0) throws
// InputError naming the argument.
#include <cstddef>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::contact {

struct LcpSettings {
  // Stop when the scaled natural-map residual (below) is <= tolerance * max|b_i|.
  double tolerance = 1e-13;
  std::size_t max_iterations = 100000;  // PGS sweeps; Lemke uses max(max_pivots, 50 n + 50)
  std::size_t max_pivots = 0;
};

struct LcpSolution {
  VecX lambda;  // >= 0
  VecX w;       // W lambda + b, recomputed from lambda (not read off a tableau)
  std::size_t iterations = 0;
  // max_i |min(W_ii lambda_i, w_i)|: the natural map with lambda scaled by the diagonal so both
  // arguments have the units of w (W_ii = 0 rows use lambda_i itself).
  double residual = 0.0;
  double fischer_burmeister = 0.0;  // max_i |a + c - sqrt(a^2 + c^2)|, a = W_ii lambda_i, c = w_i
};

// The two residuals of a candidate (lambda, w) for the matrix W (only its diagonal is read).
double natural_map_residual(const MatX& W, const VecX& lambda, const VecX& w);
double fischer_burmeister_residual(const MatX& W, const VecX& lambda, const VecX& w);

// Checks sizes, finiteness, symmetry (to 100 eps max|W|) and a non-negative diagonal.
void validate_lcp(const MatX& W, const VecX& b);

LcpSolution solve_lcp_pgs(const MatX& W, const VecX& b, const LcpSettings& settings = {});
LcpSolution solve_lcp_lemke(const MatX& W, const VecX& b, const LcpSettings& settings = {});

enum class LcpMethod { ProjectedGaussSeidel, Lemke };
LcpSolution solve_lcp(const MatX& W, const VecX& b, LcpMethod method, const LcpSettings& settings = {});

// solve_lcp with its result verified: a solution whose natural-map residual exceeds accuracy x max|b| is
// never returned. Lemke's tableau tolerances are absolute (entries below 1 are compared with 1e3 eps), so
// on a W far from unit scale - nodal compliances spanning ~N^3 on a planar rod, a Delassus matrix in the
// units of a massive rod (1e-12) - it can end (z0 leaving the basis) on an inaccurate "solution", or on a
// ray or the pivot limit. Then Lemke runs again on the Jacobi-scaled problem (D W D, D b), D = diag(W)^-1/2
// (unit diagonal; zero rows keep D = 1), lambda = D mu, and `rescaled` (if given) is incremented. W itself
// goes first: it leaves the zero-force pairs of a degenerate contact exactly non-basic, where the scaled
// problem may return them basic at round-off. PGS is invariant under the scaling (its update is
// lambda_i - w_i / W_ii) and runs once. Residuals are reported in the units of W. Inaccurate after both:
// SolverError naming the method, the pivots and the residual.
LcpSolution solve_lcp_verified(const MatX& W, const VecX& b, LcpMethod method, const LcpSettings& settings,
                               double accuracy, std::size_t* rescaled = nullptr);

}  // namespace rodvv::solvers::contact
