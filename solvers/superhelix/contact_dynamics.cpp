#include "rodvv/solvers/superhelix/contact_dynamics.hpp"

#include <algorithm>
#include <string>

#include "dense_step_system.hpp"
#include "step_guard.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/velocity_qp.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

constexpr const char* kMethod = "superhelix semi-implicit Euler step with velocity-level contact";

void check_frictionless(const std::vector<RigidObstacle>& obstacles) {
  validate_obstacles(obstacles);
  for (std::size_t i = 0; i < obstacles.size(); ++i)
    if (obstacles[i].mu != 0.0)
      throw InputError("obstacles", "invalid parameter 'obstacles': obstacle " + std::to_string(i) + " has mu " +
                                        format_value(obstacles[i].mu) +
                                        ": the dynamics' contact is frictionless, mu must be 0 (friction: "
                                        "frictional_statics.hpp)");
}

double largest_penetration(const Kinematics& kinematics, const std::vector<RigidObstacle>& obstacles) {
  double penetration = 0.0;
  for (const auto& point : kinematics.points())
    for (const auto& obstacle : obstacles)
      penetration = std::max(penetration, -obstacle_proximity(obstacle, point.position).gap);
  return penetration;
}

}  // namespace

ContactStepResult step_with_obstacles(const RodModel& model, const DynamicState& state, double h,
                                      const std::vector<RigidObstacle>& obstacles, const ContactStepOptions& options) {
  detail::check_step_input(model, state, h);
  require_finite("state.time", state.time);
  check_frictionless(obstacles);
  require_non_negative("contact_distance", options.contact_distance);
  require_open_interval("lcp.tolerance", options.lcp.tolerance, 0.0, 1.0);
  require_closed_interval("compliance", options.compliance, 0.0, 1.0);

  const RootState root = RootMotion{}.state_at(model, state.time);  // the model's root, at rest
  const detail::DenseStepSystem system = detail::dense_step_system(model, state, h, root);
  const Kinematics kinematics(model, state.q);
  const double reach = options.contact_distance > 0.0 ? options.contact_distance : element_length(model);

  // Candidates and their rows n_g^T J_g; the bound of J dv >= c is -gap_g / h - n_g^T J_g qdot_n.
  ContactStepResult result;
  std::vector<VecX> rows;
  std::vector<double> bounds;
  const auto& points = kinematics.points();
  for (std::size_t g = 0; g < points.size(); ++g)
    for (std::size_t o = 0; o < obstacles.size(); ++o) {
      const ObstacleProximity proximity = obstacle_proximity(obstacles[o], points[g].position);
      if (proximity.gap > reach) continue;
      VecX row = kinematics.position_jacobian(points[g].element, points[g].sigma).transpose() * proximity.normal;
      bounds.push_back(-proximity.gap / h - row.dot(state.qdot));
      rows.push_back(std::move(row));
      result.contacts.push_back({g, o, proximity.gap, proximity.normal, 0.0});
    }

  VecX dv;
  if (rows.empty()) {
    const Eigen::LDLT<MatX> ldlt(system.matrix);
    if (ldlt.info() != Eigen::Success) throw SolverError(kMethod, "LDL^T of M + D failed", 0, 0.0);
    dv = ldlt.solve(system.rhs);
  } else {
    MatX J(Eigen::Index(rows.size()), system.rhs.size());
    VecX c(Eigen::Index(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      J.row(Eigen::Index(i)) = rows[i].transpose();
      c(Eigen::Index(i)) = bounds[i];
    }
    // A = M_n + (h^2 + h gamma) K is symmetric positive definite: K > 0 (validate) and h > 0.
    const auto qp = contact::solve_velocity_qp(system.matrix, -system.rhs, J, c, options.method, options.lcp,
                                               options.compliance);
    dv = qp.v;
    for (std::size_t i = 0; i < rows.size(); ++i) result.contacts[i].impulse = qp.lambda(Eigen::Index(i));
    result.lcp_iterations = qp.iterations;
    result.lcp_residual = qp.residual;
  }
  result.state.qdot = state.qdot + dv;
  result.state.q = state.q + h * result.state.qdot;
  result.state.time = state.time + h;
  detail::require_finite_step(kMethod, state, result.state, h);
  result.penetration = largest_penetration(Kinematics(model, result.state.q), obstacles);
  return result;
}

}  // namespace rodvv::solvers::superhelix
