#include "rodvv/solvers/superhelix/clothoid_statics.hpp"

#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/clothoid_load_stiffness.hpp"

namespace rodvv::solvers::superhelix {

void validate_clothoid(const RodModel& model) {
  validate(model);
  // Dead forces at the Gauss points are statics loads the clothoid takes (clothoid_external_force); its
  // dynamics refuse them (clothoid_dynamics.cpp). Self-contact and the sliding clamp it has not.
  require_no_self_contact_or_tip_guide(model, "the super-clothoid");
  if (!model.natural_strain_per_element.empty())
    throw InputError("natural_strain_per_element",
                     "invalid parameter 'natural_strain_per_element': must be empty for the super-clothoid "
                     "(nodal strains; use natural_strain)");
}

VecX clothoid_natural_strain_vector(const RodModel& model) {
  VecX q0(static_cast<Eigen::Index>(clothoid_dof_count(model)));
  for (std::size_t j = 0; j <= model.elements; ++j) q0.segment<3>(3 * j) = model.natural_strain;
  return q0;
}

MatX clothoid_stiffness(const RodModel& model) {
  const auto n = static_cast<Eigen::Index>(clothoid_dof_count(model));
  MatX K = MatX::Zero(n, n);
  const double ell = element_length(model);
  const Mat3 C = model.stiffness.asDiagonal();
  for (std::size_t e = 0; e < model.elements; ++e) {
    const auto i = static_cast<Eigen::Index>(3 * e);
    K.block<3, 3>(i, i) += (ell / 3.0) * C;
    K.block<3, 3>(i + 3, i + 3) += (ell / 3.0) * C;
    K.block<3, 3>(i, i + 3) += (ell / 6.0) * C;
    K.block<3, 3>(i + 3, i) += (ell / 6.0) * C;
  }
  return K;
}

VecX clothoid_generalised_force(const ClothoidKinematics& kinematics, const std::vector<Vec3>& point_forces,
                                const Vec3& tip_force, const Vec3& tip_moment) {
  const std::size_t n = kinematics.elements(), per = kinematics.points_per_element();
  VecX force = VecX::Zero(static_cast<Eigen::Index>(3 * (n + 1)));
  Vec3 moment_about_next = tip_moment;  // moment of everything downstream about p_{Q+1}
  Vec3 resultant = tip_force;
  const auto& points = kinematics.points();
  if (!point_forces.empty() && point_forces.size() != points.size())
    throw InputError("point_forces", "invalid parameter 'point_forces': must be empty or hold one force per "
                                     "Gauss point (" + std::to_string(points.size()) + ")");
  for (std::size_t e = n; e-- > 0;) {
    Eigen::Matrix<double, 6, 1> generalised = kinematics.end_rotation_jacobian(e).transpose() * moment_about_next +
                                              kinematics.end_translation_jacobian(e).transpose() * resultant;
    moment_about_next += (kinematics.base_position(e + 1) - kinematics.base_position(e)).cross(resultant);
    if (!point_forces.empty()) {
      for (std::size_t g = 0; g < per; ++g) {
        const ClothoidPoint& point = points[e * per + g];
        const Vec3& f = point_forces[e * per + g];
        generalised += point.local_jacobian.transpose() * f;
        moment_about_next += point.offset.cross(f);
        resultant += f;
      }
    }
    force.segment<6>(static_cast<Eigen::Index>(3 * e)) += generalised;  // nodes e and e + 1
  }
  return force;
}

bool clothoid_loads_at_points(const RodModel& model) { return !model.gravity.isZero(0.0) || !model.point_forces.empty(); }

std::vector<Vec3> clothoid_point_loads(const RodModel& model, const ClothoidKinematics& kinematics,
                                       double load_factor) {
  std::vector<Vec3> loads;  // gravity m_g g plus the dead point forces, per Gauss point
  if (!clothoid_loads_at_points(model)) return loads;
  if (kinematics.points().empty())
    throw InputError("kinematics", "invalid parameter 'kinematics': built without Gauss points, but gravity or "
                                   "point forces are non-zero (construct it with with_points = true)");
  loads.reserve(kinematics.points().size());
  for (std::size_t g = 0; g < kinematics.points().size(); ++g)
    loads.push_back(load_factor * (kinematics.points()[g].mass * model.gravity +
                                   (model.point_forces.empty() ? Vec3::Zero() : model.point_forces[g])));
  return loads;
}

VecX clothoid_external_force(const RodModel& model, const ClothoidKinematics& kinematics, double load_factor) {
  return clothoid_generalised_force(kinematics, clothoid_point_loads(model, kinematics, load_factor),
                                    load_factor * model.end_force, load_factor * model.end_moment);
}

double clothoid_elastic_energy(const RodModel& model, const VecX& q) {
  const VecX strain = q - clothoid_natural_strain_vector(model);
  return 0.5 * strain.dot(clothoid_stiffness(model) * strain);
}

double clothoid_gravity_energy(const RodModel& model, const ClothoidKinematics& kinematics) {
  double energy = 0.0;
  for (const auto& point : kinematics.points()) energy -= point.mass * model.gravity.dot(point.position);
  return energy;
}

VecX clothoid_static_residual(const RodModel& model, const VecX& q, double load_factor) {
  const ClothoidKinematics kinematics(model, q, clothoid_loads_at_points(model));
  return clothoid_stiffness(model) * (q - clothoid_natural_strain_vector(model)) -
         clothoid_external_force(model, kinematics, load_factor);
}

MatX clothoid_static_jacobian(const RodModel& model, const VecX& q, double load_factor) {
  const ClothoidKinematics kinematics(model, q, clothoid_loads_at_points(model));
  MatX J = clothoid_load_stiffness(model, kinematics, load_factor);  // in place: one n x n buffer
  J *= -1.0;
  J += clothoid_stiffness(model);
  return J;
}

StaticResult solve_clothoid_static(const RodModel& model, const StaticOptions& options) {
  validate_clothoid(model);
  const VecX q0 = clothoid_natural_strain_vector(model);
  const MatX K = clothoid_stiffness(model);
  NewtonScales scales;
  scales.stiffness_max = K.cwiseAbs().rowwise().sum().maxCoeff();
  scales.length = model.length;
  const bool with_points = clothoid_loads_at_points(model);  // Gauss points carry gravity and point forces
  scales.load_scale =
      clothoid_external_force(model, ClothoidKinematics(model, q0, with_points), 1.0).lpNorm<Eigen::Infinity>();
  const StaticResidual residual = [&model, &K, &q0, with_points](const VecX& x, double lambda) {
    return VecX(K * (x - q0) - clothoid_external_force(model, ClothoidKinematics(model, x, with_points), lambda));
  };
  const StaticJacobian jacobian = [&model](const VecX& x, double lambda) {
    return clothoid_static_jacobian(model, x, lambda);
  };
  return newton_load_stepping(residual, q0, scales, options, "super-clothoid Newton", jacobian);
}

}  // namespace rodvv::solvers::superhelix
