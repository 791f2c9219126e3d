#include "rodvv/solvers/elastica2d/contact_lcp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/lcp.hpp"

namespace rodvv::solvers::elastica2d::detail {

namespace {

using Eigen::VectorXd;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kArmijo = 1e-4;
constexpr double kMinStep = 0x1p-30;

Eigen::Index idx(std::size_t i) { return static_cast<Eigen::Index>(i); }

Eigen::Vector2d position(const DiscreteLagrangian& lag, const VectorXd& z, std::size_t node) {
  return {z[idx(lag.x(node))], z[idx(lag.y(node))]};
}

// The pairs held by the stabilising penalty rho/2 g_p^2 (held[p]) and, for the line search, the
// pairs the LCP predicts active (selected[p]: lambda+_p > 0).
using Flags = std::vector<char>;

// grad L + rho sum_held g_p grad g_p - G^T lambda (rho = 0: the equilibrium residual F).
VectorXd force_residual(const DiscreteLagrangian& lag, const std::vector<Obstacle>& obstacles,
                        const std::vector<ContactPair>& pairs, const VectorXd& z, const VectorXd& lambda,
                        const Flags& held, double rho) {
  VectorXd f = lag.gradient(z);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const double c = (rho > 0.0 && held[p] ? rho * gap(obstacles[pairs[p].obstacle], position(lag, z, pairs[p].node)) : 0.0) -
                     lambda[idx(p)];
    if (c == 0.0) continue;
    const std::size_t i = pairs[p].node;
    const Eigen::Vector2d dg = gap_gradient(obstacles[pairs[p].obstacle], position(lag, z, i));
    f[idx(lag.x(i))] += c * dg.x();
    f[idx(lag.y(i))] += c * dg.y();
  }
  return f;
}

// The problem's own units (detail::residual_scales): the KKT residual's scales, a contact force's EI / L^2 and a
// gap's L, so that convergence does not depend on L and EI.
struct Units {
  VectorXd residual;
  double force = 1.0, length = 1.0;
  explicit Units(const DiscreteLagrangian& lag)
      : residual(detail::residual_scales(lag)),
        force(lag.node_stiffness(0) / (lag.problem().length * lag.problem().length)),
        length(lag.problem().length) {}
};

// ||Phi||_inf, Phi = (F, min(lambda, g)) each in its units: the convergence measure.
double natural_residual(const DiscreteLagrangian& lag, const std::vector<Obstacle>& obstacles,
                        const std::vector<ContactPair>& pairs, const VectorXd& z, const VectorXd& lambda,
                        const Units& units) {
  double r = force_residual(lag, obstacles, pairs, z, lambda, {}, 0.0).cwiseQuotient(units.residual).lpNorm<Eigen::Infinity>();
  for (std::size_t p = 0; p < pairs.size(); ++p)
    r = std::max(r, std::abs(std::min(lambda[idx(p)] / units.force,
                                      gap(obstacles[pairs[p].obstacle], position(lag, z, pairs[p].node)) / units.length)));
  return r;
}

// 2-norm of the smooth system the Newton step linearises: (F_rho, g_p for selected p, lambda_p
// otherwise). The step is its exact Newton direction, hence a descent direction of this merit.
double selected_merit(const DiscreteLagrangian& lag, const std::vector<Obstacle>& obstacles,
                      const std::vector<ContactPair>& pairs, const VectorXd& z, const VectorXd& lambda,
                      const Flags& held, double rho, const Flags& selected, const Units& units) {
  double sum = force_residual(lag, obstacles, pairs, z, lambda, held, rho).cwiseQuotient(units.residual).squaredNorm();
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const double c = selected[p] ? gap(obstacles[pairs[p].obstacle], position(lag, z, pairs[p].node)) / units.length
                                 : lambda[idx(p)] / units.force;
    sum += c * c;
  }
  return std::sqrt(sum);
}

// Hessian of L + rho/2 sum_held g_p^2 - sum_p lambda_p g_p: node (x, y) blocks only, inside the band.
Eigen::SparseMatrix<double> tangent(const DiscreteLagrangian& lag, const std::vector<Obstacle>& obstacles,
                                    const std::vector<ContactPair>& pairs, const VectorXd& z,
                                    const VectorXd& lambda, const Flags& held, double rho) {
  Eigen::SparseMatrix<double> k = lag.hessian(z);
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const Obstacle& o = obstacles[pairs[p].obstacle];
    const std::size_t i = pairs[p].node;
    const Eigen::Vector2d r = position(lag, z, i);
    Eigen::Matrix2d block = -lambda[idx(p)] * gap_hessian(o, r);
    if (rho > 0.0 && held[p]) {
      const Eigen::Vector2d dg = gap_gradient(o, r);
      block += rho * (dg * dg.transpose() + gap(o, r) * gap_hessian(o, r));
    }
    if (block.isZero(0.0)) continue;
    const Eigen::Index xi = idx(lag.x(i)), yi = idx(lag.y(i));
    t.emplace_back(xi, xi, block(0, 0));
    t.emplace_back(xi, yi, block(0, 1));
    t.emplace_back(yi, xi, block(1, 0));
    t.emplace_back(yi, yi, block(1, 1));
  }
  if (t.empty()) return k;
  Eigen::SparseMatrix<double> c(k.rows(), k.cols());
  c.setFromTriplets(t.begin(), t.end());
  return k + c;
}

