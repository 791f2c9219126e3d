#include "rodvv/solvers/elastica2d/buckling.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"

namespace rodvv::solvers::elastica2d {

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using Sparse = Eigen::SparseMatrix<double>;

constexpr const char* kMethod = "critical_loads";

Index idx(std::size_t i) { return static_cast<Index>(i); }

Problem straight_column(const BucklingProblem& column) {
  Problem problem;
  problem.length = column.length;
  problem.bending_stiffness = [EI = column.bending_stiffness](double) { return EI; };
  // Straight along +x from the origin: prescribed positions (0, 0) and (L, 0), clamp angles 0.
  const bool clamped_start = column.supports != EndSupports::PinnedPinned;
  problem.start.support = clamped_start ? Support::Clamped : Support::Pinned;
  problem.end.x = column.length;
  switch (column.supports) {
    case EndSupports::PinnedPinned:
    case EndSupports::ClampedPinned:
      problem.end.support = Support::Pinned;
      break;
    case EndSupports::ClampedFree:
      // The dead load -P e_x at the free end enters the energy linearly: it does not change the
      // Hessian, so it is left out.
      problem.end.support = Support::Free;
      break;
    case EndSupports::ClampedClamped:
      problem.end.support = Support::Clamped;
      break;
  }
  return problem;
}

// Entries of column `col` of a symmetric sparse matrix, i.e. of row `col` (the Hessian is stored
// with both triangles).
template <class F>
void for_each_in_row(const Sparse& m, std::size_t row, F&& f) {
  for (Sparse::InnerIterator it(m, idx(row)); it; ++it) f(static_cast<std::size_t>(it.row()), it.value());
}

// Basis of the perturbations allowed by the chain rows: every primal dof of z as a linear function
// of q = (dx_0, dy_0, a_0 .. a_{A-1}). Row i of the result is dz_{primal[i]}.
// The chain row of edge i reads dx_{i+1} - dx_i + sum_j J(nx_i, a_j) da_j = 0 (and the same for y);
// anything else in that row means the Lagrangian is not the inextensible chain this assumes.
MatrixXd chain_basis(const DiscreteLagrangian& lag, const Sparse& hess, const std::vector<std::size_t>& primal,
                     const std::vector<Index>& primal_slot) {
  const std::size_t n = lag.elements(), angles = lag.angle_count();
  const Index q = idx(angles + 2);
  MatrixXd node_x = MatrixXd::Zero(idx(n + 1), q), node_y = MatrixXd::Zero(idx(n + 1), q);
  node_x(0, 0) = 1.0;
  node_y(0, 1) = 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    for (int component = 0; component < 2; ++component) {
      const std::size_t row = component == 0 ? lag.nx(i) : lag.ny(i);
      const std::size_t here = component == 0 ? lag.x(i) : lag.y(i);
      const std::size_t next = component == 0 ? lag.x(i + 1) : lag.y(i + 1);
      MatrixXd& node = component == 0 ? node_x : node_y;
      Eigen::RowVectorXd increment = Eigen::RowVectorXd::Zero(q);
      double coefficient_here = 0.0, coefficient_next = 0.0;
      for_each_in_row(hess, row, [&](std::size_t col, double value) {
        if (col == here) {
          coefficient_here = value;
        } else if (col == next) {
          coefficient_next = value;
        } else if (lag.is_multiplier(col) || primal_slot[col] < 2 * idx(n + 1)) {
          if (value != 0.0)
            throw SolverError(kMethod, "chain row of edge " + std::to_string(i) +
                                           " couples an unexpected unknown (index " + std::to_string(col) +
                                           "): the Lagrangian is not the inextensible chain",
                              0, value);
        } else {
          increment[primal_slot[col] - 2 * idx(n + 1) + 2] -= value;
        }
      });
      if (coefficient_here != -1.0 || coefficient_next != 1.0)
        throw SolverError(kMethod, "chain row of edge " + std::to_string(i) +
                                       " is not r_{i+1} - r_i - g_i",
                          0, coefficient_next - 1.0);
      node.row(idx(i + 1)) = node.row(idx(i)) + increment;
    }
  }
  MatrixXd basis = MatrixXd::Zero(idx(primal.size()), q);
  for (std::size_t i = 0; i <= n; ++i) {
    basis.row(primal_slot[lag.x(i)]) = node_x.row(idx(i));
    basis.row(primal_slot[lag.y(i)]) = node_y.row(idx(i));
  }
  for (std::size_t j = 0; j < angles; ++j) basis(primal_slot[lag.angle(j)], idx(j + 2)) = 1.0;
  return basis;
}

