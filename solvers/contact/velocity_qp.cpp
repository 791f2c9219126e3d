#include "rodvv/solvers/contact/velocity_qp.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::contact {

namespace {

void check_sizes(Eigen::Index n, const VecX& R, const MatX& J, const VecX& c) {
  if (R.size() != n)
    throw InputError("R", "the linear term R must have " + std::to_string(n) + " entries (the size of M)");
  if (J.cols() != n)
    throw InputError("J", "the constraint matrix J must have " + std::to_string(n) + " columns (the size of M)");
  if (c.size() != J.rows())
    throw InputError("c", "the bounds c must have one entry per row of J (" + std::to_string(J.rows()) + ")");
  if (!R.allFinite()) throw InputError("R", "the linear term R must be finite");
  if (!J.allFinite()) throw InputError("J", "the constraint matrix J must be finite");
  if (!c.allFinite()) throw InputError("c", "the bounds c must be finite");
}

// v = v_free + M^-1 J^T lambda, with lambda from the dual LCP (W = J M^-1 J^T, b = J v_free - c).
VelocityQpSolution solve_dual(const VecX& v_free, const MatX& Minv_Jt, MatX W, const MatX& J,
                              const VecX& c, LcpMethod method, const LcpSettings& settings, double compliance) {
  require_non_negative("compliance", compliance);
  VelocityQpSolution solution;
  const VecX b = J * v_free - c;
  if (compliance > 0.0 && W.rows() > 0) W.diagonal().array() += compliance * W.diagonal().maxCoeff();
  // Verified (lcp.hpp): Lemke again on the Jacobi-scaled W when its result is off by more than 1e-6 max|b|
  // (a Delassus matrix in the units of a massive rod is ~1e-12, below Lemke's absolute tolerances).
  const LcpSolution lcp = solve_lcp_verified(W, b, method, settings, 1e-6);
  solution.lambda = lcp.lambda;
  solution.v = v_free + Minv_Jt * lcp.lambda;
  solution.gap = J * solution.v - c;
  solution.iterations = lcp.iterations;
  solution.residual = lcp.residual;
  return solution;
}

}  // namespace

VelocityQpSolution solve_velocity_qp(const MatX& M, const VecX& R, const MatX& J, const VecX& c,
                                     LcpMethod method, const LcpSettings& settings, double compliance) {
  if (M.rows() != M.cols() || M.rows() == 0)
    throw InputError("M", "the mass matrix M must be square with at least one row");
  if (!M.allFinite()) throw InputError("M", "the mass matrix M must be finite");
  check_sizes(M.rows(), R, J, c);
  const double scale = M.cwiseAbs().maxCoeff();
  if ((M - M.transpose()).cwiseAbs().maxCoeff() > 100.0 * std::numeric_limits<double>::epsilon() * scale)
    throw InputError("M", "the mass matrix M must be symmetric positive definite (it is not symmetric)");
  const Eigen::LLT<MatX> llt(M);
  if (llt.info() != Eigen::Success)
    throw InputError("M", "the mass matrix M must be symmetric positive definite (Cholesky failed)");
  const VecX v_free = -llt.solve(R);
  const MatX X = llt.matrixL().solve(J.transpose());  // L^-1 J^T, so W = X^T X is symmetric PSD
  const MatX W = X.transpose() * X;
  const MatX Minv_Jt = llt.matrixU().solve(X);
  return solve_dual(v_free, Minv_Jt, W, J, c, method, settings, compliance);
}

VelocityQpSolution solve_velocity_qp_lumped(const VecX& m, const VecX& R, const MatX& J, const VecX& c,
                                            LcpMethod method, const LcpSettings& settings) {
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (!std::isfinite(m(i)) || !(m(i) > 0.0))
      throw InputError("m", "lumped mass m(" + std::to_string(i) + ") = " + format_value(m(i)) +
                                ": every lumped mass must be a finite number > 0");
  check_sizes(m.size(), R, J, c);
  const VecX m_inv = m.cwiseInverse();
  const VecX v_free = -R.cwiseProduct(m_inv);
  const MatX Minv_Jt = m_inv.asDiagonal() * J.transpose();
  const MatX W = J * Minv_Jt;
  const MatX W_sym = 0.5 * (W + W.transpose());
  return solve_dual(v_free, Minv_Jt, W_sym, J, c, method, settings, 0.0);
}

}  // namespace rodvv::solvers::contact
