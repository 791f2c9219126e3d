#include "rodvv/solvers/rod3d/model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::rod3d {

namespace {

// A rotation to 1e-10 (a frame computed in double precision, not a guess).
void require_rotation(const std::string& name, const Mat3& frame) {
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) require_finite(name, frame(i, k));
  const double orthogonality = (frame.transpose() * frame - Mat3::Identity()).cwiseAbs().maxCoeff();
  if (orthogonality > 1e-10 || std::abs(frame.determinant() - 1.0) > 1e-10)
    throw InputError(name, "invalid parameter '" + name +
                               "': must be a rotation matrix (orthonormal columns, det +1, to 1e-10)");
}

void validate_end(const std::string& name, const EndCondition& end) {
  if (end.support == EndSupport::Free) return;
  require_finite_vector(name + ".position", end.position);
  require_rotation(name + ".frame", end.frame);
  require_finite(name + ".rotation", end.rotation);
  if (std::abs(end.rotation) > kMaxEndRotation)
    throw InputError(name + ".rotation", "invalid parameter '" + name + ".rotation' = " + format_value(end.rotation) +
                                             ": must lie in [-" + format_value(kMaxEndRotation) + ", " +
                                             format_value(kMaxEndRotation) + "] rad (1000 turns)");
  if (end.slides) {
    if (end.support != EndSupport::Clamped)
      throw InputError(name + ".slides", "invalid parameter '" + name + ".slides': only a clamped end can slide");
    if (sliding_axis(end) < 0)
      throw InputError(name + ".slides", "invalid parameter '" + name +
                                             ".slides': a sliding clamp's tangent frame.col(0) must be a coordinate "
                                             "axis (+-e_x, +-e_y or +-e_z)");
  }
}

}  // namespace

int sliding_axis(const EndCondition& end) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(end.frame(k, 0)) - 1.0) <= 1e-14) return k;
  return -1;
}

double dead_load_scale(const RodModel& model, double load_factor) {
  const double L = model.length;
  double total_force = 0.0, total_moment = 0.0;  // a distributed load counts by its resultant's size
  for (const Vec3& f : model.vertex_forces) total_force += f.norm();
  for (const Vec3& m : model.edge_moments) total_moment += m.norm();
  double force = std::max({model.end_force.norm(), model.end_moment.norm() / L,
                           model.line_density * model.gravity.norm() * L, total_force, total_moment / L});
  return load_factor * force;
}

void validate(const RodModel& model) {
  require_at_least("elements", model.elements, 2);
  require_positive("length", model.length);
  require_positive("stiffness.twist (GJ)", model.stiffness[0]);
  require_positive("stiffness.bending1 (EI1)", model.stiffness[1]);
  require_positive("stiffness.bending2 (EI2)", model.stiffness[2]);
  require_finite_vector("natural_strain", model.natural_strain);
  if (!is_inextensible(model)) require_positive("extensional_stiffness (EA, or +inf)", model.extensional_stiffness);
  require_positive("line_density", model.line_density);
  require_non_negative("twist_inertia", model.twist_inertia);
  require_finite_vector("gravity", model.gravity);
  require_finite_vector("end_force", model.end_force);
  require_finite_vector("end_moment", model.end_moment);
  const auto require_per = [](const char* name, const std::vector<Vec3>& values, std::size_t count, const char* of) {
    if (!values.empty() && values.size() != count)
      throw InputError(name, std::string("invalid parameter '") + name + "': " + std::to_string(values.size()) +
                                 " values, must be empty or one per " + of + " (" + std::to_string(count) + ")");
    for (const Vec3& value : values) require_finite_vector(name, value);
  };
  require_per("vertex_forces", model.vertex_forces, model.elements + 1, "vertex");
  require_per("edge_moments", model.edge_moments, model.elements, "edge");
  validate_end("root", model.root);
  validate_end("tip", model.tip);
  if (has_self_contact(model)) {
    require_positive("self_contact.radius", model.self_contact.radius);
    if (is_hard(model.self_contact)) {
      if (model.self_contact.stiffness != 0.0)
        throw InputError("self_contact.stiffness", "invalid parameter 'self_contact.stiffness' = " +
                                                       format_value(model.self_contact.stiffness) +
                                                       ": must be 0 with the hard contact law (it has no barrier)");
    } else {
      require_positive("self_contact.stiffness", model.self_contact.stiffness);
    }
    // Segments within pi h of each other along the rod never count (self_contact.hpp): at least one
    // pair must remain.
    const std::size_t excluded = contact_excluded_neighbours(model.self_contact.radius, rest_edge_length(model));
    if (excluded + 1 >= model.elements)
      throw InputError("self_contact.radius",
                       "invalid parameter 'self_contact.radius' = " + format_value(model.self_contact.radius) +
                           ": must be below (N - 2) ebar / pi = " +
                           format_value(double(model.elements - 2) * rest_edge_length(model) / 3.141592653589793) +
                           " (a thicker rod of this length cannot touch itself)");
  }
  if (model.tip.support == EndSupport::Clamped && model.root.support == EndSupport::Clamped)
    require_at_least("elements (both ends clamped)", model.elements, 3);
  if (is_inextensible(model) && model.root.support != EndSupport::Free && model.tip.support != EndSupport::Free &&
      !model.root.slides && !model.tip.slides &&
      !((model.tip.position - model.root.position).norm() <= model.length * (1.0 + 1e-14)))
    throw InputError("tip.position", "invalid parameter 'tip.position': the supported ends are " +
                                         format_value((model.tip.position - model.root.position).norm()) +
                                         " apart, farther than the inextensible rod between them is long (" +
                                         format_value(model.length) + ")");
}

}  // namespace rodvv::solvers::rod3d
