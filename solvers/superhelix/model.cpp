#include "rodvv/solvers/superhelix/model.hpp"

#include <Eigen/LU>

#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::superhelix {

namespace {

// A rotation: orthonormal columns and det = +1, to 1e-10 (a frame built from unit vectors in double
// precision is orthonormal to ~1e-15; 1e-10 accepts frames typed with ~10 digits).
void require_rotation(const std::string& name, const Mat3& frame) {
  for (int i = 0; i < 3; ++i) require_finite_vector(name, frame.col(i));
  const double orthogonality = (frame.transpose() * frame - Mat3::Identity()).norm();
  const double det = frame.determinant();
  if (!(orthogonality <= 1e-10) || !(std::abs(det - 1.0) <= 1e-10))
    throw InputError(name, "invalid parameter '" + name + "': must be a rotation matrix (|R^T R - I| <= 1e-10 and "
                               "|det R - 1| <= 1e-10), got |R^T R - I| = " + format_value(orthogonality) +
                               ", det R = " + format_value(det));
}

}  // namespace

void validate(const RodModel& model) {
  require_at_least("elements", model.elements, 1);
  require_positive("length", model.length);
  require_positive("stiffness.twist (GJ)", model.stiffness[0]);
  require_positive("stiffness.bending1 (EI1)", model.stiffness[1]);
  require_positive("stiffness.bending2 (EI2)", model.stiffness[2]);
  require_positive("line_density", model.line_density);
  require_non_negative("rotational_inertia.twist (rho I0)", model.rotational_inertia[0]);
  require_non_negative("rotational_inertia.bending1 (rho I1)", model.rotational_inertia[1]);
  require_non_negative("rotational_inertia.bending2 (rho I2)", model.rotational_inertia[2]);
  require_non_negative("rayleigh_stiffness", model.rayleigh_stiffness);
  require_finite_vector("natural_strain", model.natural_strain);
  if (!model.natural_strain_per_element.empty()) {
    if (model.natural_strain_per_element.size() != model.elements)
      throw InputError("natural_strain_per_element",
                       "invalid parameter 'natural_strain_per_element': must be empty or hold one value "
                       "per element (" + std::to_string(model.elements) + "), got " +
                           std::to_string(model.natural_strain_per_element.size()));
    for (const auto& q0 : model.natural_strain_per_element)
      require_finite_vector("natural_strain_per_element", q0);
  }
  require_finite_vector("gravity", model.gravity);
  require_finite_vector("root_position", model.root_position);
  require_finite_vector("end_force", model.end_force);
  require_finite_vector("end_moment", model.end_moment);
  require_rotation("root_frame", model.root_frame);
  if (model.self_contact.radius != 0.0 || model.self_contact.stiffness != 0.0 || is_hard(model.self_contact))
    validate_self_contact(model.self_contact, "self_contact.");
  if (model.tip_guide.stiffness != 0.0 || model.tip_guide.rotational_stiffness != 0.0) {
    require_positive("tip_guide.stiffness", model.tip_guide.stiffness);
    require_positive("tip_guide.rotational_stiffness", model.tip_guide.rotational_stiffness);
    require_finite_vector("tip_guide.point", model.tip_guide.point);
    require_rotation("tip_guide.frame", model.tip_guide.frame);
  }
  if (model.gauss_points < 1 || model.gauss_points > 8)
    throw InputError("gauss_points", "invalid parameter 'gauss_points' = " +
                                         std::to_string(model.gauss_points) + ": must be an integer in [1, 8]");
  if (!model.point_forces.empty()) {
    if (model.point_forces.size() != model.elements * model.gauss_points)
      throw InputError("point_forces", "invalid parameter 'point_forces': must be empty or hold one force per Gauss "
                                       "point (" + std::to_string(model.elements * model.gauss_points) + "), got " +
                                           std::to_string(model.point_forces.size()));
    for (const auto& f : model.point_forces) require_finite_vector("point_forces", f);
  }
}

void validate_self_contact(const SelfContact& contact, const std::string& prefix) {
  require_positive(prefix + "radius", contact.radius);
  if (!is_hard(contact)) {
    require_positive(prefix + "stiffness", contact.stiffness);
  } else if (contact.stiffness != 0.0) {
    const std::string name = prefix + "stiffness";
    throw InputError(name, "invalid parameter '" + name + "' = " + format_value(contact.stiffness) +
                               ": must be 0 with the hard contact law (it has no barrier)");
  }
}

void require_statics_only_loads_absent(const RodModel& model, const char* what) {
  if (!model.point_forces.empty())
    throw InputError("point_forces", std::string("invalid parameter 'point_forces': ") + what +
                                         " does not take forces at the Gauss points (statics only); must be empty");
  require_no_self_contact_or_tip_guide(model, what);
}

void require_no_self_contact_or_tip_guide(const RodModel& model, const char* what) {
  if (model.self_contact.radius != 0.0)
    throw InputError("self_contact", std::string("invalid parameter 'self_contact': ") + what +
                                         " does not take self-contact (statics only); its radius must be 0");
  if (model.tip_guide.stiffness != 0.0)
    throw InputError("tip_guide", std::string("invalid parameter 'tip_guide': ") + what +
                                      " does not take a sliding clamp at the tip (statics only); its stiffness must be 0");
}

Vec3 elliptic_section_inertia(double line_density, double a, double b) {
  require_positive("line_density", line_density);
  require_positive("a", a);
  require_positive("b", b);
  return 0.25 * line_density * Vec3(a * a + b * b, b * b, a * a);
}

Vec3 natural_strain(const RodModel& model, std::size_t element) {
  return model.natural_strain_per_element.empty() ? model.natural_strain
                                                  : model.natural_strain_per_element[element];
}

VecX natural_strain_vector(const RodModel& model) {
  VecX q0(dof_count(model));
  for (std::size_t e = 0; e < model.elements; ++e) q0.segment<3>(3 * e) = natural_strain(model, e);
  return q0;
}

void set_natural_strain_vector(RodModel& model, const VecX& q0) {
  if (q0.size() != Eigen::Index(dof_count(model)))
    throw InputError("natural_strain", "invalid parameter 'natural_strain': must hold 3 N = " +
                                           std::to_string(dof_count(model)) + " values, got " + std::to_string(q0.size()));
  model.natural_strain_per_element.resize(model.elements);
  for (std::size_t e = 0; e < model.elements; ++e) model.natural_strain_per_element[e] = q0.segment<3>(Eigen::Index(3 * e));
}

VecX generalised_stiffness(const RodModel& model) {
  VecX k(dof_count(model));
  const double ell = element_length(model);
  for (std::size_t e = 0; e < model.elements; ++e) k.segment<3>(3 * e) = model.stiffness * ell;
  return k;
}

}  // namespace rodvv::solvers::superhelix
