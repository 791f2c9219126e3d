#include "rodvv/solvers/rod3d/ring.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <Eigen/Dense>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "vertex_chart.hpp"

namespace rodvv::solvers::rod3d {

namespace {

constexpr int kStencil = 11;

// An orthonormal basis of the null space of the rows of `rows` (m x n), rank measured by a
// column-pivoted QR of its transpose (threshold n eps times the largest pivot, times 64).
MatX null_space_basis(const MatX& rows, std::size_t& rank) {
  const Eigen::Index n = rows.cols();
  Eigen::ColPivHouseholderQR<MatX> qr(rows.transpose());
  qr.setThreshold(64.0 * double(n) * std::numeric_limits<double>::epsilon());
  rank = std::size_t(qr.rank());
  const MatX q = qr.householderQ() * MatX::Identity(n, n);
  return q.rightCols(n - Eigen::Index(rank));
}

}  // namespace

void validate(const TwistedRing& ring) {
  if (ring.elements < 3 || ring.elements > kMaxRingElements)
    throw InputError("elements", "invalid parameter 'elements' = " + std::to_string(ring.elements) +
                                     ": must lie in [3, " + std::to_string(kMaxRingElements) +
                                     "] (dense linearisation, O(N^3))");
  require_positive("length", ring.length);
  require_positive("stiffness.twist (GJ)", ring.stiffness[0]);
  require_positive("stiffness.bending1 (EI1)", ring.stiffness[1]);
  require_positive("stiffness.bending2 (EI2)", ring.stiffness[2]);
  require_finite("twist", ring.twist);
  require_finite_vector("center", ring.center);
  const double orthogonality = (ring.frame.transpose() * ring.frame - Mat3::Identity()).cwiseAbs().maxCoeff();
  if (!(orthogonality <= 1e-10) || !(std::abs(ring.frame.determinant() - 1.0) <= 1e-10))
    throw InputError("frame", "invalid parameter 'frame': must be a rotation matrix (to 1e-10)");
}

RingLinearization linearize_ring(const TwistedRing& ring) {
  validate(ring);
  const std::size_t n = ring.elements;
  const auto dofs = Eigen::Index(4 * n);
  const double ell = ring.length / double(n), pi = std::numbers::pi;
  const double radius = ell / (2.0 * std::sin(pi / double(n)));  // the regular N-gon of side ebar
  const Vec3 u = ring.frame.col(0), v = ring.frame.col(1), normal = ring.frame.col(2);
  const auto wrap = [n](std::size_t i) { return i % n; };

  RingLinearization out;
  out.position.resize(n);
  out.angle.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * pi * double(i) / double(n);
    out.position[i] = ring.center + radius * (std::cos(a) * u + std::sin(a) * v);
    out.angle[i] = ring.twist * double(i) / double(n);
  }
  std::vector<Vec3> tangent(n);
  for (std::size_t j = 0; j < n; ++j) tangent[j] = (out.position[wrap(j + 1)] - out.position[j]).normalized();

