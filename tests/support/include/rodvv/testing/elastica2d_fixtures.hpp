// Shared helpers of the planar-rod solver tests (tests/solvers/test_elastica2d*.cpp): the name of an
// InputError's parameter, the observed order of an error sequence, scheme names for parameterised
// suites, the pinned-pinned column problem, tight Newton options, and the central-difference check
// of the discrete Lagrangian's gradient and Hessian. One copy here instead of one per test file.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/elastica2d/discretisation.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"
#include "rodvv/testing/input_error.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace rodvv::testing {

// Least-squares slope of log|error| against log h = log(1/N), negated: the observed order in 1/N.
inline double observed_order(const std::vector<std::size_t>& levels, const std::vector<double>& errors) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(levels.size());
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const double lx = std::log(1.0 / static_cast<double>(levels[i]));
    const double ly = std::log(std::abs(errors[i]));
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

namespace elastica2d {

namespace e2 = rodvv::solvers::elastica2d;

// Test-name suffix of a scheme in INSTANTIATE_TEST_SUITE_P.
inline std::string name_of(e2::Scheme scheme) {
  return scheme == e2::Scheme::Polygon ? "Polygon" : "Arcs";
}

// Pinned at s = 0, roller (Sliding, on y = 0, x free) at s = L with the dead compressive load P
// along -x (load control). PHYSICS.md §3.2.
inline e2::Problem pinned_column(double load) {
  e2::Problem p;
  p.start.support = e2::Support::Pinned;
  p.end.support = e2::Support::Sliding;
  p.end.load.force_x = -load;
  return p;
}

// Newton tolerance 1e-12: below every discretisation error the tests compare (>= 1e-8).
inline e2::SolverOptions tight() {
  e2::SolverOptions o;
  o.tolerance = 1e-12;
  return o;
}

// Reproducible state with every entry in [-0.8, 0.8]: angles, positions, multipliers all O(1),
// angle differences up to ~1.6.
inline Eigen::VectorXd random_state(const e2::DiscreteLagrangian& lag, unsigned seed) {
  std::srand(seed);
  return 0.8 * Eigen::VectorXd::Random(static_cast<Eigen::Index>(lag.size()));
}

// Max |analytic - central difference| over gradient and the given Hessian, relative to
// max(1, |difference quotient|), in units of d^2 with d = cbrt(eps) (1 + |z_j|). Truncation is
// ~ d^2 |f'''| / 6 and round-off ~ eps |f| / d ~ d^2 |f|, so O(1) derivatives give a few units.
inline double derivative_mismatch(const e2::DiscreteLagrangian& lag, const Eigen::VectorXd& z,
                                  const Eigen::MatrixXd& hess) {
  const double d0 = std::cbrt(kEpsilon);
  const Eigen::VectorXd g = lag.gradient(z);
  double worst = 0.0;
  for (Eigen::Index j = 0; j < z.size(); ++j) {
    const double d = d0 * (1.0 + std::abs(z[j]));
    Eigen::VectorXd zp = z, zm = z;
    zp[j] += d;
    zm[j] -= d;
    const double fd = (lag.value(zp) - lag.value(zm)) / (2 * d);
    worst = std::max(worst, std::abs(g[j] - fd) / std::max(1.0, std::abs(fd)) / (d * d));
    const Eigen::VectorXd col = (lag.gradient(zp) - lag.gradient(zm)) / (2 * d);
    for (Eigen::Index i = 0; i < z.size(); ++i)
      worst = std::max(worst, std::abs(hess(i, j) - col[i]) / std::max(1.0, std::abs(col[i])) / (d * d));
  }
  return worst;
}

}  // namespace elastica2d
}  // namespace rodvv::testing
