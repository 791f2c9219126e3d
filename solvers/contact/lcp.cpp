#include "rodvv/solvers/contact/lcp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::contact {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// W_ii lambda_i, so that both arguments of the complementarity function carry the units of w.
double scaled_lambda(const MatX& W, const VecX& lambda, Eigen::Index i) {
  return W(i, i) > 0.0 ? W(i, i) * lambda(i) : lambda(i);
}

double convergence_scale(const VecX& b) { return b.size() == 0 ? 0.0 : b.cwiseAbs().maxCoeff(); }

LcpSolution finish(const MatX& W, const VecX& b, VecX lambda, std::size_t iterations) {
  LcpSolution solution;
  solution.lambda = std::move(lambda);
  solution.w = W * solution.lambda + b;
  solution.iterations = iterations;
  solution.residual = natural_map_residual(W, solution.lambda, solution.w);
  solution.fischer_burmeister = fischer_burmeister_residual(W, solution.lambda, solution.w);
  return solution;
}

}  // namespace

double natural_map_residual(const MatX& W, const VecX& lambda, const VecX& w) {
  double residual = 0.0;
  for (Eigen::Index i = 0; i < lambda.size(); ++i)
    residual = std::max(residual, std::abs(std::min(scaled_lambda(W, lambda, i), w(i))));
  return residual;
}

double fischer_burmeister_residual(const MatX& W, const VecX& lambda, const VecX& w) {
  double residual = 0.0;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    const double a = scaled_lambda(W, lambda, i);
    residual = std::max(residual, std::abs(a + w(i) - std::hypot(a, w(i))));
  }
  return residual;
}

void validate_lcp(const MatX& W, const VecX& b) {
  if (W.rows() != W.cols())
    throw InputError("W", "the LCP matrix W must be square, got " + std::to_string(W.rows()) + " x " +
                              std::to_string(W.cols()));
  if (b.size() != W.rows())
    throw InputError("b", "the LCP vector b must have " + std::to_string(W.rows()) +
                              " entries (the size of W), got " + std::to_string(b.size()));
  if (!W.allFinite()) throw InputError("W", "the LCP matrix W must have finite entries");
  if (!b.allFinite()) throw InputError("b", "the LCP vector b must have finite entries");
  if (W.size() == 0) return;
  // Symmetry to 100 eps of the largest entry: a Delassus matrix J A^-1 J^T formed in floating
  // point is symmetric to a few ulps, a genuinely non-symmetric W is off by O(1).
  const double scale = W.cwiseAbs().maxCoeff();
  const double asymmetry = (W - W.transpose()).cwiseAbs().maxCoeff();
  if (asymmetry > 100.0 * kEps * scale)
    throw InputError("W", "the LCP matrix W must be symmetric positive semidefinite; max |W - W^T| = " +
                              format_value(asymmetry) + " > 100 eps max|W|");
  for (Eigen::Index i = 0; i < W.rows(); ++i)
    if (W(i, i) < 0.0)
      throw InputError("W", "the LCP matrix W must be positive semidefinite, but W(" + std::to_string(i) +
                                "," + std::to_string(i) + ") = " + format_value(W(i, i)) + " < 0");
}

