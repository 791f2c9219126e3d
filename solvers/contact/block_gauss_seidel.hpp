#pragma once
// The block Gauss-Seidel of cone_complementarity.hpp, written once for both representations of the
// Delassus operator W: the dense matrix and the factored W = sum_b H_b M_b H_b^T + C
// (factored_delassus.hpp). An operator provides
//   contacts()            the number of contacts n,
//   block(k)              W_kk (3 x 3, symmetric positive definite),
//   product(k, r)         (W r)_k for the current r,
//   changed(k, delta)     r_k moved by delta (the factored form keeps M H^T r per body up to date),
//   velocities(r)         W r, all contacts (the residual).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/cone_complementarity.hpp"

namespace rodvv::solvers::contact::detail {

// The scaled natural-map residual (cone_complementarity.hpp) of r with u = W r + b.
template <class Operator>
double natural_map_residual(const Operator& W, const VecX& b, const VecX& mu, const VecX& r, const VecX& u,
                            ConeLaw law) {
  double worst = 0.0, scale = 0.0;
  for (Eigen::Index k = 0; k < mu.size(); ++k) {
    const Mat3 block = W.block(k);
    scale = std::max(scale, b.segment<3>(3 * k).norm() / block.norm());
    worst = std::max(worst, contact_natural_map(block, r.segment<3>(3 * k), u.segment<3>(3 * k), mu[k], law));
  }
  return scale > 0.0 ? worst / scale : worst;
}

template <class Operator>
ConeSolution block_gauss_seidel(Operator& W, const VecX& b, const VecX& mu, ConeLaw law, const ConeSettings& settings) {
  require_open_interval("tolerance", settings.tolerance, 0.0, 1.0);
  require_at_least("max_sweeps", settings.max_sweeps, 1);
  const Eigen::Index n = mu.size();
  const char* method = law == ConeLaw::Coulomb ? "block Gauss-Seidel (Coulomb)" : "block Gauss-Seidel (SOC)";
  ConeSolution solution;
  solution.r = VecX::Zero(3 * n);
  double scale = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) scale = std::max(scale, b.segment<3>(3 * k).norm() / W.block(k).norm());
  if (n == 0 || scale == 0.0) {  // no contact, or nothing pushes: r = 0 is the solution
    solution.u = b;
    return solution;
  }
  // Each contact's block and its inverse, once (the local stick solve needs W_kk^-1 every sweep).
  std::vector<Mat3> blocks(static_cast<std::size_t>(n)), inverses(static_cast<std::size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k) {
    blocks[std::size_t(k)] = W.block(k);
    inverses[std::size_t(k)] = blocks[std::size_t(k)].inverse();
  }
  // The residual costs another pass over W (as much as a sweep: the dense product, or for a bundle the
  // memory traffic of the factors), so it is evaluated on a schedule: after the first sweep, then at
  // half the sweeps its observed linear rate between the last two evaluations predicts to the
  // tolerance, at most a quarter of the sweeps so far ahead (a rate seen on a plateau may be too slow
  // by any factor; the cap bounds the sweeps done beyond convergence to a quarter). Near the tolerance
  // it is evaluated every sweep, and at the last one; the stopping test is the full residual's.
  std::size_t next_check = 1, last_check = 0;
  double last_residual = 0.0;
  for (std::size_t sweep = 1; sweep <= settings.max_sweeps; ++sweep) {
    for (Eigen::Index k = 0; k < n; ++k) {
      const Mat3& block = blocks[std::size_t(k)];
      const Vec3 previous = solution.r.segment<3>(3 * k);
      const Vec3 local_b = b.segment<3>(3 * k) + W.product(k, solution.r) - block * previous;
      const Vec3 next = solve_local_cone_problem(block, inverses[std::size_t(k)], local_b, mu[k], law, &previous);
      solution.r.segment<3>(3 * k) = next;
      W.changed(k, next - previous);
    }
    solution.sweeps = sweep;
    if (sweep < next_check && sweep < settings.max_sweeps) {
      check_time_budget(method, sweep, solution.residual);
      continue;
    }
    solution.u = W.velocities(solution.r) + b;
    solution.residual = natural_map_residual(W, b, mu, solution.r, solution.u, law);
    check_time_budget(method, sweep, solution.residual);
    if (solution.residual <= settings.tolerance) break;
    if (sweep == settings.max_sweeps)
      throw SolverError(method, "no convergence in " + std::to_string(sweep) + " sweeps (natural-map residual " +
                                    format_value(solution.residual) + " > tolerance " +
                                    format_value(settings.tolerance) + ")",
                        sweep, solution.residual);
    std::size_t ahead = 1;
    if (last_check > 0 && solution.residual < last_residual) {
      const double rate = std::log(solution.residual / last_residual) / double(sweep - last_check);  // < 0
      const double predicted = std::log(settings.tolerance / solution.residual) / rate;
      ahead = std::clamp<std::size_t>(std::size_t(0.5 * predicted), 1, std::max<std::size_t>(1, sweep / 4));
    }
    last_check = sweep;
    last_residual = solution.residual;
    next_check = sweep + ahead;
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    const Vec3 rk = solution.r.segment<3>(3 * k);
    solution.cone_violation =
        std::max(solution.cone_violation, std::max(0.0, std::hypot(rk[1], rk[2]) - mu[k] * rk[0]) / scale);
  }
  return solution;
}

}  // namespace rodvv::solvers::contact::detail