// An LCP solution whose natural-map residual exceeds this fraction of max|b| is not taken as a
// Newton step, so that an inaccurate LCP can never silently derail the iteration. Measured on the
// cavity line contact (N = 32 .. 512, polygon and arcs): the accepted solutions <= 7e-9 (N = 512;
// PGS stops at 1e-13), the inaccurate unscaled Lemke solutions (below) 5e-3 .. 2e-1. 1e-6 is a
// factor >= 140 from both.
constexpr double kLcpAccuracy = 1e-6;

// The condensed LCP, with a verified result (contact::solve_lcp_verified: Lemke on W, then on the
// Jacobi-scaled problem if inaccurate). Why the scaling is needed here: diag W spans the nodal
// compliances, from ~h^3 / EI next to a support to ~L^3 / EI mid-span (a ratio ~N^3), and on a line
// contact the Delassus block of the flat run is near-singular (condition ~(run / h)^4). Unscaled, Lemke
// ended on "solutions" with a natural-map residual of 5e-3 .. 2e-1 x max|b| (cavity line contact,
// polygon, once at N = 128, 2-3 times at N = 256, in load steps 7 and 8): a wrong set of loaded pairs
// and a Newton step |dz| ~ 25 on a rod of length 1. The earlier version took these steps: at N = 128 it
// recovered, at N = 256 the iterate became unstable even with its loaded pairs held and the solve ended
// in SolverError. Scaled, the worst residual measured is 6e-9 x max|b| (N = 512).
contact::LcpSolution solve_condensed(const MatX& W, const VecX& b, const ContactOptions& options,
                                     std::size_t& rescaled) {
  return contact::solve_lcp_verified(W, b, options.lcp, options.lcp_settings, kLcpAccuracy, &rescaled);
}

std::string lcp_name(contact::LcpMethod m) {
  return m == contact::LcpMethod::Lemke ? "Lemke" : "projected Gauss-Seidel";
}

}  // namespace

