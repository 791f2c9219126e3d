#pragma once
// Quasi-static frictional contact of a bundle of Super-Helices with rigid obstacles and with each other:
// the forward problem of inverse_bundle.hpp, as frictional_statics.hpp is that of inverse_contact.hpp
// (ALGORITHMS.md §4.1 and §4.2). frictional_statics.hpp's increment for one rod is this solver with one
// strand; its header states the method, which is the same here over the strands' coordinates stacked,
// q = (q_1, ..., q_S).
//
// Contacts between rods, point to curve: every Gauss point g of strand a against its foot on the
// centreline of every strand b > a (the material point (element, sigma) of b nearest x_g, by projection),
// when within `contact_distance` of touching; they touch at a centreline distance `law.distance` (the sum
// of the two radii). Its gap is |x_g - x_b(foot)| - distance, its normal n = (x_g - x_b(foot)) / |...|
// (perpendicular to b's tangent away from b's ends), its force r = (r_N, r_T1, r_T2) in contact_frame(n)
// acts as +frame r on a at g and -frame r on b at the foot, and its slip is the increment's relative motion
// of the two material points, ((x_g - x_g,prev) - (x_b(foot) - x_b,prev(foot))) . (t1, t2), with b's
// material point placed at the previous equilibrium by its q and root placement. Its Jacobian J_rel =
// (J_g, -J_b(foot)) over (q_a, q_b) takes J_g's place in H and in the normal's turning term -J_rel^T r_N
// dn/dx J_rel of A, with dn/dx = (I - n n^T - t t^T) / |x_g - x_b(foot)| (t b's tangent at the foot, along
// which the foot follows x_g; the curvature's share, d kappa, is left out). A also holds the rest of the
// contact's exact tangent: n turning with t as b bends (dn = -t (t x n)^T Theta dq_b, Theta b's rotation
// Jacobian at the foot), the foot sliding along b with it (moving the reaction's lever arm), and the lever
// arm of the reaction held at the foot (point_load_jacobian, load_stiffness.hpp), as the Gauss points' are
// in static_jacobian; checked against finite differences of the residual (5e-10). The Coulomb
// coefficient is law.mu. Only the points of the lower-numbered strand are tested, so two strands crossing
// at a steep angle between two Gauss points are not seen: the model is for strands lying along each other
// (hair, cables in a bundle), as the inverse bundle's contacts. A is dense over all the strands (the
// turning term couples the two strands of a contact): a Newton iteration costs O((sum 3 N_s)^3) for A and
// O((3 m)^3) for the active set (m candidates), which suits bundles of tens of strands; the broad phase
// tests the points of a against b's bounding box first. The inverse (inverse_bundle.hpp) scales to thousands.
//
// The step's matrix is frictional_statics.hpp's, with one more stage before the Levenberg shift: A
// augmented on the normal rows of the contacts that carry a force and also on the tangential rows of those
// that stick (force strictly inside the cone; their slip stays 0). A strand resting on another is unstable
// across it without them (the normal turns at r_N / d, d = 2 a; an obstacle's at r_N / its radius).
//
// Converged when every strand's relative equilibrium residual and step meet frictional_statics.hpp's
// test; the residual reported is the largest over the strands.
//
// Known limits (2026-12-08). Tested: strands sliding on each other without friction (a rod drawn down the
// groove of two others held on a plane by friction) and strands sticking on each other (tests/solvers/
// test_superhelix_bundle_frictional_statics.cpp). Not yet: strands sliding on each other with friction, the
// same groove with the upper rod's Gauss points against the lower rods' centrelines, and inverse/bundle's
// hair held at its target by the inverse's rest shapes. There the contact problem is degenerate (the
// sticking forces along an inextensible strand near its clamp are not determined: W has eigenvalues at
// the 1e-12 compliance), the active set cycles between sticking and sliding and the Gauss-Seidel fallback
// stalls between 1e-10 and 1e-7: SolverError, with the iterations and the residual.
// Bad input (InputError naming it): as frictional_statics.hpp for every strand ("point_forces",
// "self_contact", "obstacles"); no strand ("strands"); law.distance < 0 or law.mu < 0, not finite ("law");
// a previous state with another strand count, or one that does not fit a strand or lacks its root's
// placement, or a rod contact naming a strand or point out of range or one strand twice ("previous");
// options out of range. A Gauss point on another strand's centreline (no normal): SolverError.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/frictional_statics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct RodRodContactLaw {
  double distance = 0.0;  // centreline distance at which two strands touch (the sum of their radii); 0: they do not
  double mu = 0.0;        // Coulomb friction coefficient between strands, >= 0
};

struct RodRodContact {
  std::size_t strand = 0, point = 0;  // the strand that feels +force, its Gauss point
  std::size_t other_strand = 0;       // the strand that feels -force, at the point's foot:
  std::size_t other_element = 0;      //   its element
  double other_sigma = 0.0;           //   and the offset in it
  Vec3 foot = Vec3::Zero();           //   there, in the world
  double gap = 0.0;                   // |x_g - x_b(foot)| - distance at the solution
  Mat3 frame = Mat3::Identity();      // columns (n, t1, t2), n from the foot to the point
  Vec3 local_force = Vec3::Zero();    // r = (r_N, r_T1, r_T2)
  Vec3 force = Vec3::Zero();          // world: frame * r, on `strand`
  Vec3 slip = Vec3::Zero();           // (gap, t1 . dx_rel, t2 . dx_rel) of the increment
};

// A bundle's equilibrium (or the start of its load path). strands[s] holds strand s's q, Gauss points and
// obstacle contacts, with the bundle's iterations and residuals.
struct BundleFrictionalResult {
  std::vector<FrictionalStaticResult> strands;
  std::vector<RodRodContact> rod_contacts;  // the candidates at the solution (a zero force: open)
  std::size_t iterations = 0;
  double residual = 0.0;          // the largest relative equilibrium residual over the strands
  double contact_residual = 0.0;  // natural-map residual of the last contact solve
  double penetration = 0.0;       // max(0, -gap) over obstacles and strand pairs
};

// The start of a load path: strand s at q[s], no contact force (InputError "q" as kinematics.hpp; "strands"
// if the counts differ or there is no strand).
BundleFrictionalResult bundle_frictional_start(const std::vector<RodModel>& strands, const std::vector<VecX>& q);

// One increment from `previous` to the equilibrium of the strands under their current loads and root
// placements, starting from previous's q with its contact forces.
BundleFrictionalResult solve_bundle_frictional_increment(const std::vector<RodModel>& strands,
                                                         const std::vector<RigidObstacle>& obstacles,
                                                         const RodRodContactLaw& law,
                                                         const BundleFrictionalResult& previous,
                                                         const FrictionalStaticOptions& options = {});

}  // namespace rodvv::solvers::superhelix