  // Bending and twisting: one stencil per vertex, edges i-1 and i (mod N).
  out.gradient = VecX::Zero(dofs);
  out.hessian = MatX::Zero(dofs, dofs);
  Eigen::Matrix<double, kStencil, 1> z, g;
  Eigen::Matrix<double, kStencil, kStencil> h;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = wrap(i + n - 1), next = wrap(i + 1);
    const detail::VertexChart chart{tangent[prev], normal, tangent[i], normal, 0.0};
    z.segment<3>(0) = out.position[prev];
    // The closure: at vertex 0 the previous edge's angle is theta^{N-1} - Phi (theta^{j+N} = theta^j +
    // Phi). The stencil depends on the two angles only through their difference for EI1 = EI2 (the
    // averaged material directors turn together), so the shift is exact there; for EI1 != EI2 it
    // turns edge N-1's frame at vertex 0 by -Phi, a real discontinuity unless Phi is a whole number
    // of turns (ring_stability_eigenvalue refuses that case).
    z[3] = out.angle[prev] - (i == 0 ? ring.twist : 0.0);
    z.segment<3>(4) = out.position[i];
    z[7] = out.angle[i];
    z.segment<3>(8) = out.position[next];
    detail::vertex_stencil_derivatives(chart, z, ring.stiffness, Vec3::Zero(), ell, g, h);
    std::array<Eigen::Index, kStencil> index{};
    for (int c = 0; c < 3; ++c) {
      index[std::size_t(c)] = Eigen::Index(4 * prev) + c;
      index[std::size_t(4 + c)] = Eigen::Index(4 * i) + c;
      index[std::size_t(8 + c)] = Eigen::Index(4 * next) + c;
    }
    index[3] = Eigen::Index(4 * prev + 3);
    index[7] = Eigen::Index(4 * i + 3);
    for (int a = 0; a < kStencil; ++a) {
      out.gradient[index[std::size_t(a)]] += g[a];
      for (int b = 0; b < kStencil; ++b) out.hessian(index[std::size_t(a)], index[std::size_t(b)]) += h(a, b);
    }
  }

  // Inextensibility c_j = |x_{j+1} - x_j| - ebar: gradient -+t on (x_j, x_{j+1}), Hessian (I - t t^T)/|e|.
  out.constraints = MatX::Zero(Eigen::Index(n), dofs);
  for (std::size_t j = 0; j < n; ++j) {
    out.constraints.block<1, 3>(Eigen::Index(j), Eigen::Index(4 * j)) = -tangent[j].transpose();
    out.constraints.block<1, 3>(Eigen::Index(j), Eigen::Index(4 * wrap(j + 1))) = tangent[j].transpose();
  }
  // The tension: least squares on dE/dz + C^T lambda = 0 (all edges equal by symmetry: the mean).
  const VecX lambda = out.constraints.transpose().colPivHouseholderQr().solve(-out.gradient);
  out.tension = lambda.mean();
  const VecX imbalance = out.gradient + out.constraints.transpose() * lambda;
  const double force_scale = std::max(out.gradient.cwiseAbs().maxCoeff(), ring.stiffness.maxCoeff() / (ring.length * ring.length));
  out.residual = imbalance.cwiseAbs().maxCoeff() / force_scale;
  for (std::size_t j = 0; j < n; ++j) {
    const double len = (out.position[wrap(j + 1)] - out.position[j]).norm();
    const Mat3 block = lambda[Eigen::Index(j)] * (Mat3::Identity() - tangent[j] * tangent[j].transpose()) / len;
    const auto a = Eigen::Index(4 * j), b = Eigen::Index(4 * wrap(j + 1));
    out.hessian.block<3, 3>(a, a) += block;
    out.hessian.block<3, 3>(b, b) += block;
    out.hessian.block<3, 3>(a, b) -= block;
    out.hessian.block<3, 3>(b, a) -= block;
  }

  // The exact zero modes of a free ring.
  const bool isotropic = ring.stiffness[1] == ring.stiffness[2];
  out.zero_modes = MatX::Zero(dofs, isotropic ? 7 : 6);
  for (int k = 0; k < 3; ++k) {
    const Vec3 w = Vec3::Unit(k);
    for (std::size_t i = 0; i < n; ++i) {
      out.zero_modes.block<3, 1>(Eigen::Index(4 * i), k) = w;
      out.zero_modes.block<3, 1>(Eigen::Index(4 * i), 3 + k) = w.cross(out.position[i] - ring.center);
      out.zero_modes(Eigen::Index(4 * i + 3), 3 + k) = w.dot(tangent[i]);
    }
  }
  if (isotropic)
    for (std::size_t j = 0; j < n; ++j) out.zero_modes(Eigen::Index(4 * j + 3), 6) = 1.0;
  return out;
}

double ring_stability_eigenvalue(const TwistedRing& ring) {
  validate(ring);
  if (ring.stiffness[1] != ring.stiffness[2])
    throw InputError("stiffness", "invalid parameter 'stiffness': the ring's stability needs EI1 = EI2 (got " +
                                      format_value(ring.stiffness[1]) + " and " + format_value(ring.stiffness[2]) + ")");
  const RingLinearization lin = linearize_ring(ring);
  std::size_t rank = 0;
  const MatX q = null_space_basis(lin.constraints, rank);                  // C q = 0
  const MatX modes_in_q = q.transpose() * lin.zero_modes;                  // the zero modes lie in null(C)
  std::size_t mode_rank = 0;
  const MatX p = null_space_basis(modes_in_q.transpose(), mode_rank);      // orthogonal to them
  if (mode_rank != std::size_t(lin.zero_modes.cols()))
    throw SolverError("rod3d ring stability", "the zero modes are not independent (rank " + std::to_string(mode_rank) + ")",
                      0, 0.0);
  const MatX basis = q * p;
  const MatX a = basis.transpose() * lin.hessian * basis;
  Eigen::SelfAdjointEigenSolver<MatX> solver(0.5 * (a + a.transpose()), Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success)
    throw SolverError("rod3d ring stability (dense symmetric eigensolver)", "eigenvalue iteration did not converge", 0, 0.0);
  return solver.eigenvalues()[0];
}

}  // namespace rodvv::solvers::rod3d
