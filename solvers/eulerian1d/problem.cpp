#include "rodvv/solvers/eulerian1d/problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::eulerian1d {

double Material::wave_speed() const { return std::sqrt(kappa / rho0); }

VecX linear_reference_map(const Grid& grid, double x_left, double stretch) {
  require_finite("x_left", x_left);
  require_positive("stretch", stretch);
  VecX xi(static_cast<Eigen::Index>(grid.nodes()));
  for (std::size_t j = 0; j < grid.nodes(); ++j)
    xi(static_cast<Eigen::Index>(j)) = (grid.node(j) - x_left) / stretch;
  return xi;
}

namespace {

// Where the initial solid ends: xi0 = X, by linear interpolation (xi0 already checked monotone).
double initial_position(const Grid& grid, const VecX& xi, double X) {
  for (Eigen::Index j = 0; j + 1 < xi.size(); ++j)
    if (xi(j) <= X && X <= xi(j + 1))
      return grid.node(static_cast<std::size_t>(j)) + grid.dx() * (X - xi(j)) / (xi(j + 1) - xi(j));
  return std::nan("");
}

}  // namespace

double least_cell_updates(const Grid& grid, const Material& material, const Settings& settings) {
  const double least_steps = settings.t_end * material.wave_speed() / (settings.cfl * grid.dx());
  return least_steps * static_cast<double>(grid.cells);
}

void validate(const Problem& problem, const Settings& settings) {
  const Grid& grid = problem.grid;
  require_finite("x_min", grid.x_min);
  require_finite("x_max", grid.x_max);
  require_greater("x_max", grid.x_max, grid.x_min);
  require_at_least("cells", grid.cells, 2);
  require_positive("dx", grid.dx());
  require_positive("rho0", problem.material.rho0);
  require_positive("kappa", problem.material.kappa);
  require_positive("length", problem.material.length);
  require_finite("gravity", problem.gravity);
  require_positive("t_end", settings.t_end);
  require_positive("max_cell_updates", settings.max_cell_updates);
  // First-order upwind is stable for Courant numbers up to 1.
  if (!(settings.cfl > 0.0 && settings.cfl <= 1.0))
    throw InputError("cfl", "invalid parameter 'cfl' = " + format_value(settings.cfl) +
                                ": must be in (0, 1] (the upwind stability limit)");
  for (double t : settings.snapshot_times) require_closed_interval("snapshot_times", t, 0.0, settings.t_end);

  const auto n = static_cast<Eigen::Index>(grid.nodes());
  if (problem.xi0.size() != n)
    throw InputError("xi0", "the initial reference map xi0 must have one value per node (" +
                                std::to_string(n) + "), got " + std::to_string(problem.xi0.size()));
  if (problem.v0.size() != n)
    throw InputError("v0", "the initial velocity v0 must have one value per node (" + std::to_string(n) +
                               "), got " + std::to_string(problem.v0.size()));
  if (!problem.xi0.allFinite()) throw InputError("xi0", "the initial reference map xi0 must be finite");
  if (!problem.v0.allFinite()) throw InputError("v0", "the initial velocity v0 must be finite");
  for (Eigen::Index j = 0; j + 1 < n; ++j)
    if (!(problem.xi0(j + 1) > problem.xi0(j)))
      throw InputError("xi0", "the reference map must be strictly increasing (det F = 1/xi_x > 0), but "
                              "xi0[" + std::to_string(j + 1) + "] - xi0[" + std::to_string(j) + "] = " +
                                  format_value(problem.xi0(j + 1) - problem.xi0(j)) + " <= 0");
  const double L0 = problem.material.length;
  if (!(problem.xi0(0) <= 0.0 && problem.xi0(n - 1) >= L0))
    throw InputError("xi0", "the initial solid 0 <= xi <= L0 = " + format_value(L0) +
                                " must lie inside the grid: need xi0[0] <= 0 and xi0[last] >= L0, got " +
                                format_value(problem.xi0(0)) + " and " + format_value(problem.xi0(n - 1)));
  // A wall may touch the initial solid: its ends are interpolated from xi0, so "touching" is
  // decided to within 16 eps of the grid coordinates.
  const double slack = 16.0 * std::numeric_limits<double>::epsilon() *
                       std::max({std::abs(grid.x_min), std::abs(grid.x_max), grid.dx()});
  const double x_left = initial_position(grid, problem.xi0, 0.0) + slack;
  const double x_right = initial_position(grid, problem.xi0, L0) - slack;
  if (problem.left_wall) {
    const double w = *problem.left_wall;
    if (!std::isfinite(w) || w < grid.x_min || w > x_left)
      throw InputError("left_wall", "invalid parameter 'left_wall' = " + format_value(w) +
                                        ": must lie in [x_min, left end of the initial solid] = [" +
                                        format_value(grid.x_min) + ", " + format_value(x_left) +
                                        "] (a barrier may not overlap the initial solid)");
  }
  if (problem.right_wall) {
    const double w = *problem.right_wall;
    if (!std::isfinite(w) || w > grid.x_max || w < x_right)
      throw InputError("right_wall", "invalid parameter 'right_wall' = " + format_value(w) +
                                         ": must lie in [right end of the initial solid, x_max] = [" +
                                         format_value(x_right) + ", " + format_value(grid.x_max) +
                                         "] (a barrier may not overlap the initial solid)");
  }
}

}  // namespace rodvv::solvers::eulerian1d