void newton_lcp(const DiscreteLagrangian& lag, const std::vector<Obstacle>& obstacles,
                const std::vector<ContactPair>& pairs, VectorXd& z, VectorXd& lambda,
                const SolverOptions& options, const ContactOptions& contact, NewtonState& state,
                LcpNewtonStats& stats, const std::string& method) {
  // Stiffness scale of the penalty: EI / L^3 (a unit force at a node of a rod of length L moves it
  // by ~L^3 / EI).
  double ei = 0.0;
  for (std::size_t i = 0; i <= lag.elements(); ++i) ei = std::max(ei, lag.node_stiffness(i));
  const double length = lag.problem().length;
  const double rho_start = contact.stabilisation * ei / (length * length * length);

  const Units units(lag);
  std::vector<std::size_t> candidates;
  std::vector<Eigen::Vector2d> normal;  // grad g of each candidate at the iterate
  Flags held(pairs.size()), selected(pairs.size());
  for (std::size_t it = 0;; ++it) {
    const double r = natural_residual(lag, obstacles, pairs, z, lambda, units);
    state.residual = r;
    check_time_budget(method, state.iterations, r);
    if (!std::isfinite(r))
      throw SolverError(method, "contact residual became non-finite", state.iterations, r);
    if (r <= options.tolerance) return;
    if (it == options.max_iterations)
      throw SolverError(method,
                        "Josephy-Newton with the " + lcp_name(contact.lcp) + " LCP did not converge in " +
                            std::to_string(options.max_iterations) + " iterations",
                        state.iterations, r);

    // Candidates: near the obstacle, or loaded. The loaded pairs are the ones held by the penalty.
    candidates.clear();
    normal.clear();
    bool any_held = false;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const Eigen::Vector2d ri = position(lag, z, pairs[p].node);
      const Obstacle& o = obstacles[pairs[p].obstacle];
      held[p] = lambda[idx(p)] > 0.0;
      any_held = any_held || held[p];
      if (held[p] || gap(o, ri) <= contact.candidate_distance) {
        candidates.push_back(p);
        normal.push_back(gap_gradient(o, ri));
      }
    }
    const Eigen::Index m = idx(candidates.size());

    // Condensation (b = g + G dz0, W = G K^-1 G^T column by column); if W is not positive
    // semidefinite (an unstable tangent) or the LCP fails, the penalty is raised x 100, at most
    // kRaises times.
    constexpr int kRaises = 3;
    double rho = any_held ? rho_start : 0.0;
    VectorXd gradient, rhs;
    contact::LcpSolution lcp;
    VecX b(m);
    for (int attempt = 0;; ++attempt) {
      if (!state.lu.factorize(tangent(lag, obstacles, pairs, z, lambda, held, rho)))
        throw SolverError(method, "KKT matrix is singular", state.iterations, r);
      gradient = force_residual(lag, obstacles, pairs, z, VectorXd::Zero(idx(pairs.size())), held, rho);
      const VectorXd dz0 = state.lu.solve(-gradient);
      MatX W(m, m);
      rhs = VectorXd::Zero(idx(lag.size()));
      for (Eigen::Index c = 0; c < m; ++c) {
        const ContactPair& pc = pairs[candidates[static_cast<std::size_t>(c)]];
        const Eigen::Vector2d& nc = normal[static_cast<std::size_t>(c)];
        const Eigen::Index xc = idx(lag.x(pc.node)), yc = idx(lag.y(pc.node));
        b[c] = gap(obstacles[pc.obstacle], position(lag, z, pc.node)) + nc.x() * dz0[xc] + nc.y() * dz0[yc];
        rhs[xc] = nc.x();
        rhs[yc] = nc.y();
        const VectorXd column = state.lu.solve(rhs);
        rhs[xc] = 0.0;
        rhs[yc] = 0.0;
        for (Eigen::Index d = 0; d < m; ++d) {
          const std::size_t node = pairs[candidates[static_cast<std::size_t>(d)]].node;
          const Eigen::Vector2d& nd = normal[static_cast<std::size_t>(d)];
          W(d, c) = nd.x() * column[idx(lag.x(node))] + nd.y() * column[idx(lag.y(node))];
        }
      }
      const MatX Wsym = 0.5 * (W + W.transpose());
      try {
        lcp = solve_condensed(Wsym, b, contact, stats.rescaled);
        break;
      } catch (const std::exception& e) {  // InputError: W not PSD; SolverError: LCP failed
        if (rho == 0.0 || attempt == kRaises)
          throw SolverError(method, "the " + lcp_name(contact.lcp) + " LCP of Newton iteration " + std::to_string(it) +
                                        " failed (penalty " + format_value(rho) + "): " + e.what(),
                            state.iterations, r);
        rho *= 100.0;
      }
    }
    ++stats.solves;
    stats.iterations += lcp.iterations;
    stats.max_iterations = std::max(stats.max_iterations, lcp.iterations);
    stats.candidates = static_cast<std::size_t>(m);
    stats.residual = lcp.residual;
    stats.fischer_burmeister = lcp.fischer_burmeister;
    stats.scale = m == 0 ? 0.0 : b.cwiseAbs().maxCoeff();

    // The step: K dz = -grad L + G^T lambda+ (one solve with the whole right-hand side).
    VectorXd target = VectorXd::Zero(idx(pairs.size()));
    rhs = -gradient;
    for (Eigen::Index c = 0; c < m; ++c) {
      const std::size_t p = candidates[static_cast<std::size_t>(c)];
      const Eigen::Vector2d& nc = normal[static_cast<std::size_t>(c)];
      target[idx(p)] = lcp.lambda[c];
      rhs[idx(lag.x(pairs[p].node))] += lcp.lambda[c] * nc.x();
      rhs[idx(lag.y(pairs[p].node))] += lcp.lambda[c] * nc.y();
    }
    const VectorXd dz = state.lu.solve(rhs);
    ++state.iterations;
    if (!dz.allFinite()) throw SolverError(method, "Newton step is non-finite", state.iterations, r);
    bool changed = false;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      selected[p] = target[idx(p)] > 0.0;
      changed = changed || (selected[p] != held[p]);
    }
    stats.set_changes += changed ? 1 : 0;
    if (dz.lpNorm<Eigen::Infinity>() <= 64.0 * kEps * (1.0 + z.lpNorm<Eigen::Infinity>())) {
      z += dz;
      lambda = target;
      state.residual = natural_residual(lag, obstacles, pairs, z, lambda, units);
      return;
    }
    const VectorXd dlambda = target - lambda;
    const double merit = selected_merit(lag, obstacles, pairs, z, lambda, held, rho, selected, units);
    double alpha = 1.0;
    for (;;) {
      const VectorXd zt = z + alpha * dz;
      const VectorXd lt = alpha == 1.0 ? target : VectorXd(lambda + alpha * dlambda);
      const double mt = selected_merit(lag, obstacles, pairs, zt, lt, held, rho, selected, units);
      if (std::isfinite(mt) && mt <= (1.0 - kArmijo * alpha) * merit) {
        z = zt;
        lambda = lt;
        break;
      }
      alpha *= 0.5;
      if (alpha < kMinStep)
        throw SolverError(method, "line search failed (Josephy-Newton with the " + lcp_name(contact.lcp) + " LCP)",
                          state.iterations, r);
    }
  }
}

}  // namespace rodvv::solvers::elastica2d::detail
