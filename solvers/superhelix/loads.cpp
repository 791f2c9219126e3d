#include "rodvv/solvers/superhelix/loads.hpp"

namespace rodvv::solvers::superhelix {

VecX generalised_force(const Kinematics& kinematics, const std::vector<Vec3>& point_forces,
                       const Vec3& tip_force, const Vec3& tip_moment) {
  const std::size_t n = kinematics.elements(), per = kinematics.points_per_element();
  VecX force(3 * n);
  Vec3 moment_about_next = tip_moment;  // moment of everything downstream about p_{Q+1}
  Vec3 resultant = tip_force;
  const auto& points = kinematics.points();
  for (std::size_t e = n; e-- > 0;) {
    Vec3 generalised = kinematics.end_rotation_jacobian(e).transpose() * moment_about_next +
                       kinematics.end_translation_jacobian(e).transpose() * resultant;
    // shift the downstream wrench to p_Q and add the element's own point forces
    moment_about_next += (kinematics.base_position(e + 1) - kinematics.base_position(e)).cross(resultant);
    if (!point_forces.empty()) {
      for (std::size_t g = 0; g < per; ++g) {
        const GaussPoint& point = points[e * per + g];
        const Vec3& f = point_forces[e * per + g];
        generalised += point.local_jacobian.transpose() * f;
        moment_about_next += point.offset.cross(f);
        resultant += f;
      }
    }
    force.segment<3>(3 * e) = generalised;
  }
  return force;
}

std::vector<Vec3> gauss_point_loads(const RodModel& model, const Kinematics& kinematics, double load_factor) {
  std::vector<Vec3> loads;
  if (!model.gravity.isZero(0.0) || !model.point_forces.empty()) {
    const auto& points = kinematics.points();
    loads.reserve(points.size());
    for (std::size_t g = 0; g < points.size(); ++g)
      loads.push_back(load_factor * (points[g].mass * model.gravity +
                                     (model.point_forces.empty() ? Vec3::Zero() : model.point_forces[g])));
  }
  return loads;
}

VecX external_generalised_force(const RodModel& model, const Kinematics& kinematics, double load_factor) {
  return generalised_force(kinematics, gauss_point_loads(model, kinematics, load_factor),
                           load_factor * model.end_force, load_factor * model.end_moment);
}

double elastic_energy(const RodModel& model, const VecX& q) {
  const VecX strain = q - natural_strain_vector(model);
  return 0.5 * strain.dot(generalised_stiffness(model).cwiseProduct(strain));
}

double gravity_energy(const RodModel& model, const Kinematics& kinematics) {
  double energy = 0.0;
  for (const auto& point : kinematics.points()) energy -= point.mass * model.gravity.dot(point.position);
  return energy;
}

}  // namespace rodvv::solvers::superhelix
