#include "rodvv/solvers/superhelix/clothoid_dynamics.hpp"

#include <Eigen/Cholesky>

#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

// J_g qdot at every Gauss point.
std::vector<Vec3> point_velocities(const ClothoidKinematics& kinematics, const VecX& qdot) {
  std::vector<Vec3> v;
  v.reserve(kinematics.points().size());
  for (const auto& p : kinematics.points()) v.push_back(kinematics.position_jacobian(p.element, p.sigma) * qdot);
  return v;
}

void check_state(const RodModel& model, const DynamicState& state) {
  const auto n = static_cast<Eigen::Index>(clothoid_dof_count(model));
  if (state.q.size() != n || state.qdot.size() != n)
    throw InputError("state", "invalid parameter 'state': q and qdot must hold 3 (N + 1) = " + std::to_string(n) +
                                  " values");
  if (!state.q.allFinite() || !state.qdot.allFinite())
    throw InputError("state", "invalid parameter 'state': q and qdot must be finite");
}

}  // namespace

MatX clothoid_mass_matrix(const ClothoidKinematics& kinematics) {
  const auto n = static_cast<Eigen::Index>(3 * (kinematics.elements() + 1));
  MatX M = MatX::Zero(n, n);
  for (const auto& p : kinematics.points()) {
    const MatX J = kinematics.position_jacobian(p.element, p.sigma);
    M.noalias() += p.mass * J.transpose() * J;
  }
  return M;
}

std::vector<Vec3> clothoid_bias_accelerations(const RodModel& model, const ClothoidKinematics& kinematics,
                                              const VecX& qdot) {
  const double rate = qdot.lpNorm<Eigen::Infinity>();
  if (rate == 0.0) return std::vector<Vec3>(kinematics.points().size(), Vec3::Zero());
  const double e = std::cbrt(std::numeric_limits<double>::epsilon()) / (model.length * rate);
  const auto plus = point_velocities(ClothoidKinematics(model, kinematics.q() + e * qdot), qdot);
  const auto minus = point_velocities(ClothoidKinematics(model, kinematics.q() - e * qdot), qdot);
  std::vector<Vec3> zeta(plus.size());
  for (std::size_t g = 0; g < plus.size(); ++g) zeta[g] = (plus[g] - minus[g]) / (2.0 * e);
  return zeta;
}

VecX clothoid_velocity_change(const RodModel& model, const DynamicState& state, double h) {
  validate_clothoid(model);
  require_positive("h", h);
  check_state(model, state);
  const ClothoidKinematics kin(model, state.q);
  const MatX K = clothoid_stiffness(model);
  const MatX D = (h * h + h * model.rayleigh_stiffness) * K;
  const auto zeta = clothoid_bias_accelerations(model, kin, state.qdot);
  std::vector<Vec3> bias(zeta.size());
  for (std::size_t g = 0; g < zeta.size(); ++g) bias[g] = -kin.points()[g].mass * zeta[g];
  // B_n = F_ext - sum_g m_g J_g^T zeta_g (the bias enters as point forces -m_g zeta_g)
  const VecX B = clothoid_external_force(model, kin) +
                 clothoid_generalised_force(kin, bias, Vec3::Zero(), Vec3::Zero());
  const VecX rhs = h * (-K * (state.q - clothoid_natural_strain_vector(model)) + B) - D * state.qdot;
  const MatX A = clothoid_mass_matrix(kin) + D;
  return A.ldlt().solve(rhs);
}

DynamicState clothoid_step(const RodModel& model, const DynamicState& state, double h) {
  DynamicState next = state;
  next.qdot = state.qdot + clothoid_velocity_change(model, state, h);
  next.q = state.q + h * next.qdot;
  next.time = state.time + h;
  return next;
}

double clothoid_kinetic_energy(const ClothoidKinematics& kinematics, const VecX& qdot) {
  double energy = 0.0;
  const auto v = point_velocities(kinematics, qdot);
  for (std::size_t g = 0; g < v.size(); ++g) energy += 0.5 * kinematics.points()[g].mass * v[g].squaredNorm();
  return energy;
}

double clothoid_total_energy(const RodModel& model, const DynamicState& state) {
  check_state(model, state);
  const ClothoidKinematics kin(model, state.q);
  return clothoid_kinetic_energy(kin, state.qdot) + clothoid_elastic_energy(model, state.q) +
         clothoid_gravity_energy(model, kin) - model.end_force.dot(kin.tip_position());
}

}  // namespace rodvv::solvers::superhelix
