#include "rodvv/solvers/rod3d/linearized.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCore>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/rod3d/discrete_energy.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::solvers::rod3d {

namespace {

bool is_multiplier(const DofLayout& layout, std::size_t k) {
  return layout.multipliers && k < layout.size() - 3 && k % layout.stride() == 4;
}

// The round-off floor of the scaled residual (statics.cpp): edge vectors carry eps |x|, the
// integrated curvatures eps |x| N / L, the vertex forces relative to EI / L^2 N^3 eps |x| / L
// (measured 1.1 N^3 eps; the straight state at N = 256 shows 1.6e-8): 8 N^3 eps max(1, |x|_max / L).
double round_off_floor(const RodModel& model, const RodState& state) {
  double extent = model.length;
  for (const Vec3& x : state.position) extent = std::max(extent, x.cwiseAbs().maxCoeff());
  const double n = double(model.elements);
  return 8.0 * std::numeric_limits<double>::epsilon() * n * n * n * extent / model.length;
}

}  // namespace

VecX lumped_mass(const RodModel& model) {
  validate(model);
  require_positive("twist_inertia", model.twist_inertia);
  const DofLayout layout(model);
  const double ell = rest_edge_length(model);
  VecX mass = VecX::Zero(Eigen::Index(layout.size()));
  for (std::size_t i = 0; i <= model.elements; ++i) {
    const double m = model.line_density * ell * ((i == 0 || i == model.elements) ? 0.5 : 1.0);
    mass.segment<3>(Eigen::Index(layout.vertex(i))).setConstant(m);
  }
  for (std::size_t j = 0; j < model.elements; ++j) mass[Eigen::Index(layout.angle(j))] = model.twist_inertia * ell;
  return mass;
}

LinearizedRod linearize(const RodModel& model, const RodState& equilibrium, const LinearizationOptions& options) {
  validate(model);
  if (model.elements > kMaxModalElements)
    throw InputError("elements", "invalid parameter 'elements' = " + std::to_string(model.elements) +
                                     ": the dense modal analysis is limited to N <= " +
                                     std::to_string(kMaxModalElements) + " (O(N^3) work)");
  require_positive("equilibrium_tolerance", options.equilibrium_tolerance);
  require_positive("symmetry_tolerance", options.symmetry_tolerance);
  const VecX mass = lumped_mass(model);
  const double imbalance = scaled_residual(model, equilibrium, 1.0);
  const double accepted = std::max(options.equilibrium_tolerance, round_off_floor(model, equilibrium));
  if (!(imbalance <= accepted))
    throw InputError("state", "invalid parameter 'state': not an equilibrium at load factor 1 (scaled residual " +
                                  format_value(imbalance) + " > " + format_value(accepted) + ")");

  const DofLayout layout(model);
  std::vector<char> held(layout.size(), 0);
  for (std::size_t k : held_dofs(model)) held[k] = 1;
  LinearizedRod out;
  std::vector<Eigen::Index> primal_index(layout.size(), -1), constraint_index(layout.size(), -1);
  std::size_t constraints = 0;
  for (std::size_t k = 0; k < layout.size(); ++k) {
    if (held[k]) continue;
    if (is_multiplier(layout, k)) {
      constraint_index[k] = Eigen::Index(constraints++);
    } else {
      primal_index[k] = Eigen::Index(out.free_dofs.size());
      out.free_dofs.push_back(k);
    }
  }
  const auto n = Eigen::Index(out.free_dofs.size());
  const auto m = Eigen::Index(constraints);

  VecX residual;
  Eigen::SparseMatrix<double> jacobian;
  static_system(model, equilibrium, 1.0, residual, jacobian);
  MatX K = MatX::Zero(n, n), C = MatX::Zero(m, n);
  for (int col = 0; col < jacobian.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(jacobian, col); it; ++it) {
      const auto row = std::size_t(it.row()), c = std::size_t(it.col());
      if (primal_index[row] >= 0 && primal_index[c] >= 0) K(primal_index[row], primal_index[c]) += it.value();
      if (constraint_index[row] >= 0 && primal_index[c] >= 0) C(constraint_index[row], primal_index[c]) += it.value();
    }

  // W = M^{-1/2} on the free dofs; Q = the null space of C W, orthonormal.
  VecX w(n);
  for (Eigen::Index a = 0; a < n; ++a) w[a] = 1.0 / std::sqrt(mass[Eigen::Index(out.free_dofs[std::size_t(a)])]);
  MatX Q;
  if (m > 0) {
    const MatX CWt = (C * w.asDiagonal()).transpose();  // n x m
    Eigen::ColPivHouseholderQR<MatX> qr(CWt);
    // Rank threshold: column norms of C W are 1 / sqrt(m_i) times O(1) direction cosines; a
    // dependent constraint leaves a pivot at round-off (n eps times the largest).
    qr.setThreshold(64.0 * double(n) * std::numeric_limits<double>::epsilon());
    out.constraint_rank = std::size_t(qr.rank());
    const MatX full_q = qr.householderQ() * MatX::Identity(n, n);
    Q = full_q.rightCols(n - Eigen::Index(out.constraint_rank));
  } else {
    Q = MatX::Identity(n, n);
  }
  out.basis = w.asDiagonal() * Q;
  MatX A = out.basis.transpose() * K * out.basis;
  const double largest = A.cwiseAbs().maxCoeff();
  out.asymmetry = largest > 0.0 ? (A - A.transpose()).cwiseAbs().maxCoeff() / largest : 0.0;
  if (!(out.asymmetry <= options.symmetry_tolerance))
    throw InputError("end_moment",
                     "invalid parameter 'end_moment': the linearised stiffness is not symmetric (relative asymmetry " +
                         format_value(out.asymmetry) + " > " + format_value(options.symmetry_tolerance) +
                         ", the load stiffness of the dead tip moment, which is not conservative): no real "
                         "normal modes");
  out.hessian = 0.5 * (A + A.transpose());
  return out;
}

