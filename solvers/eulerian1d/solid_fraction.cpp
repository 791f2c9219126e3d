#include "rodvv/solvers/eulerian1d/solid_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::eulerian1d {

namespace {

double evaluate(const ReferenceMap& xi, double x, std::size_t& evaluations) {
  ++evaluations;
  const double value = xi(x);
  if (!std::isfinite(value))
    throw InputError("xi0", "the reference map xi0 must be finite on the grid, but xi0(" +
                                format_value(x) + ") = " + format_value(value));
  return value;
}

// Nodal values, with the strict increase checked between consecutive samples (nodes and
// samples_per_cell - 1 interior points per cell).
VecX sample_checked(const Grid& grid, const ReferenceMap& xi, const MapSampling& sampling,
                    std::size_t& evaluations) {
  require_at_least("samples_per_cell", sampling.samples_per_cell, 1);
  if (!xi) throw InputError("xi0", "the reference map xi0 must be callable (got an empty function)");
  const std::size_t n = sampling.samples_per_cell;
  const double dx = grid.dx();
  VecX nodal(static_cast<Eigen::Index>(grid.nodes()));
  double x_prev = grid.node(0), prev = evaluate(xi, x_prev, evaluations);
  nodal(0) = prev;
  for (std::size_t c = 0; c < grid.cells; ++c) {
    for (std::size_t i = 1; i <= n; ++i) {
      const double x = i == n ? grid.node(c + 1)
                              : grid.node(c) + dx * static_cast<double>(i) / static_cast<double>(n);
      const double value = evaluate(xi, x, evaluations);
      if (!(value > prev))
        throw InputError("xi0", "the reference map xi0 must be strictly increasing on the grid "
                                "(det F = 1/xi_x > 0), but xi0(" + format_value(x) + ") - xi0(" +
                                    format_value(x_prev) + ") = " + format_value(value - prev) +
                                    " <= 0 (in cell " + std::to_string(c) + ")");
      x_prev = x;
      prev = value;
    }
    nodal(static_cast<Eigen::Index>(c + 1)) = prev;
  }
  return nodal;
}

}  // namespace

double locate_material_point(const ReferenceMap& xi, double X, double a, double b,
                             std::size_t* evaluations) {
  std::size_t count = 0;
  double fa = evaluate(xi, a, count), fb = evaluate(xi, b, count);
  if (!(a <= b && fa <= X && X <= fb))
    throw InputError("X", "locate_material_point needs a <= b and xi(a) <= X <= xi(b), got X = " +
                              format_value(X) + " and [xi(a), xi(b)] = [" + format_value(fa) + ", " +
                              format_value(fb) + "]");
  // Halving the interval reaches two adjacent doubles in at most ~1100 steps (the binades down to
  // the subnormals near x = 0); usually ~55. The cap is only a guard against a broken map.
  constexpr int max_halvings = 4096;
  int halvings = 0;
  while (fa < X && X < fb) {
    const double m = a + 0.5 * (b - a);
    if (!(a < m && m < b)) break;  // a and b adjacent: the root is located to round-off
    if (++halvings > max_halvings)
      throw SolverError("eulerian1d: bisection", "no convergence to adjacent doubles", halvings, b - a);
    const double fm = evaluate(xi, m, count);
    if (fm < X)
      a = m, fa = fm;
    else
      b = m, fb = fm;
  }
  if (evaluations) *evaluations += count;
  return X - fa <= fb - X ? a : b;
}

VecX sample_reference_map(const Grid& grid, const ReferenceMap& xi, const MapSampling& sampling) {
  std::size_t evaluations = 0;
  return sample_checked(grid, xi, sampling, evaluations);
}

SolidFraction solid_fraction(const Grid& grid, const Material& material, const ReferenceMap& xi,
                             const MapSampling& sampling) {
  require_positive("length", material.length);
  require_positive("dx", grid.dx());
  SolidFraction out;
  const VecX nodal = sample_checked(grid, xi, sampling, out.evaluations);
  const double L0 = material.length;
  const Eigen::Index last = nodal.size() - 1;
  if (!(nodal(0) <= 0.0 && nodal(last) >= L0))
    throw InputError("xi0", "the solid 0 <= xi <= L0 = " + format_value(L0) +
                                " must lie inside the grid: need xi0(x_min) <= 0 and xi0(x_max) >= L0, got " +
                                format_value(nodal(0)) + " and " + format_value(nodal(last)));

  // The cell k with xi_k < X <= xi_{k+1} (or xi_0 = X): the first node at or above X closes it.
  auto end_point = [&](double X) {
    const auto* begin = nodal.data();
    const Eigen::Index upper = std::lower_bound(begin, begin + nodal.size(), X) - begin;
    if (upper == 0) return grid.node(0);  // xi(x_min) = X exactly
    const auto k = static_cast<std::size_t>(upper - 1);
    return locate_material_point(xi, X, grid.node(k), grid.node(k + 1), &out.evaluations);
  };
  out.x_left = end_point(0.0);
  out.x_right = end_point(L0);

  const auto cells = static_cast<Eigen::Index>(grid.cells);
  const double dx = grid.dx();
  auto clip = [L0](double value) { return std::min(std::max(value, 0.0), L0); };
  out.fraction.resize(cells);
  out.solid_length.resize(cells);
  for (Eigen::Index c = 0; c < cells; ++c) {
    const double x0 = grid.node(static_cast<std::size_t>(c)), x1 = grid.node(static_cast<std::size_t>(c + 1));
    out.solid_length(c) = clip(nodal(c + 1)) - clip(nodal(c));
    if (out.x_left <= x0 && x1 <= out.x_right) {
      out.fraction(c) = 1.0;  // whole cell solid: exactly 1, as the clipped linear path gives
    } else {
      const double lo = std::max(x0, out.x_left), hi = std::min(x1, out.x_right);
      out.fraction(c) = hi > lo ? (hi - lo) / dx : 0.0;
    }
  }
  return out;
}

}  // namespace rodvv::solvers::eulerian1d
