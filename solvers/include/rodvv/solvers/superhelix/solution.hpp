#pragma once
// The 3-D solution struct (common/spatial_rod.hpp) of a Super-Helix configuration q.
//   stations at the element midpoints s = (Q + 1/2) ell, where the constant element strain is a
//   second-order approximation of the continuous strain: position and frame (closed form),
//   u = q_Q, v = e0, m = R K (q_Q - q0_Q) (constitutive law), n from force balance n' + f = 0 with
//   the dead loads, n(s) = F_end + rho S g (L - s), V = -rho S g . r; with self-contact, n(s) also
//   sums the contact forces beyond s (at the Gauss points and at their feet) and V adds the contact
//   field V_eff(s) (self_contact.hpp: contact_field); the model's dead point forces at the Gauss points
//   (contact forces of inverse and frictional statics) enter n(s) the same way (one at the station
//   itself, with one Gauss point per element, counts half);
//   vertices: the N + 1 element ends.
#include <cstddef>
#include <string>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"

namespace rodvv::solvers::superhelix {

SpatialRodSolution make_solution(const RodModel& model, const VecX& q, std::string method = "super-helix");
// With hard self-contact (hard_self_contact.hpp) the forces are the statics' multipliers: `contacts` (its
// HardContactStatics::contacts) enter n(s) the same way, and there is no contact field. make_solution without
// them refuses a model with hard self-contact (InputError "self_contact.law"), and this one any other model.
SpatialRodSolution make_solution(const RodModel& model, const VecX& q, const std::vector<ArcContact>& contacts,
                                 std::string method = "super-helix");

// Shared by make_solution and make_clothoid_solution (clothoid_solution.hpp).
// One station of an inextensible, unshearable rod under the model's dead loads: pose (r, R), strain
// u (v = e0), m = R K (u - u_hat), n(s) = F_end + rho S g (L - s), V = -rho S g . r, no shear energy.
void append_station(SpatialRodSolution& solution, const RodModel& model, double s, const Vec3& r, const Mat3& R,
                    const Vec3& u, const Vec3& u_hat);
// The N + 1 element ends as vertices, from any kinematics offering base_position(i) and base_frame(i).
template <class Kinematics>
void append_vertices(SpatialRodSolution& solution, const Kinematics& kinematics, std::size_t elements, double ell) {
  for (std::size_t i = 0; i <= elements; ++i) {
    solution.vertex_s.push_back(static_cast<double>(i) * ell);
    solution.vertex_position.push_back(kinematics.base_position(i));
    solution.vertex_frame.push_back(kinematics.base_frame(i));
  }
}

}  // namespace rodvv::solvers::superhelix
