#include "rodvv/solvers/elastica2d/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/banded_lu.hpp"
#include "rodvv/solvers/elastica2d/contact_lcp.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/newton.hpp"

namespace rodvv::solvers::elastica2d {

namespace {

using Eigen::VectorXd;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kArmijo = 1e-4;
constexpr double kMinStep = 0x1p-30;

struct Pair {
  std::size_t node = 0;
  std::size_t obstacle = 0;
  bool operator<(const Pair& o) const {
    return node != o.node ? node < o.node : obstacle < o.obstacle;
  }
  bool operator==(const Pair& o) const { return node == o.node && obstacle == o.obstacle; }
};

// The KKT system of the discrete Lagrangian augmented by one multiplier row per active pair,
// inserted right after the node's y so that the band is kept.
class AugmentedSystem {
 public:
  AugmentedSystem(const DiscreteLagrangian& lag, const std::vector<Obstacle>& obstacles,
                  std::vector<Pair> active)
      : lag_(lag), obstacles_(obstacles), active_(std::move(active)) {
    std::sort(active_.begin(), active_.end());
    const std::size_t n = lag.size();
    map_.resize(n);
    row_.resize(active_.size());
    std::size_t shift = 0, p = 0;
    for (std::size_t k = 0; k < n; ++k) {
      map_[k] = k + shift;
      while (p < active_.size() && lag.y(active_[p].node) == k) {
        row_[p] = k + shift + 1;
        ++shift;
        ++p;
      }
    }
    size_ = n + active_.size();
  }

  const std::vector<Pair>& active() const noexcept { return active_; }
  std::size_t size() const noexcept { return size_; }

  // Each residual component's scale in the problem's own units (detail::residual_scales; a gap row is a
  // length, L), so that convergence does not depend on L and EI.
  VectorXd residual_scales() const {
    const VectorXd kkt = detail::residual_scales(lag_);
    VectorXd scale = VectorXd::Constant(idx(size_), lag_.problem().length);
    for (std::size_t k = 0; k < map_.size(); ++k) scale[idx(map_[k])] = kkt[idx(k)];
    return scale;
  }

  VectorXd pack(const VectorXd& z, const std::vector<double>& lambda) const {
    VectorXd w(static_cast<Eigen::Index>(size_));
    for (std::size_t k = 0; k < map_.size(); ++k) w[idx(map_[k])] = z[idx(k)];
    for (std::size_t p = 0; p < active_.size(); ++p) w[idx(row_[p])] = lambda[p];
    return w;
  }
  void unpack(const VectorXd& w, VectorXd& z, std::vector<double>& lambda) const {
    for (std::size_t k = 0; k < map_.size(); ++k) z[idx(k)] = w[idx(map_[k])];
    lambda.resize(active_.size());
    for (std::size_t p = 0; p < active_.size(); ++p) lambda[p] = w[idx(row_[p])];
  }

  Eigen::Vector2d position(const VectorXd& w, std::size_t node) const {
    return {w[idx(map_[lag_.x(node)])], w[idx(map_[lag_.y(node)])]};
  }

  VectorXd residual(const VectorXd& w, VectorXd& z) const {
    std::vector<double> lambda;
    unpack(w, z, lambda);
    const VectorXd g = lag_.gradient(z);
    VectorXd f(static_cast<Eigen::Index>(size_));
    for (std::size_t k = 0; k < map_.size(); ++k) f[idx(map_[k])] = g[idx(k)];
    for (std::size_t p = 0; p < active_.size(); ++p) {
      const Obstacle& o = obstacles_[active_[p].obstacle];
      const std::size_t i = active_[p].node;
      const Eigen::Vector2d r = position(w, i);
      const Eigen::Vector2d dg = gap_gradient(o, r);
      f[idx(map_[lag_.x(i)])] -= lambda[p] * dg.x();
      f[idx(map_[lag_.y(i)])] -= lambda[p] * dg.y();
      f[idx(row_[p])] = -gap(o, r);
    }
    return f;
  }

