#include "rodvv/solvers/superhelix/dynamics.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/element.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"

namespace rodvv::solvers::superhelix {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat63 = Eigen::Matrix<double, 6, 3>;

void check_state(const RodModel& model, const DynamicState& state, double h) {
  validate(model);
  require_positive("h", h);
  const auto n = static_cast<Eigen::Index>(dof_count(model));
  if (state.q.size() != n || state.qdot.size() != n)
    throw InputError("state", "invalid parameter 'state': q and qdot must hold 3 N = " + std::to_string(n) +
                                  " values");
  if (!state.q.allFinite()) throw InputError("state.q", "invalid parameter 'state.q': must be finite");
  if (!state.qdot.allFinite()) throw InputError("state.qdot", "invalid parameter 'state.qdot': must be finite");
}

// X(r): motion at p -> motion at p + r (ALGORITHMS.md §1.6).
Mat6 motion_transform(const Vec3& r) {
  Mat6 x = Mat6::Identity();
  x.block<3, 3>(3, 0) = -skew(r);
  return x;
}

// Right-hand side shared by both paths: h (-K (q - q0)) - D qdot, without the point / tip loads.
VecX elastic_rhs(const RodModel& model, const DynamicState& state, double h, VecX& damping_diagonal) {
  const VecX k = generalised_stiffness(model);
  damping_diagonal = (h * h + h * model.rayleigh_stiffness) * k;
  return -h * k.cwiseProduct(state.q - natural_strain_vector(model)) - damping_diagonal.cwiseProduct(state.qdot);
}

VecX dense_velocity_change(const RodModel& model, const DynamicState& state, double h) {
  const Kinematics kinematics(model, state.q);
  const auto zeta = bias_accelerations(model, kinematics, state.qdot);
  const auto n = static_cast<Eigen::Index>(dof_count(model));
  MatX M = MatX::Zero(n, n);
  VecX loads = VecX::Zero(n);
  const auto& points = kinematics.points();
  for (std::size_t g = 0; g < points.size(); ++g) {
    const GaussPoint& point = points[g];
    const MatX J = kinematics.position_jacobian(point.element, point.sigma);
    const auto used = static_cast<Eigen::Index>(3 * (point.element + 1));  // causality: J is zero beyond
    M.topLeftCorner(used, used).noalias() += point.mass * J.leftCols(used).transpose() * J.leftCols(used);
    loads.head(used) += J.leftCols(used).transpose() * (point.mass * (model.gravity - zeta[g]));
  }
  const std::size_t last = model.elements - 1;
  const double ell = element_length(model);
  loads += kinematics.position_jacobian(last, ell).transpose() * model.end_force +
           kinematics.rotation_jacobian(last, ell).transpose() * model.end_moment;
  VecX damping;
  const VecX rhs = elastic_rhs(model, state, h, damping) + h * loads;
  M.diagonal() += damping;
  const Eigen::LDLT<MatX> ldlt(M);
  if (ldlt.info() != Eigen::Success)
    throw SolverError("superhelix dense step", "LDL^T of M + D failed", 0, 0.0);
  return ldlt.solve(rhs);
}

VecX recursive_velocity_change(const RodModel& model, const DynamicState& state, double h) {
  const Kinematics kinematics(model, state.q);
  const auto zeta = bias_accelerations(model, kinematics, state.qdot);
  VecX damping;
  const VecX b = elastic_rhs(model, state, h, damping);
  const std::size_t n = model.elements, per = kinematics.points_per_element();
  const auto& points = kinematics.points();

  std::vector<Mat3> h_inverse(n);
  std::vector<Mat63> coupling(n);  // U_Q
  std::vector<Vec3> joint_rhs(n);  // u_Q
  Mat6 articulated = Mat6::Zero();  // I^A_{Q+1}
  Vec6 bias;                        // c_{Q+1}: the tip wrench enters with a minus sign (beta = -f)
  bias << -h * model.end_moment, -h * model.end_force;

  for (std::size_t e = n; e-- > 0;) {
    Mat63 S;
    S.topRows<3>() = kinematics.end_rotation_jacobian(e);
    S.bottomRows<3>() = kinematics.end_translation_jacobian(e);
    const Mat6 X = motion_transform(kinematics.base_position(e + 1) - kinematics.base_position(e));

    Mat6 inertia = Mat6::Zero();  // I_el
    Mat63 u_points = Mat63::Zero();
    Mat3 tt = Mat3::Zero();
    Vec6 point_bias = Vec6::Zero();
    Vec3 t_beta = Vec3::Zero();
    for (std::size_t g = 0; g < per; ++g) {
      const std::size_t index = e * per + g;
      const GaussPoint& point = points[index];
      const Mat3 D = skew(point.offset);
      const double m = point.mass;
      inertia.block<3, 3>(0, 0) -= m * D * D;
      inertia.block<3, 3>(0, 3) += m * D;
      inertia.block<3, 3>(3, 0) -= m * D;
      inertia.block<3, 3>(3, 3) += m * Mat3::Identity();
      u_points.topRows<3>() += m * D * point.local_jacobian;
      u_points.bottomRows<3>() += m * point.local_jacobian;
      tt += m * point.local_jacobian.transpose() * point.local_jacobian;
      const Vec3 beta = h * m * (zeta[index] - model.gravity);
      point_bias.head<3>() += point.offset.cross(beta);
      point_bias.tail<3>() += beta;
      t_beta += point.local_jacobian.transpose() * beta;
    }
    const Mat63 IS = articulated * S;
    Mat3 H = tt + S.transpose() * IS;
    H.diagonal() += damping.segment<3>(3 * e);
    const Mat63 U = u_points + X.transpose() * IS;
    const Vec3 u = b.segment<3>(3 * e) - S.transpose() * bias - t_beta;
    const Mat3 Hinv = H.inverse();
    articulated = inertia + X.transpose() * articulated * X - U * Hinv * U.transpose();
    bias = X.transpose() * bias + point_bias + U * (Hinv * u);
    h_inverse[e] = Hinv;
    coupling[e] = U;
    joint_rhs[e] = u;
  }

  VecX dv(3 * n);
  Vec6 acceleration = Vec6::Zero();  // clamped root at rest
  for (std::size_t e = 0; e < n; ++e) {
    const Vec3 x = h_inverse[e] * (joint_rhs[e] - coupling[e].transpose() * acceleration);
    dv.segment<3>(3 * e) = x;
    Mat63 S;
    S.topRows<3>() = kinematics.end_rotation_jacobian(e);
    S.bottomRows<3>() = kinematics.end_translation_jacobian(e);
    acceleration = motion_transform(kinematics.base_position(e + 1) - kinematics.base_position(e)) * acceleration +
                   S * x;
  }
  return dv;
}

}  // namespace

