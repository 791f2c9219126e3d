#pragma once
// The data of a Super-Helix rod problem (ALGORITHMS.md §1; Bertails et al. 2006): a Kirchhoff rod
// (inextensible, unshearable) of length L clamped at s = 0, cut into N elements of equal length on
// which the material strains q_Q = (twist, kappa1, kappa2) are constant.
//
// Generalised coordinates: q in R^{3N}, q.segment<3>(3 Q) = (tau, kappa1, kappa2) of element Q.
// Frame convention: R = [n0 n1 n2] with n0 the tangent; R' = R [q_Q]x on element Q.
// Loads (all dead, world components): gravity acceleration g acting on the line density rho S,
// an end force and an end moment at s = L, and (statics only) forces at the Gauss points. Dissipation: stiffness-proportional (Rayleigh) damping
// gamma K qdot. Units: any consistent set.
//
// Inertia (dynamics only; statics never reads it): the line density rho S (translation) and the
// cross-section's rotational inertia per unit length J = diag(rho I0, rho I1, rho I2) in material
// components (index 0 = tangent n0, 1 = n1, 2 = n2): kinetic energy per unit length
//   1/2 rho S |r_t|^2 + 1/2 Omega . J Omega,   Omega = R^T omega (material angular velocity).
// For a solid section I0 = I1 + I2 (polar moment); elliptic_section_inertia gives J for an elliptic
// (or, a = b, circular) section of the model's density. The default J = (1e-2, 5e-3, 5e-3) is the
// solid circular section of radius 0.1414 (a^2 = 0.02) with the default rho S = 1 (the twist inertia
// rho I0 = 1e-2 of the nodal rod3d model), so that M is positive definite: without J a straight
// element's twist moves no mass and M is only semi-definite. J = 0 is the translational-only
// Super-Helix of Bertails et al. 2006 (an Euler-Bernoulli rod).
//
// validate() throws rodvv::InputError naming the parameter and its range for: zero elements,
// non-positive length / stiffness / density, a negative rotational inertia, a root frame that is not
// a rotation (|R^T R - I| or |det R - 1| above 1e-10), negative damping, a non-finite entry anywhere,
// a wrong-sized per-element natural strain or point-force list, fewer than 1 or more than 8 Gauss
// points.
#include <cstddef>
#include <string>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::superhelix {

// Frictionless self-contact (self_contact.hpp; statics only): through the cubic barrier, or hard (the
// constraint d >= 2h at the Gauss points, its forces the multipliers of a complementarity problem:
// hard_self_contact.hpp).
enum class ContactLaw { Barrier, Hard };

struct SelfContact {
  double radius = 0.0;     // h > 0: contact when two arcs are closer than 2h (0 in a model: none)
  double stiffness = 0.0;  // barrier: k > 0, force / length^3, the cubic barrier's per unit length of rod; hard: 0
  ContactLaw law = ContactLaw::Barrier;
};

inline bool is_hard(const SelfContact& contact) { return contact.law == ContactLaw::Hard; }

// A sliding clamp at the tip (tip_guide.hpp; statics only): the tip slides along the line through `point`
// along frame.col(0), its frame held at `frame`, by springs of stiffness k (off the axis) and k_r (turning).
struct TipGuide {
  double stiffness = 0.0;             // k >= 0, force / length; 0: no guide (the tip is free)
  double rotational_stiffness = 0.0;  // k_r > 0 with a guide, force x length (moment per radian^2 / 2)
  Vec3 point = Vec3::Zero();          // a point of the axis
  Mat3 frame = Mat3::Identity();      // the tip frame held (a rotation); its n0 is the axis
};

struct RodModel {
  double length = 1.0;
  std::size_t elements = 8;
  Vec3 stiffness = Vec3::Ones();          // (GJ, EI1, EI2): twist and the two bending stiffnesses
  Vec3 natural_strain = Vec3::Zero();     // q0, the same on every element ...
  std::vector<Vec3> natural_strain_per_element;  // ... unless this holds N values
  double line_density = 1.0;              // rho S, mass per unit length
  Vec3 rotational_inertia = Vec3(1e-2, 5e-3, 5e-3);  // (rho I0, rho I1, rho I2) >= 0, per unit length
  Vec3 gravity = Vec3::Zero();            // acceleration of gravity g
  Vec3 root_position = Vec3::Zero();
  Mat3 root_frame = Mat3::Identity();     // columns n0, n1, n2 at s = 0
  Vec3 end_force = Vec3::Zero();          // dead force at s = L
  Vec3 end_moment = Vec3::Zero();         // dead moment at s = L
  // Dead forces at the Gauss points (world, Kinematics::points() order): empty, or one per point
  // (elements x gauss_points). Statics only (contact forces held fixed, inverse_contact.hpp): the
  // dynamics, the solution struct and the super-clothoid refuse a non-empty list.
  std::vector<Vec3> point_forces;
  SelfContact self_contact;               // radius 0: none. Statics only (static_residual, static_jacobian)
  TipGuide tip_guide;                     // stiffness 0: none (a free tip). Statics only
  double rayleigh_stiffness = 0.0;        // gamma: damping force -gamma K qdot
  std::size_t gauss_points = 4;           // Gauss-Legendre points per element (mass, gravity)
};

void validate(const RodModel& model);
// InputError naming prefix + "radius" unless > 0, prefix + "stiffness" unless > 0 (barrier) or 0 (hard).
void validate_self_contact(const SelfContact& contact, const std::string& prefix);
// InputError "point_forces", "self_contact" or "tip_guide" naming `what` (the dynamics, the total energy,
// the super-clothoid, inverse statics), which do not take these statics-only loads.
void require_statics_only_loads_absent(const RodModel& model, const char* what);
// The same for self-contact and the sliding clamp alone (the super-clothoid's statics takes point forces).
void require_no_self_contact_or_tip_guide(const RodModel& model, const char* what);

// (rho I0, rho I1, rho I2) of a solid elliptic section of line density rho S with semi-axis a along
// n1 and b along n2 (S = pi a b, I1 = pi a b^3 / 4, I2 = pi a^3 b / 4, I0 = I1 + I2):
// rho S (a^2 + b^2) / 4, rho S b^2 / 4, rho S a^2 / 4. InputError for rho S, a or b not finite and > 0.
Vec3 elliptic_section_inertia(double line_density, double a, double b);

inline double element_length(const RodModel& model) {
  return model.length / static_cast<double>(model.elements);
}
inline std::size_t dof_count(const RodModel& model) { return 3 * model.elements; }

// q0 of element Q.
Vec3 natural_strain(const RodModel& model, std::size_t element);
// q0 as one vector of 3N values, and back: natural_strain_per_element from 3N values (InputError
// "natural_strain" for another size).
VecX natural_strain_vector(const RodModel& model);
void set_natural_strain_vector(RodModel& model, const VecX& q0);
// Diagonal of the generalised stiffness K_Q = diag(GJ, EI1, EI2) * ell_Q, as 3N values
// (U_elastic = 1/2 (q - q0)^T diag(K) (q - q0), ALGORITHMS.md §1.4).
VecX generalised_stiffness(const RodModel& model);

}  // namespace rodvv::solvers::superhelix
