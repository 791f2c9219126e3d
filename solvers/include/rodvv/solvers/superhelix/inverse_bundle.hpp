#pragma once
// Inverse statics of a bundle of Super-Helices in frictional contact with obstacles and with each
// other (ALGORITHMS.md §3.2; Derouet-Jourdan, Bertails-Descoubes, Daviet & Thollot, "Inverse dynamic
// hair modeling with frictional contact", SIGGRAPH Asia 2013, where a head of hair has thousands of
// strands and tens of thousands of contacts). inverse_contact.hpp for one strand; here S strands with
// targets q_s share the contacts between them: a contact k between Gauss point g_a of strand a and
// Gauss point g_b of strand b (or an obstacle) carries r_k in its cone, +frame r_k on a and -frame r_k
// on b. The least-deformation SOCQP over all strands at once,
//
//   min_{r in K_mu}  sum_s 1/2 |K_s^-1 (F_s + H_s^T r)|^2 + gamma |r|^2,
//   W = sum_s H_s K_s^-2 H_s^T + 2 gamma I,   b = sum_s H_s K_s^-2 F_s,
//
// (q0bar_s = q_s; H_s the rows (n, t1, t2)^T dx_g/dq_s of the contacts touching strand s, signed for
// the force on it) is solved by the block Gauss-Seidel with the SOC law on the factored W
// (contact/factored_delassus.hpp: never formed; a sweep costs O(sum over contacts of the strands'
// degrees of freedom); the contacts visited from the free ends toward the roots, whatever their order
// here: a third fewer sweeps), then q0_s = q_s - K_s^-1 (F_s + H_s^T r). gamma is relative to the mean
// diagonal of sum_s H_s K_s^-2 H_s^T, as in inverse_contact.hpp; the frame of a contact is
// contact_frame(normal). A contact between two points of one strand is a self-contact (its two
// sides are merged: frame^T (J_a - J_b)).
// Bad input (InputError naming it): as validate(model) per strand and q ("q": one target per strand,
// 3N finite values each); a contact naming a strand or Gauss point out of range, or the same point
// twice, or a normal that is not a finite unit vector to 1e-10, or, between two rods, not the direction
// from the other point to this one within 1e-6, or two points at the same place ("contacts"); mu <= 0 or not finite
// ("mu"); gamma <= 0 ("gamma"). A SOCQP that does not converge: SolverError (sweeps, residual).
#include <cstddef>
#include <limits>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/contact/cone_complementarity.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

inline constexpr std::size_t kObstacle = std::numeric_limits<std::size_t>::max();

struct BundleContact {
  std::size_t strand = 0, point = 0;                    // the rod the force r acts on, its Gauss point
  std::size_t other_strand = kObstacle, other_point = 0;  // the rod that feels -r, or kObstacle
  Vec3 normal;  // unit, world, towards `strand`'s point (between rods: from the other point to it)
  double mu = 0.5;                                      // friction coefficient, > 0
};

struct InverseBundleOptions {
  double gamma = 1e-3;  // relative to the mean diagonal of sum_s H_s K_s^-2 H_s^T
  contact::ConeSettings solver = {};
};

struct InverseBundleResult {
  std::vector<VecX> natural_strain;  // q0_s per strand
  VecX local_forces;                 // r_k = (r_N, r_T1, r_T2) per contact, on `strand`
  std::vector<Mat3> frames;          // columns (n, t1, t2) per contact
  std::size_t sweeps = 0;
  double residual = 0.0;        // natural-map residual of the SOCQP
  double cone_violation = 0.0;  // max (|r_T| - mu r_N)_+, relative
};

InverseBundleResult inverse_statics_of_bundle(const std::vector<RodModel>& strands, const std::vector<VecX>& q,
                                              const std::vector<BundleContact>& contacts,
                                              const InverseBundleOptions& options = {});

// Each strand at rest in its q0 with the found forces as dead point forces (+frame r on `strand`,
// -frame r on `other_strand`): its forward statics holds its q, one strand at a time.
std::vector<RodModel> bundle_rest_models(const std::vector<RodModel>& strands,
                                         const std::vector<BundleContact>& contacts,
                                         const InverseBundleResult& result);

}  // namespace rodvv::solvers::superhelix
