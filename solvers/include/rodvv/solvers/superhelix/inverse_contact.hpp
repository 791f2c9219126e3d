#pragma once
// Inverse statics of a Super-Helix in frictional contact (ALGORITHMS.md §3.2; Derouet-Jourdan,
// Bertails-Descoubes, Daviet & Thollot, "Inverse dynamic hair modeling with frictional contact",
// SIGGRAPH Asia 2013). The target q touches obstacles at some Gauss points; at equilibrium every
// contact force may be anything in its Coulomb cone (all relative velocities vanish), so
//
//   K (q - q0) = F(q) + H^T r,   r_k = (r_N, r_T1, r_T2) in K_mu_k,   q0(r) = q - K^-1 (F + H^T r),
//
// is underdetermined; the paper picks the r that keeps q0 closest to a preferred rest shape q0bar
// (by default q itself: the least deformation), regularised:
//
//   min_{r in K_mu}  1/2 |q - K^-1 (F + H^T r) - q0bar|^2 + gamma |r|^2
//   = min 1/2 r^T W r + b^T r,  W = H K^-2 H^T + 2 gamma I,  b = -H K^-1 z,  z = q - K^-1 F - q0bar,
//
// a convex SOCQP whose KKT conditions are the plain SOC complementarity K_mu ∋ r _|_ W r + b ∈ K_mu*,
// solved by the same block Gauss-Seidel as the forward frictional problem with the per-contact law
// swapped (contact/cone_complementarity.hpp, ConeLaw::SecondOrderCone; So-bogus does the same), which
// visits the contacts from the free end toward the root (fewer sweeps), whatever their order here.
// H: the rows (normal, t1, t2)^T dr_g/dq of each contact's Gauss point (kinematics.hpp), its frame
// built from the normal (t1 = the unit vector orthogonal to n in the plane of n and the world axis
// least aligned with it, t2 = n x t1). gamma is given relative to the mean diagonal of H K^-2 H^T
// (dimensionless, > 0): W stays SPD when contacts outnumber degrees of freedom.
//
// Then q0 follows, and with the found forces as dead loads at their Gauss points
// (RodModel::point_forces, contact_model) the forward statics holds q: the round trip.
// Bad input: as validate(model) and q (InputError "q"); a contact's point out of range, a normal
// that is not a unit vector to 1e-10 or not finite (InputError "contacts"); mu <= 0 or not finite
// ("mu"); gamma <= 0 ("gamma"); q0bar of the wrong size ("preferred_rest"). A SOCQP that does not
// converge: SolverError from the Gauss-Seidel, with its sweeps and residual.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/contact/cone_complementarity.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct RodContact {
  std::size_t point = 0;  // Gauss point (Kinematics::points() order)
  Vec3 normal;            // unit, world, from the obstacle towards the rod
  double mu = 0.5;        // friction coefficient, > 0
};

struct InverseContactOptions {
  double gamma = 1e-3;  // regularisation, relative to the mean diagonal of H K^-2 H^T
  VecX preferred_rest;  // q0bar, 3N values; empty: q
  contact::ConeSettings solver = {};
};

struct InverseContactResult {
  VecX natural_strain;            // q0
  VecX local_forces;              // r, (r_N, r_T1, r_T2) per contact
  std::vector<Vec3> forces;       // the same in world components
  std::vector<Mat3> frames;       // columns (n, t1, t2) per contact
  std::size_t sweeps = 0;
  double residual = 0.0;          // natural-map residual of the SOCQP (cone_complementarity.hpp)
  double cone_violation = 0.0;    // max (|r_T| - mu r_N)_+, relative
};

InverseContactResult inverse_statics_with_contacts(const RodModel& model, const VecX& q,
                                                   const std::vector<RodContact>& contacts,
                                                   const InverseContactOptions& options = {});

// The model at rest in q0 with the found contact forces as dead point forces: its forward statics
// holds q.
RodModel contact_model(const RodModel& model, const std::vector<RodContact>& contacts,
                       const InverseContactResult& result);

// The contact frame (n, t1, t2) of a unit normal (as above).
Mat3 contact_frame(const Vec3& normal);

}  // namespace rodvv::solvers::superhelix
