#pragma once
// Spatial discretisation of the 1-D reference-map solid (ALGORITHMS.md §6.2):
//   cell c = (j, j+1):  dxi_c = xi_{j+1} - xi_j > 0,  F_c = dx / dxi_c,  sigma_c = kappa (F_c - 1)
//   solid length        l_c = clip(xi_{j+1}) - clip(xi_j),  clip = min(max(., 0), L0)  (exact for a
//                       piecewise-linear monotone map), solid fraction phi_c = l_c / dxi_c
//   lumped mass         m_j = rho0 (l_{j-1} + l_j) / 2, so sum m_j = rho0 L0 exactly
//   force               f_j = phi_j sigma_j - phi_{j-1} sigma_{j-1} = -dW/dx_j for the stored energy
//                       W = sum_c l_c psi(F_c): the free-surface traction comes out by itself.
#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/eulerian1d/problem.hpp"

namespace rodvv::solvers::eulerian1d {

struct CellFields {
  VecX solid_length;  // l_c (reference length of solid in the cell)
  VecX fraction;      // phi_c
  VecX stretch;       // F_c
  VecX stress;        // sigma_c
};

// Throws SolverError("eulerian1d", ...) if xi is not strictly increasing (det F <= 0).
CellFields cell_fields(const Grid& grid, const Material& material, const VecX& xi);
VecX lumped_masses(const Material& material, const CellFields& cells);
VecX nodal_forces(const CellFields& cells);
// Stored energy sum_c l_c kappa (F_c - 1)^2 / 2.
double elastic_energy(const Material& material, const CellFields& cells);
// Cell-averaged density rho0 l_c / dx (the discrete rho = rho0 xi_x).
VecX cell_density(const Grid& grid, const Material& material, const CellFields& cells);

// First-order upwind a_j D_up u_j: (u_j - u_{j-1})/dx if a_j > 0, (u_{j+1} - u_j)/dx otherwise; the
// one-sided difference that exists at the two ends of the grid.
VecX upwind_transport(const Grid& grid, const VecX& a, const VecX& u);

// Position where xi = X by linear interpolation in the cell that brackets it; empty if xi does not
// take the value X on the grid.
std::optional<double> material_point_position(const Grid& grid, const VecX& xi, double X);

// Copies the velocity of the nearest node with mass > 0 to every node without mass.
void extrapolate_velocity(const VecX& masses, VecX& v);

}  // namespace rodvv::solvers::eulerian1d