LcpSolution solve_lcp_pgs(const MatX& W, const VecX& b, const LcpSettings& settings) {
  validate_lcp(W, b);
  require_positive("tolerance", settings.tolerance);
  const Eigen::Index n = b.size();
  VecX lambda = VecX::Zero(n);
  const double target = settings.tolerance * convergence_scale(b);
  if (n == 0 || b.minCoeff() >= 0.0) return finish(W, b, lambda, 0);  // lambda = 0 is a solution

  // A zero diagonal of a PSD matrix means a zero row: w_i = b_i whatever lambda is.
  for (Eigen::Index i = 0; i < n; ++i)
    if (W(i, i) == 0.0 && b(i) < 0.0)
      throw SolverError("lcp-pgs", "infeasible LCP: row " + std::to_string(i) +
                                       " of W is zero and b_i < 0, so w_i < 0 for every lambda",
                        0, -b(i));

  double residual = std::numeric_limits<double>::infinity();
  for (std::size_t sweep = 1; sweep <= settings.max_iterations; ++sweep) {
    for (Eigen::Index i = 0; i < n; ++i) {
      if (W(i, i) == 0.0) continue;
      const double wi = W.row(i).dot(lambda) + b(i);
      lambda(i) = std::max(0.0, lambda(i) - wi / W(i, i));
    }
    const VecX w = W * lambda + b;
    residual = natural_map_residual(W, lambda, w);
    if (!std::isfinite(residual))
      throw SolverError("lcp-pgs", "non-finite iterate (diverging: the LCP may be infeasible)", sweep,
                        residual);
    if (residual <= target) return finish(W, b, std::move(lambda), sweep);
  }
  throw SolverError("lcp-pgs",
                    "no convergence to tolerance " + format_value(settings.tolerance) +
                        " x max|b| (an infeasible LCP, or W too ill-conditioned for Gauss-Seidel)",
                    settings.max_iterations, residual);
}

LcpSolution solve_lcp_lemke(const MatX& W, const VecX& b, const LcpSettings& settings) {
  validate_lcp(W, b);
  const Eigen::Index n = b.size();
  if (n == 0 || b.minCoeff() >= 0.0) return finish(W, b, VecX::Zero(n), 0);

  // Tableau of  I w - W z - d z0 = b  (d = 1). Columns: w_0..w_{n-1}, z_0..z_{n-1}, z0, rhs.
  // Variable ids follow the columns; basis[i] is the variable basic in row i.
  const Eigen::Index z0 = 2 * n, rhs = 2 * n + 1;
  MatX T(n, 2 * n + 2);
  T << MatX::Identity(n, n), -W, -VecX::Ones(n), b;
  std::vector<Eigen::Index> basis(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) basis[static_cast<std::size_t>(i)] = i;

  auto pivot = [&](Eigen::Index row, Eigen::Index col) {
    T.row(row) /= T(row, col);
    for (Eigen::Index i = 0; i < n; ++i)
      if (i != row && T(i, col) != 0.0) T.row(i) -= T(i, col) * T.row(row);
    T(row, col) = 1.0;
  };

  // Initial pivot: z0 enters at the value that makes every w_i >= 0; the most negative b_i leaves.
  Eigen::Index row = 0;
  b.minCoeff(&row);
  Eigen::Index leaving = basis[static_cast<std::size_t>(row)];
  pivot(row, z0);
  basis[static_cast<std::size_t>(row)] = z0;
  Eigen::Index entering = leaving < n ? leaving + n : leaving - n;

  const std::size_t max_pivots =
      std::max<std::size_t>(settings.max_pivots, 50 * static_cast<std::size_t>(n) + 50);
  for (std::size_t pivots = 1; pivots <= max_pivots; ++pivots) {
    // Ratio test over rows whose basic variable decreases as `entering` grows. Pivot tolerance
    // relative to the column's largest entry: below it an entry is round-off of an exact zero.
    const double column_scale = T.col(entering).cwiseAbs().maxCoeff();
    const double pivot_tol = 1e3 * kEps * std::max(column_scale, 1.0);
    std::vector<Eigen::Index> candidates;
    double min_ratio = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < n; ++i) {
      if (T(i, entering) <= pivot_tol) continue;
      const double ratio = std::max(T(i, rhs), 0.0) / T(i, entering);
      min_ratio = std::min(min_ratio, ratio);
    }
    if (!std::isfinite(min_ratio))
      throw SolverError("lcp-lemke",
                        "secondary ray: the LCP has no solution (infeasible, or W not positive "
                        "semidefinite)",
                        pivots, T.col(rhs).cwiseAbs().maxCoeff());
    const double tie_tol = 1e3 * kEps * std::max(min_ratio, 1.0);
    for (Eigen::Index i = 0; i < n; ++i)
      if (T(i, entering) > pivot_tol && std::max(T(i, rhs), 0.0) / T(i, entering) <= min_ratio + tie_tol)
        candidates.push_back(i);
    // z0 leaving ends the path; otherwise break ties lexicographically on the rows of B^-1 (the
    // w columns) divided by the pivot entry, which rules out cycling on degenerate problems.
    row = -1;
    for (Eigen::Index i : candidates)
      if (basis[static_cast<std::size_t>(i)] == z0) row = i;
    if (row < 0) {
      row = candidates.front();
      for (std::size_t k = 1; k < candidates.size(); ++k) {
        const Eigen::Index i = candidates[k];
        for (Eigen::Index j = 0; j < n; ++j) {
          const double a = T(i, j) / T(i, entering), c = T(row, j) / T(row, entering);
          if (a < c - kEps) { row = i; break; }
          if (a > c + kEps) break;
        }
      }
    }
    leaving = basis[static_cast<std::size_t>(row)];
    pivot(row, entering);
    basis[static_cast<std::size_t>(row)] = entering;
    if (leaving == z0) {
      VecX lambda = VecX::Zero(n);
      for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index var = basis[static_cast<std::size_t>(i)];
        if (var >= n && var < 2 * n) lambda(var - n) = std::max(T(i, rhs), 0.0);
      }
      return finish(W, b, std::move(lambda), pivots);
    }
    entering = leaving < n ? leaving + n : leaving - n;  // the complement of the leaving variable
  }
  throw SolverError("lcp-lemke", "pivot limit reached (cycling)", max_pivots,
                    T.col(rhs).cwiseAbs().maxCoeff());
}