// The primal block of a Hessian, in the order of `primal`.
Sparse primal_block(const Sparse& hess, const std::vector<std::size_t>& primal,
                    const std::vector<Index>& primal_slot) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t col : primal)
    for_each_in_row(hess, col, [&](std::size_t row, double value) {
      if (primal_slot[row] >= 0) triplets.emplace_back(primal_slot[row], primal_slot[col], value);
    });
  Sparse block(idx(primal.size()), idx(primal.size()));
  block.setFromTriplets(triplets.begin(), triplets.end());
  return block;
}

void normalise(BucklingMode& mode) {
  double largest = 0.0;
  for (double t : mode.theta) largest = std::max(largest, std::abs(t));
  if (largest == 0.0) return;
  double sign = 1.0;
  for (double t : mode.theta)
    if (std::abs(t) >= 0.5 * largest) {
      sign = t > 0.0 ? 1.0 : -1.0;
      break;
    }
  for (double& t : mode.theta) t *= sign / largest;
}

}  // namespace

std::string_view end_supports_id(EndSupports supports) {
  switch (supports) {
    case EndSupports::PinnedPinned:
      return "pinned-pinned";
    case EndSupports::ClampedFree:
      return "clamped-free";
    case EndSupports::ClampedClamped:
      return "clamped-clamped";
    case EndSupports::ClampedPinned:
      return "clamped-pinned";
  }
  return "unknown";
}

EndSupports end_supports_from_id(std::string_view id) {
  for (EndSupports s : {EndSupports::PinnedPinned, EndSupports::ClampedFree, EndSupports::ClampedClamped,
                        EndSupports::ClampedPinned})
    if (id == end_supports_id(s)) return s;
  throw InputError("supports", "invalid parameter 'supports' = " + std::string(id) +
                                   ": must be one of pinned-pinned, clamped-free, clamped-clamped, "
                                   "clamped-pinned");
}

