#include "rodvv/solvers/eulerian1d/discretisation.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"

namespace rodvv::solvers::eulerian1d {

CellFields cell_fields(const Grid& grid, const Material& material, const VecX& xi) {
  const auto cells = static_cast<Eigen::Index>(grid.cells);
  const double dx = grid.dx(), L0 = material.length;
  auto clip = [L0](double value) { return std::min(std::max(value, 0.0), L0); };
  CellFields f{VecX(cells), VecX(cells), VecX(cells), VecX(cells)};
  for (Eigen::Index c = 0; c < cells; ++c) {
    const double dxi = xi(c + 1) - xi(c);
    if (!(dxi > 0.0))
      throw SolverError("eulerian1d",
                        "reference map no longer increasing in cell " + std::to_string(c) +
                            " (det F = dx / dxi <= 0)",
                        0, dxi);
    f.solid_length(c) = clip(xi(c + 1)) - clip(xi(c));
    f.fraction(c) = f.solid_length(c) / dxi;
    f.stretch(c) = dx / dxi;
    f.stress(c) = material.kappa * (f.stretch(c) - 1.0);
  }
  return f;
}

VecX lumped_masses(const Material& material, const CellFields& cells) {
  const Eigen::Index n = cells.solid_length.size();
  VecX m = VecX::Zero(n + 1);
  for (Eigen::Index c = 0; c < n; ++c) {
    const double half = 0.5 * material.rho0 * cells.solid_length(c);
    m(c) += half;
    m(c + 1) += half;
  }
  return m;
}

VecX nodal_forces(const CellFields& cells) {
  const Eigen::Index n = cells.solid_length.size();
  VecX f = VecX::Zero(n + 1);
  for (Eigen::Index c = 0; c < n; ++c) {
    const double t = cells.fraction(c) * cells.stress(c);  // phi_c sigma_c pulls node c+1 back
    f(c) += t;
    f(c + 1) -= t;
  }
  return f;
}

double elastic_energy(const Material& material, const CellFields& cells) {
  double energy = 0.0;
  for (Eigen::Index c = 0; c < cells.solid_length.size(); ++c) {
    const double e = cells.stretch(c) - 1.0;
    energy += cells.solid_length(c) * 0.5 * material.kappa * e * e;
  }
  return energy;
}

VecX cell_density(const Grid& grid, const Material& material, const CellFields& cells) {
  return cells.solid_length * (material.rho0 / grid.dx());
}

VecX upwind_transport(const Grid& grid, const VecX& a, const VecX& u) {
  const Eigen::Index last = u.size() - 1;
  const double inv_dx = 1.0 / grid.dx();
  VecX out(u.size());
  for (Eigen::Index j = 0; j <= last; ++j) {
    const bool backward = a(j) > 0.0 ? j > 0 : j == last;
    const double du = backward ? u(j) - u(j - 1) : u(j + 1) - u(j);
    out(j) = a(j) * du * inv_dx;
  }
  return out;
}

std::optional<double> material_point_position(const Grid& grid, const VecX& xi, double X) {
  const Eigen::Index n = xi.size();
  if (n < 2 || X < xi(0) || X > xi(n - 1)) return std::nullopt;
  // xi is increasing: the first node with xi > X closes the bracketing cell.
  const auto* begin = xi.data();
  const auto it = std::upper_bound(begin, begin + n, X);
  Eigen::Index k = std::min<Eigen::Index>(it - begin, n - 1) - 1;
  k = std::max<Eigen::Index>(k, 0);
  return grid.node(static_cast<std::size_t>(k)) + grid.dx() * (X - xi(k)) / (xi(k + 1) - xi(k));
}

void extrapolate_velocity(const VecX& masses, VecX& v) {
  const Eigen::Index n = v.size();
  constexpr Eigen::Index none = -1;
  std::vector<Eigen::Index> left(static_cast<std::size_t>(n), none), right(static_cast<std::size_t>(n), none);
  for (Eigen::Index j = 0, last = none; j < n; ++j) {
    if (masses(j) > 0.0) last = j;
    left[static_cast<std::size_t>(j)] = last;
  }
  for (Eigen::Index j = n - 1, next = none; j >= 0; --j) {
    if (masses(j) > 0.0) next = j;
    right[static_cast<std::size_t>(j)] = next;
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    if (masses(j) > 0.0) continue;
    const Eigen::Index l = left[static_cast<std::size_t>(j)], r = right[static_cast<std::size_t>(j)];
    if (l == none && r == none) return;  // no solid at all: nothing to copy
    const Eigen::Index source = l == none ? r : r == none ? l : (j - l <= r - j ? l : r);
    v(j) = v(source);
  }
}

}  // namespace rodvv::solvers::eulerian1d
