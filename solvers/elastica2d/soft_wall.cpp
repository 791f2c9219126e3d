#include "rodvv/solvers/elastica2d/soft_wall.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/newton.hpp"

namespace rodvv::solvers::elastica2d {

Potential soft_walls(double a, double b) {
  require_positive("wall_gap", a);
  require_positive("wall_softness", b);
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Potential v;
  v.value = [a, b](double, double y) { return std::abs(y) < a ? b / (a - y) + b / (a + y) : inf; };
  v.gradient = [a, b, nan](double, double y) -> Eigen::Vector2d {
    if (!(std::abs(y) < a)) return Eigen::Vector2d(nan, nan);
    const double up = a - y, down = a + y;
    return Eigen::Vector2d(0.0, b / (up * up) - b / (down * down));
  };
  v.hessian = [a, b, nan](double, double y) -> Eigen::Matrix2d {
    Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
    if (!(std::abs(y) < a)) return Eigen::Matrix2d::Constant(nan);
    const double up = a - y, down = a + y;
    h(1, 1) = 2.0 * b / (up * up * up) + 2.0 * b / (down * down * down);
    return h;
  };
  return v;
}

PlanarRodSolution solve_soft_walls(const Problem& problem, const Discretisation& discretisation,
                                   double gap, double softness, const SolverOptions& options,
                                   const InitialGuess& guess, const SoftWallOptions& soft) {
  require_positive("wall_gap", gap);
  require_positive("wall_softness", softness);
  require_positive("soft.start_softness", soft.start_softness);
  require_open_interval("soft.softness_ratio", soft.softness_ratio, 0.0, 1.0);
  validate(options);
  if (problem.potential.active())
    throw InputError("potential", "invalid parameter 'potential': solve_soft_walls sets the potential itself; "
                                  "pass a problem without one");
  // First stage: load/displacement stepping from the guess at the softer of b and b_start.
  validate(problem);
  double b = std::max(softness, soft.start_softness * bending_stiffness_at(problem, 0.0) / problem.length);
  Problem staged = problem;
  staged.potential = soft_walls(gap, b);
  DiscreteLagrangian first(staged, discretisation);
  first.set_load_factor(1.0 / static_cast<double>(options.load_steps));
  Eigen::VectorXd z = detail::initial_state(first, staged, guess);
  for (std::size_t i = 0; i <= first.elements(); ++i)
    if (!(std::abs(z[static_cast<Eigen::Index>(first.y(i))]) < gap))
      throw InputError("guess.theta", "invalid parameter 'guess.theta': the initial state leaves the strip |y| < wall_gap");
  const std::size_t rows = first.rows().size();
  std::vector<double> from(rows), to(rows);
  for (std::size_t k = 0; k < rows; ++k) {
    const BoundaryRow& row = first.rows()[k];
    to[k] = row.target;
    const bool angle_row = first.scheme() == Scheme::Arcs &&
                           (row.dof == first.angle(0) || row.dof == first.angle(first.elements()));
    from[k] = angle_row ? row.target : z[static_cast<Eigen::Index>(row.dof)];
  }
  detail::NewtonState state;
  for (std::size_t step = 1; step <= options.load_steps; ++step) {
    const double lambda = static_cast<double>(step) / static_cast<double>(options.load_steps);
    first.set_load_factor(lambda);
    for (std::size_t k = 0; k < rows; ++k)
      first.set_row_target(k, step == options.load_steps ? to[k] : from[k] + lambda * (to[k] - from[k]));
    detail::newton(first, z, options, state);
  }
  // Continuation in b: the unknowns keep their layout (same supports, same N).
  while (b > softness) {
    b = std::max(softness, b * soft.softness_ratio);
    staged.potential = soft_walls(gap, b);
    const DiscreteLagrangian stage(staged, discretisation);
    detail::newton(stage, z, options, state);
    if (b == softness) {
      PlanarRodSolution sol = detail::fill_solution(stage, z);
      sol.iterations = state.iterations;
      sol.residual = state.residual;
      return sol;
    }
  }
  PlanarRodSolution sol = detail::fill_solution(first, z);
  sol.iterations = state.iterations;
  sol.residual = state.residual;
  return sol;
}

}  // namespace rodvv::solvers::elastica2d