  Eigen::SparseMatrix<double> jacobian(const VectorXd& w, const VectorXd& z) const {
    using T = Eigen::Triplet<double>;
    const Eigen::SparseMatrix<double> h = lag_.hessian(z);
    std::vector<T> t;
    t.reserve(static_cast<std::size_t>(h.nonZeros()) + 8 * active_.size());
    for (Eigen::Index c = 0; c < h.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(h, c); it; ++it)
        t.emplace_back(idx(map_[static_cast<std::size_t>(it.row())]),
                       idx(map_[static_cast<std::size_t>(it.col())]), it.value());
    for (std::size_t p = 0; p < active_.size(); ++p) {
      const Obstacle& o = obstacles_[active_[p].obstacle];
      const std::size_t i = active_[p].node;
      const Eigen::Vector2d r = position(w, i);
      const Eigen::Vector2d dg = gap_gradient(o, r);
      const Eigen::Matrix2d hg = w[idx(row_[p])] * gap_hessian(o, r);
      const Eigen::Index xi = idx(map_[lag_.x(i)]), yi = idx(map_[lag_.y(i)]), li = idx(row_[p]);
      t.emplace_back(xi, xi, -hg(0, 0));
      t.emplace_back(xi, yi, -hg(0, 1));
      t.emplace_back(yi, xi, -hg(1, 0));
      t.emplace_back(yi, yi, -hg(1, 1));
      t.emplace_back(xi, li, -dg.x());
      t.emplace_back(li, xi, -dg.x());
      t.emplace_back(yi, li, -dg.y());
      t.emplace_back(li, yi, -dg.y());
    }
    Eigen::SparseMatrix<double> j(idx(size_), idx(size_));
    j.setFromTriplets(t.begin(), t.end());
    return j;
  }

