#pragma once
// Internal to solvers/rod3d: one vertex stencil of the bending-twisting energy (discrete_energy.cpp),
// for the rods whose topology the open-rod assembly does not cover (ring.cpp: a closed loop). The
// 11 stencil dofs are (x_{i-1}, theta^{i-1}, x_i, theta^i, x_{i+1}); the chart is the base state's
// tangents and reference directors of the two edges and the vertex's reference twist (the trial
// reference frames are parallel-transported from the chart's tangents, discrete_energy.hpp).
#include <Eigen/Core>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::rod3d::detail {

struct VertexChart {
  Vec3 t_prev, a_prev, t_next, a_next;  // tangents and reference directors of edges i-1, i at the base
  double reference_twist = 0.0;         // of the vertex at the base (plus any closure twist of a ring)
};

// Gradient and Hessian of 1/2 (k - k0)^T K (k - k0) / lbar in the 11 dofs (the production jets).
void vertex_stencil_derivatives(const VertexChart& chart, const Eigen::Matrix<double, 11, 1>& dofs, const Vec3& stiffness,
                                const Vec3& natural_integrated, double voronoi, Eigen::Matrix<double, 11, 1>& gradient,
                                Eigen::Matrix<double, 11, 11>& hessian);

// The integrated strains k = (twist, kb.m1avg, kb.m2avg) of the stencil.
Vec3 vertex_stencil_strains(const VertexChart& chart, const Eigen::Matrix<double, 11, 1>& dofs);

}  // namespace rodvv::solvers::rod3d::detail