LcpSolution solve_lcp(const MatX& W, const VecX& b, LcpMethod method, const LcpSettings& settings) {
  return method == LcpMethod::Lemke ? solve_lcp_lemke(W, b, settings) : solve_lcp_pgs(W, b, settings);
}

LcpSolution solve_lcp_verified(const MatX& W, const VecX& b, LcpMethod method, const LcpSettings& settings,
                               double accuracy, std::size_t* rescaled) {
  require_open_interval("accuracy", accuracy, 0.0, 1.0);
  const bool lemke = method == LcpMethod::Lemke;
  const auto accurate = [&](const LcpSolution& s) {
    return b.size() == 0 || s.residual <= accuracy * b.cwiseAbs().maxCoeff();
  };
  LcpSolution s;
  bool ok = false;
  try {
    s = solve_lcp(W, b, method, settings);
    ok = accurate(s);
  } catch (const SolverError&) {
    if (!lemke) throw;
  }
  if (lemke && !ok) {
    if (rescaled != nullptr) ++*rescaled;
    const Eigen::Index m = b.size();
    VecX d(m);
    for (Eigen::Index i = 0; i < m; ++i) d[i] = W(i, i) > 0.0 ? 1.0 / std::sqrt(W(i, i)) : 1.0;
    MatX scaled = d.asDiagonal() * W * d.asDiagonal();
    scaled = (0.5 * (scaled + scaled.transpose())).eval();  // exactly symmetric again
    const std::size_t unscaled_pivots = s.iterations;
    s = solve_lcp_lemke(scaled, d.cwiseProduct(b), settings);
    s.iterations += unscaled_pivots;
    s.lambda = d.cwiseProduct(s.lambda);
    s.w = W * s.lambda + b;
    s.residual = natural_map_residual(W, s.lambda, s.w);
    s.fischer_burmeister = fischer_burmeister_residual(W, s.lambda, s.w);
  }
  if (!accurate(s))
    throw SolverError(lemke ? "lcp-lemke" : "lcp-pgs",
                      "inaccurate LCP solution: natural-map residual " + format_value(s.residual) + " > " +
                          format_value(accuracy) + " max|b|",
                      s.iterations, s.residual);
  return s;
}

}  // namespace rodvv::solvers::contact
