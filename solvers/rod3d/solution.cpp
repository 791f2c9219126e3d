#include "rodvv/solvers/rod3d/solution.hpp"

#include <Eigen/Geometry>

#include "rodvv/solvers/rod3d/discrete_energy.hpp"

namespace rodvv::solvers::rod3d {

namespace {

// The rotation halfway from a to b: a exp(1/2 log(a^T b)).
Mat3 halfway(const Mat3& a, const Mat3& b) {
  Eigen::AngleAxisd relative(a.transpose() * b);
  relative.angle() *= 0.5;
  return a * relative.toRotationMatrix();
}

}  // namespace

SpatialRodSolution make_solution(const RodModel& model, const RodState& state) {
  validate(model);
  const std::size_t n = model.elements;
  const double ell = rest_edge_length(model);
  const bool extensible = !is_inextensible(model);
  const auto strains = integrated_strains(model, state);
  const auto vertex_forces = elastic_vertex_forces(model, state);

  // Internal force of edge j: the elastic forces of the vertices beyond it.
  std::vector<Vec3> edge_force(n);
  Vec3 beyond = Vec3::Zero();
  for (std::size_t j = n; j-- > 0;) {
    beyond += vertex_forces[j + 1];
    edge_force[j] = beyond;
  }
  // A dead moment on edge j puts its couple on x_{j+1} and minus it on x_j (discrete_energy.cpp): only the
  // first is beyond edge j, and it is a load, not an elastic force.
  for (std::size_t j = 0; j < n; ++j) {
    Vec3 moment = j < model.edge_moments.size() ? model.edge_moments[j] : Vec3::Zero();
    if (j == n - 1) moment += model.end_moment;
    if (moment.isZero(0.0)) continue;
    const Vec3 e = state.position[j + 1] - state.position[j];
    edge_force[j] -= moment.cross(e) / e.squaredNorm();
  }
  std::vector<Mat3> frames(n);
  std::vector<double> stretch(n);
  for (std::size_t j = 0; j < n; ++j) {
    frames[j] = material_frame(state, j);
    stretch[j] = (state.position[j + 1] - state.position[j]).norm() / ell;
  }

  // The self-contact field felt along each segment, per unit length (PHYSICS.md §1.2: V_eff(s) =
  // int U(|r(s) - r(sigma)|) dsigma, the full field, not half of it): each pair's barrier energy is
  // felt in full by both of its segments.
  std::vector<double> contact_field(n, 0.0);
  if (has_self_contact(model))
    for (const ContactPair& pair : self_contacts(model.self_contact, state.position, ell)) {
      const double field = contact_pair_energy(model.self_contact, pair.distance) / ell;
      contact_field[pair.first] += field;
      contact_field[pair.second] += field;
    }

  SpatialRodSolution solution;
  solution.method = "discrete elastic rod (Bergou et al. 2008)";
  solution.length = model.length;
  const std::size_t first = model.root.support == EndSupport::Clamped ? 2 : 1;
  const std::size_t last = model.tip.support == EndSupport::Clamped ? n - 2 : n - 1;
  for (std::size_t i = first; i <= last && i < n; ++i) {
    const Mat3 frame = halfway(frames[i - 1], frames[i]);
    const Vec3 u = strains[i] / ell;
    const double v0 = 0.5 * (stretch[i - 1] + stretch[i]);
    solution.s.push_back(vertex_arclength(model, i));
    solution.position.push_back(state.position[i]);
    solution.frame.push_back(frame);
    solution.strain_u.push_back(u);
    solution.strain_v.push_back(Vec3(v0, 0.0, 0.0));
    solution.stiffness.push_back(model.stiffness);
    solution.natural_strain.push_back(model.natural_strain);
    solution.force_n.push_back(0.5 * (edge_force[i - 1] + edge_force[i]));
    solution.moment_m.push_back(frame * model.stiffness.cwiseProduct(u - model.natural_strain));
    solution.potential.push_back(-model.line_density * model.gravity.dot(state.position[i]) +
                                 0.5 * (contact_field[i - 1] + contact_field[i]));
    solution.shear_energy.push_back(extensible ? 0.5 * model.extensional_stiffness * (v0 - 1.0) * (v0 - 1.0) : 0.0);
  }
  // Vertices on [0, L]: a clamped end contributes its support point (the clamped edge's midpoint,
  // with that edge's frame) instead of its ghost vertex.
  const bool clamped_root = model.root.support == EndSupport::Clamped, clamped_tip = model.tip.support == EndSupport::Clamped;
  if (clamped_root) {
    solution.vertex_s.push_back(0.0);
    solution.vertex_position.push_back(0.5 * (state.position[0] + state.position[1]));
    solution.vertex_frame.push_back(frames[0]);
  }
  for (std::size_t i = clamped_root ? 1 : 0; i <= (clamped_tip ? n - 1 : n); ++i) {
    solution.vertex_s.push_back(vertex_arclength(model, i));
    solution.vertex_position.push_back(state.position[i]);
    solution.vertex_frame.push_back(i == 0 ? frames[0] : i == n ? frames[n - 1] : halfway(frames[i - 1], frames[i]));
  }
  if (clamped_tip) {
    solution.vertex_s.push_back(model.length);
    solution.vertex_position.push_back(0.5 * (state.position[n - 1] + state.position[n]));
    solution.vertex_frame.push_back(frames[n - 1]);
  }
  return solution;
}

}  // namespace rodvv::solvers::rod3d