 private:
  static Eigen::Index idx(std::size_t i) { return static_cast<Eigen::Index>(i); }
  const DiscreteLagrangian& lag_;
  const std::vector<Obstacle>& obstacles_;
  std::vector<Pair> active_;
  std::vector<std::size_t> map_, row_;
  std::size_t size_ = 0;
};

// Newton on the augmented KKT system with a fixed active set (same safeguards and the same scaled residual
// and merit as detail::newton: ||D f||, D = 1 / residual scale).
void newton_active(const AugmentedSystem& sys, VectorXd& z, std::vector<double>& lambda,
                   const SolverOptions& options, detail::NewtonState& state,
                   const std::string& method) {
  VectorXd w = sys.pack(z, lambda);
  VectorXd scratch = z;
  const VectorXd scale = sys.residual_scales();
  const auto scaled = [&scale](const VectorXd& f) { return f.cwiseQuotient(scale).eval(); };
  for (std::size_t it = 0;; ++it) {
    const VectorXd f = sys.residual(w, scratch);
    const double r = scaled(f).lpNorm<Eigen::Infinity>();
    state.residual = r;
    check_time_budget(method, state.iterations, r);
    if (!std::isfinite(r))
      throw SolverError(method, "KKT residual with contact became non-finite", state.iterations, r);
    if (r <= options.tolerance) break;
    if (it == options.max_iterations)
      throw SolverError(method,
                        "Newton with " + std::to_string(sys.active().size()) +
                            " active contacts did not converge in " +
                            std::to_string(options.max_iterations) + " iterations",
                        state.iterations, r);
    if (!state.lu.factorize(sys.jacobian(w, scratch)))
      throw SolverError(method, "KKT matrix with contact rows is singular", state.iterations, r);
    const VectorXd dw = state.lu.solve(-f);
    ++state.iterations;
    if (!dw.allFinite()) throw SolverError(method, "Newton step is non-finite", state.iterations, r);
    if (dw.lpNorm<Eigen::Infinity>() <= 64.0 * kEps * (1.0 + w.lpNorm<Eigen::Infinity>())) {
      w += dw;
      state.residual = scaled(sys.residual(w, scratch)).lpNorm<Eigen::Infinity>();
      break;
    }
    const double merit = scaled(f).norm();
    double alpha = 1.0;
    for (;;) {
      const VectorXd trial = w + alpha * dw;
      const double m = scaled(sys.residual(trial, scratch)).norm();
      if (std::isfinite(m) && m <= (1.0 - kArmijo * alpha) * merit) {
        w = trial;
        break;
      }
      alpha *= 0.5;
      if (alpha < kMinStep)
        throw SolverError(method, "line search failed with contact rows", state.iterations, r);
    }
  }
  sys.unpack(w, z, lambda);
}

// Does obstacle o act on node i?
bool acts_on(const Obstacle& o, double s) { return s >= o.s_min && s <= o.s_max; }

double node_s(const DiscreteLagrangian& lag, std::size_t i) {
  return i == lag.elements() ? lag.problem().length : static_cast<double>(i) * lag.element_length();
}

Eigen::Vector2d node_position(const DiscreteLagrangian& lag, const VectorXd& z, std::size_t i) {
  return {z[static_cast<Eigen::Index>(lag.x(i))], z[static_cast<Eigen::Index>(lag.y(i))]};
}

// Round-off of a gap: 64 eps of the lengths it is computed from (L and the largest coordinate).
double gap_tolerance(const DiscreteLagrangian& lag, const VectorXd& z) {
  double largest = 0.0;
  for (std::size_t i = 0; i <= lag.elements(); ++i) largest = std::max(largest, node_position(lag, z, i).cwiseAbs().maxCoeff());
  return 64.0 * kEps * (lag.problem().length + largest);
}

}  // namespace

void validate(const ContactOptions& options) {
  require_at_least("contact.max_active_set_iterations", options.max_active_set_iterations, 1);
  if (options.method != ContactMethod::ActiveSet && options.method != ContactMethod::NewtonLcp)
    throw InputError("contact.method", "invalid parameter 'contact.method': must be ActiveSet or NewtonLcp");
  if (options.lcp != contact::LcpMethod::Lemke && options.lcp != contact::LcpMethod::ProjectedGaussSeidel)
    throw InputError("contact.lcp", "invalid parameter 'contact.lcp': must be Lemke or ProjectedGaussSeidel");
  require_open_interval("contact.lcp_settings.tolerance", options.lcp_settings.tolerance, 0.0, 1.0);
  require_at_least("contact.lcp_settings.max_iterations", options.lcp_settings.max_iterations, 1);
  if (!(options.candidate_distance > 0.0))  // +inf allowed (every pair); NaN and <= 0 are not
    throw InputError("contact.candidate_distance",
                     "invalid parameter 'contact.candidate_distance' = " + format_value(options.candidate_distance) +
                         ": must be > 0 (+inf = every pair)");
  require_non_negative("contact.stabilisation", options.stabilisation);
}

ContactSolution solve_static_contact(const Problem& problem, const Discretisation& discretisation,
                                     const std::vector<Obstacle>& obstacles,
                                     const SolverOptions& options, const InitialGuess& guess,
                                     const ContactOptions& contact) {
  validate(options);
  validate(contact);
  for (std::size_t o = 0; o < obstacles.size(); ++o)
    validate(obstacles[o], "obstacles[" + std::to_string(o) + "]");
  DiscreteLagrangian lag(problem, discretisation);
  const std::size_t n = lag.elements();
  // A node's contact force in the problem's units, EI / L^2 (the active set drops forces below -tolerance of it).
  const double force_unit = lag.node_stiffness(0) / (problem.length * problem.length);
  const bool lcp = contact.method == ContactMethod::NewtonLcp;
  const std::string method =
      detail::method_name(discretisation.scheme) + "-contact" +
      (lcp ? (contact.lcp == contact::LcpMethod::Lemke ? "-lcp-lemke" : "-lcp-pgs") : "");
  lag.set_load_factor(1.0 / static_cast<double>(options.load_steps));
  VectorXd z = detail::initial_state(lag, problem, guess);

  // The initial state must be admissible.
  const double tol_gap = gap_tolerance(lag, z);
  for (std::size_t i = 0; i <= n; ++i)
    for (std::size_t o = 0; o < obstacles.size(); ++o) {
      if (!acts_on(obstacles[o], node_s(lag, i))) continue;
      const double g = gap(obstacles[o], node_position(lag, z, i));
      if (g < -tol_gap)
        throw InputError("guess.theta", "invalid parameter 'guess.theta': the initial state penetrates obstacles[" +
                                            std::to_string(o) + "] at node " + std::to_string(i) +
                                            " (gap " + format_value(g) +
                                            " < 0); start from an admissible shape");
    }

  const std::size_t rows = lag.rows().size();
  std::vector<double> from(rows), to(rows);
  for (std::size_t k = 0; k < rows; ++k) {
    const BoundaryRow& row = lag.rows()[k];
    to[k] = row.target;
    const bool angle_row =
        lag.scheme() == Scheme::Arcs && (row.dof == lag.angle(0) || row.dof == lag.angle(n));
    from[k] = angle_row ? row.target : z[static_cast<Eigen::Index>(row.dof)];
  }

  // NewtonLcp: every acting (node, obstacle) pair with its force.
  std::vector<detail::ContactPair> pairs;
  if (lcp)
    for (std::size_t i = 0; i <= n; ++i)
      for (std::size_t o = 0; o < obstacles.size(); ++o)
        if (acts_on(obstacles[o], node_s(lag, i))) pairs.push_back({i, o});
  VectorXd pair_force = VectorXd::Zero(static_cast<Eigen::Index>(pairs.size()));
  detail::LcpNewtonStats lcp_stats;

  detail::NewtonState state;
  std::vector<Pair> active;
  std::vector<double> lambda;
  std::size_t updates = 0;
  const auto steps = options.load_steps;
  for (std::size_t step = 1; step <= steps; ++step) {
    const double load = static_cast<double>(step) / static_cast<double>(steps);
    lag.set_load_factor(load);
    for (std::size_t k = 0; k < rows; ++k)
      lag.set_row_target(k, step == steps ? to[k] : from[k] + load * (to[k] - from[k]));
    if (lcp) {
      detail::newton_lcp(lag, obstacles, pairs, z, pair_force, options, contact, state, lcp_stats, method);
      continue;
    }
    for (std::size_t sweep = 0;; ++sweep) {
      AugmentedSystem sys(lag, obstacles, active);
      // lambda follows the sorted order of sys.active(); `active` was kept sorted.
      newton_active(sys, z, lambda, options, state, method);
      // Active-set update (primal-dual): drop negative multipliers, add penetrating pairs.
      std::vector<Pair> next;
      for (std::size_t p = 0; p < active.size(); ++p)
        if (lambda[p] >= -options.tolerance * force_unit) next.push_back(active[p]);
      // Per obstacle, each run of consecutive penetrating inactive nodes contributes its deepest
      // node only: adding a whole run at once over-constrains the rod (a straight rod pushed
      // through a disk cannot follow its arc with every node), and the run's other nodes come in
      // on later updates if they still penetrate.
      const double tol = gap_tolerance(lag, z);
      for (std::size_t o = 0; o < obstacles.size(); ++o) {
        std::size_t deepest = 0;
        double depth = -tol;
        auto close_run = [&] {
          if (depth < -tol) next.push_back({deepest, o});
          depth = -tol;
        };
        for (std::size_t i = 0; i <= n; ++i) {
          const Pair pair{i, o};
          const bool candidate = acts_on(obstacles[o], node_s(lag, i)) &&
                                 !std::binary_search(active.begin(), active.end(), pair);
          const double g = candidate ? gap(obstacles[o], node_position(lag, z, i)) : 0.0;
          if (!(g < -tol)) {
            close_run();
            continue;
          }
          if (g < depth) {
            depth = g;
            deepest = i;
          }
        }
        close_run();
      }
      std::sort(next.begin(), next.end());
      if (next == active) break;
      ++updates;
      if (sweep + 1 >= contact.max_active_set_iterations)
        throw SolverError(method,
                          "active set did not settle after " +
                              std::to_string(contact.max_active_set_iterations) + " updates",
                          state.iterations, state.residual);
      // Carry the multipliers of the pairs that stay; new pairs start at 0.
      std::vector<double> carried(next.size(), 0.0);
      for (std::size_t q = 0; q < next.size(); ++q) {
        const auto it = std::lower_bound(active.begin(), active.end(), next[q]);
        if (it != active.end() && *it == next[q])
          carried[q] = lambda[static_cast<std::size_t>(it - active.begin())];
      }
      active = std::move(next);
      lambda = std::move(carried);
    }
  }

  ContactSolution out;
  out.rod = detail::fill_solution(lag, z);
  out.rod.method = method;
  out.rod.iterations = state.iterations;
  out.rod.residual = state.residual;
  out.active_set_iterations = lcp ? lcp_stats.set_changes : updates;
  if (lcp) {
    // Report the pairs that carry a force or touch their obstacle to round-off, as active pairs.
    const double touching = gap_tolerance(lag, z);
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const double f = pair_force[static_cast<Eigen::Index>(p)];
      if (f > 0.0 || gap(obstacles[pairs[p].obstacle], node_position(lag, z, pairs[p].node)) <= touching) {
        active.push_back({pairs[p].node, pairs[p].obstacle});
        lambda.push_back(f);
      }
    }
    out.lcp_solves = lcp_stats.solves;
    out.lcp_iterations = lcp_stats.iterations;
    out.lcp_max_iterations = lcp_stats.max_iterations;
    out.lcp_candidates = lcp_stats.candidates;
    out.lcp_residual = lcp_stats.residual;
    out.lcp_fischer_burmeister = lcp_stats.fischer_burmeister;
    out.lcp_scale = lcp_stats.scale;
    out.lcp_rescaled = lcp_stats.rescaled;
  }
  out.contact_force_x.assign(n + 1, 0.0);
  out.contact_force_y.assign(n + 1, 0.0);
  out.min_gap.assign(n + 1, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i <= n; ++i)
    for (std::size_t o = 0; o < obstacles.size(); ++o)
      if (acts_on(obstacles[o], node_s(lag, i)))
        out.min_gap[i] = std::min(out.min_gap[i], gap(obstacles[o], node_position(lag, z, i)));
  for (std::size_t p = 0; p < active.size(); ++p) {
    NodeContact c;
    c.node = active[p].node;
    c.obstacle = active[p].obstacle;
    c.force = lambda[p];
    const Eigen::Vector2d r = node_position(lag, z, c.node);
    c.gap = gap(obstacles[c.obstacle], r);
    c.direction = gap_gradient(obstacles[c.obstacle], r);
    out.contact_force_x[c.node] += c.force * c.direction.x();
    out.contact_force_y[c.node] += c.force * c.direction.y();
    out.contacts.push_back(c);
  }
  // |min(lambda, g)| over every acting pair (lambda = 0 off the contacts).
  for (std::size_t i = 0; i <= n; ++i)
    for (std::size_t o = 0; o < obstacles.size(); ++o) {
      if (!acts_on(obstacles[o], node_s(lag, i))) continue;
      const auto it = std::lower_bound(active.begin(), active.end(), Pair{i, o});
      const double f = it != active.end() && *it == Pair{i, o}
                           ? lambda[static_cast<std::size_t>(it - active.begin())] : 0.0;
      out.complementarity_residual = std::max(
          out.complementarity_residual, std::abs(std::min(f, gap(obstacles[o], node_position(lag, z, i)))));
    }
  return out;
}

}  // namespace rodvv::solvers::elastica2d