std::vector<Vec3> bias_accelerations(const RodModel& model, const Kinematics& kinematics, const VecX& qdot) {
  const double rate = qdot.lpNorm<Eigen::Infinity>();
  std::vector<Vec3> zeta(kinematics.points().size(), Vec3::Zero());
  if (rate == 0.0) return zeta;
  const double e = std::cbrt(std::numeric_limits<double>::epsilon()) / (model.length * rate);
  const Kinematics plus(model, kinematics.q() + e * qdot), minus(model, kinematics.q() - e * qdot);
  const auto v_plus = plus.point_velocities(qdot), v_minus = minus.point_velocities(qdot);
  for (std::size_t g = 0; g < zeta.size(); ++g) zeta[g] = (v_plus[g] - v_minus[g]) / (2.0 * e);
  return zeta;
}

MatX mass_matrix(const Kinematics& kinematics) {
  const auto n = static_cast<Eigen::Index>(3 * kinematics.elements());
  MatX M = MatX::Zero(n, n);
  for (const auto& point : kinematics.points()) {
    const MatX J = kinematics.position_jacobian(point.element, point.sigma);
    const auto used = static_cast<Eigen::Index>(3 * (point.element + 1));
    M.topLeftCorner(used, used).noalias() += point.mass * J.leftCols(used).transpose() * J.leftCols(used);
  }
  return M;
}

VecX velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path) {
  check_state(model, state, h);
  return path == DynamicsPath::Dense ? dense_velocity_change(model, state, h)
                                     : recursive_velocity_change(model, state, h);
}

DynamicState step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path) {
  DynamicState next;
  next.qdot = state.qdot + velocity_change(model, state, h, path);
  next.q = state.q + h * next.qdot;
  next.time = state.time + h;
  return next;
}

double kinetic_energy(const Kinematics& kinematics, const VecX& qdot) {
  const auto velocities = kinematics.point_velocities(qdot);
  double energy = 0.0;
  for (std::size_t g = 0; g < velocities.size(); ++g)
    energy += 0.5 * kinematics.points()[g].mass * velocities[g].squaredNorm();
  return energy;
}

double total_energy(const RodModel& model, const DynamicState& state) {
  const Kinematics kinematics(model, state.q);
  return kinetic_energy(kinematics, state.qdot) + elastic_energy(model, state.q) +
         gravity_energy(model, kinematics) - model.end_force.dot(kinematics.tip_position());
}

VecX bending_frequencies(const RodModel& model, std::size_t count) {
  validate(model);
  if (count < 1 || count > model.elements)
    throw InputError("count", "invalid parameter 'count' = " + std::to_string(count) +
                                  ": must be an integer in [1, N = " + std::to_string(model.elements) + "]");
  const Kinematics kinematics(model, VecX::Zero(static_cast<Eigen::Index>(dof_count(model))));
  const MatX M = mass_matrix(kinematics);
  const VecX k = generalised_stiffness(model);
  const auto n = static_cast<Eigen::Index>(model.elements);
  MatX Mb(n, n), Kb = MatX::Zero(n, n);
  for (Eigen::Index a = 0; a < n; ++a) {
    Kb(a, a) = k[3 * a + 1];
    for (Eigen::Index c = 0; c < n; ++c) Mb(a, c) = M(3 * a + 1, 3 * c + 1);
  }
  // K v = omega^2 M v (M is positive definite on the bending coordinates of a straight rod).
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> solver(Kb, Mb);
  if (solver.info() != Eigen::Success)
    throw SolverError("superhelix modes", "generalised eigenproblem failed", 0, 0.0);
  VecX omega(static_cast<Eigen::Index>(count));
  for (Eigen::Index i = 0; i < omega.size(); ++i) omega[i] = std::sqrt(solver.eigenvalues()[i]);
  return omega;
}

}  // namespace rodvv::solvers::superhelix