BucklingResult critical_loads(const BucklingProblem& column, const Discretisation& discretisation,
                              std::size_t modes) {
  require_positive("length", column.length);
  require_positive("bending_stiffness", column.bending_stiffness);
  if (end_supports_id(column.supports) == "unknown")
    throw InputError("supports", "invalid parameter 'supports': must be PinnedPinned, ClampedFree, "
                                 "ClampedClamped or ClampedPinned");
  validate(discretisation);
  require_at_least("modes", modes, 1);

  // The pencil is solved for the unit column (L = EI = 1) and its loads scaled by EI / L^2, its stations
  // by L: the problem is homogeneous, so that is exact. Solved at the user's L and EI, the geometric
  // stiffness - the difference of two Hessians that both carry the bending terms EI / h against the
  // load's h - lost eps EI / (h^2) to cancellation (EI = 1e12 or L = 1e-6: not positive definite, or
  // loads off by 30 %).
  const BucklingProblem unit{column.supports, 1.0, 1.0};
  const double load_unit = column.bending_stiffness / (column.length * column.length);
  const DiscreteLagrangian lag(straight_column(unit), discretisation);
  const std::size_t n = lag.elements(), angles = lag.angle_count();
  const double h = lag.element_length();

  // The straight state: r_i = (s_i, 0), all angles 0, multipliers 0; then n_i = -e_x on every edge.
  VectorXd z = VectorXd::Zero(idx(lag.size()));
  for (std::size_t i = 0; i <= n; ++i) z[idx(lag.x(i))] = i == n ? unit.length : static_cast<double>(i) * h;
  const Sparse unloaded = lag.hessian(z);
  for (std::size_t i = 0; i < n; ++i) z[idx(lag.nx(i))] = -1.0;
  const Sparse loaded = lag.hessian(z);

  // Primal unknowns in the order (x_0, y_0, ..., x_N, y_N, a_0, ..., a_{A-1}).
  std::vector<std::size_t> primal;
  for (std::size_t i = 0; i <= n; ++i) {
    primal.push_back(lag.x(i));
    primal.push_back(lag.y(i));
  }
  for (std::size_t j = 0; j < angles; ++j) primal.push_back(lag.angle(j));
  std::vector<Index> primal_slot(lag.size(), -1);
  for (std::size_t k = 0; k < primal.size(); ++k) primal_slot[primal[k]] = idx(k);

  // Chain rows eliminated; then the boundary rows C q = 0, C = B Z0.
  const MatrixXd z0 = chain_basis(lag, unloaded, primal, primal_slot);
  MatrixXd boundary = MatrixXd::Zero(idx(lag.rows().size()), z0.cols());
  for (std::size_t k = 0; k < lag.rows().size(); ++k)
    for_each_in_row(unloaded, lag.row_multiplier(k), [&](std::size_t col, double value) {
      if (primal_slot[col] >= 0) boundary.row(idx(k)) += value * z0.row(primal_slot[col]);
    });
  // null(C) = the last q - rank columns of Q in C^T P = Q R. The entries of C are 0 or O(1) (unit
  // rows and sums of h * (exact 0) chord derivatives), so the default rank threshold is safe.
  const Eigen::ColPivHouseholderQR<MatrixXd> qr(boundary.transpose());
  const Index rank = qr.rank();
  const Index reduced = z0.cols() - rank;
  if (modes > static_cast<std::size_t>(reduced))
    throw InputError("modes", "invalid parameter 'modes' = " + std::to_string(modes) + ": must be in [1, " +
                                  std::to_string(reduced) + "] (the number of free perturbations for " +
                                  std::to_string(n) + " elements)");
  const MatrixXd z_full = z0 * qr.householderQ();
  const MatrixXd basis = z_full.rightCols(reduced);

  // Reduced pencil (symmetrised against round-off in the products).
  const Sparse kb = primal_block(unloaded, primal, primal_slot);
  const Sparse kg = primal_block(Sparse(unloaded - loaded), primal, primal_slot);
  MatrixXd a = basis.transpose() * (kb * basis);
  MatrixXd b = basis.transpose() * (kg * basis);
  a = 0.5 * (a + a.transpose()).eval();
  b = 0.5 * (b + b.transpose()).eval();

  // A v = P B v with B = L L^T: (L^-1 A L^-T) w = P w, v = L^-T w.
  const Eigen::LLT<MatrixXd> llt(b);
  if (llt.info() != Eigen::Success)
    throw SolverError(kMethod, "the geometric stiffness is not positive definite on the allowed "
                               "perturbations (a rigid motion is left free)",
                      0, std::numeric_limits<double>::quiet_NaN());
  MatrixXd c = llt.matrixL().solve(a);
  c = llt.matrixL().solve(c.transpose()).eval();
  c = 0.5 * (c + c.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<MatrixXd> eigen(c);
  if (eigen.info() != Eigen::Success)
    throw SolverError(kMethod, "symmetric eigen decomposition did not converge", 0,
                      std::numeric_limits<double>::quiet_NaN());

  BucklingResult result;
  result.reduced_size = static_cast<std::size_t>(reduced);
  for (std::size_t m = 0; m < modes; ++m) {
    const VectorXd v = llt.matrixU().solve(eigen.eigenvectors().col(idx(m)));
    const VectorXd dz = basis * v;
    BucklingMode mode;
    mode.load = eigen.eigenvalues()[idx(m)] * load_unit;
    for (std::size_t j = 0; j < angles; ++j) {
      const double offset = discretisation.scheme == Scheme::Polygon ? 0.5 : 0.0;
      mode.s.push_back(j == n ? column.length : (static_cast<double>(j) + offset) * h * column.length);
      mode.theta.push_back(dz[primal_slot[lag.angle(j)]]);
    }
    normalise(mode);
    result.modes.push_back(std::move(mode));
  }
  return result;
}

}  // namespace rodvv::solvers::elastica2d