LinearModes linear_modes(const RodModel& model, const RodState& equilibrium, const LinearizationOptions& options) {
  const LinearizedRod lin = linearize(model, equilibrium, options);
  Eigen::SelfAdjointEigenSolver<MatX> solver(lin.hessian);
  if (solver.info() != Eigen::Success)
    throw SolverError("rod3d linear modes (dense symmetric eigensolver)", "eigenvalue iteration did not converge", 0,
                      0.0);
  LinearModes modes;
  modes.omega_squared = solver.eigenvalues();
  modes.frequencies = modes.omega_squared.cwiseMax(0.0).cwiseSqrt();
  const DofLayout layout(model);
  const MatX free_shapes = lin.basis * solver.eigenvectors();
  modes.shapes = MatX::Zero(Eigen::Index(layout.size()), free_shapes.cols());
  for (std::size_t a = 0; a < lin.free_dofs.size(); ++a)
    modes.shapes.row(Eigen::Index(lin.free_dofs[a])) = free_shapes.row(Eigen::Index(a));
  return modes;
}

double stability_eigenvalue(const RodModel& model, const RodState& equilibrium, const LinearizationOptions& options) {
  const LinearizedRod lin = linearize(model, equilibrium, options);
  if (lin.hessian.rows() == 0) return 0.0;
  Eigen::SelfAdjointEigenSolver<MatX> solver(lin.hessian, Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success)
    throw SolverError("rod3d stability (dense symmetric eigensolver)", "eigenvalue iteration did not converge", 0, 0.0);
  return solver.eigenvalues()[0];
}

ModalContent modal_content(const RodModel& model, const VecX& shape, const Mat3& frame) {
  const DofLayout layout(model);
  if (shape.size() != Eigen::Index(layout.size()))
    throw InputError("shape", "invalid parameter 'shape': must hold " + std::to_string(layout.size()) + " values");
  const VecX mass = lumped_mass(model);
  ModalContent content;
  for (std::size_t i = 0; i <= model.elements; ++i) {
    const Vec3 u = frame.transpose() * shape.segment<3>(Eigen::Index(layout.vertex(i)));
    content.translation += mass[Eigen::Index(layout.vertex(i))] * u.cwiseAbs2();
  }
  for (std::size_t j = 0; j < model.elements; ++j) {
    const auto k = Eigen::Index(layout.angle(j));
    content.rotation += mass[k] * shape[k] * shape[k];
  }
  return content;
}

}  // namespace rodvv::solvers::rod3d
