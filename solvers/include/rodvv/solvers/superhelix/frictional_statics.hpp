#pragma once
// Quasi-static frictional contact of a Super-Helix with rigid obstacles (ALGORITHMS.md §4.1: statics
// takes the dynamics' contact problem with A the tangent stiffness and u the displacement increment;
// §4.2 for the solver). The forward problem of the inverse statics with contact (inverse_contact.hpp).
//
// An increment takes the rod from a previous equilibrium, where its Gauss points were at x_prev, to
// the equilibrium under the model's current loads and root placement. Unknowns: q, and at every Gauss
// point g near an obstacle its contact force r_g = (r_N, r_T1, r_T2) in the frame (n, t1, t2) =
// contact_frame(n), n the obstacle's outward normal at x_g(q). Conditions:
//   K (q - q0) - F_ext(q) - sum_g J_g^T (n r_N + t1 r_T1 + t2 r_T2) = 0       (equilibrium)
//   u_g = (gap(x_g), t1 . (x_g - x_prev,g), t2 . (x_g - x_prev,g))              (gap and slip)
//   Signorini-Coulomb between u_g and r_g (contact/cone_complementarity.hpp, ConeLaw::Coulomb)
// with J_g = dx_g/dq (kinematics.hpp). Friction opposes the increment's slip; a point that sticks has
// not moved. The path of the loads is the caller's: friction makes the equilibrium depend on it, so a
// load history is a sequence of increments, each from the previous one's result (frictional_start for
// the first).
//
// Newton on (q, r): at q_k with forces r_k the equilibrium residual R_k and its Jacobian A (static_residual
// and static_jacobian with the forces as dead point loads, which already differentiate their lever
// arms, plus the turning of the normal force with the point on a curved obstacle, -J_g^T r_N dn/dx J_g);
// u linearised, u = H dq + w with H the rows (n, t1, t2)^T J_g and w the gaps and slips at q_k;
// eliminating dq = A^-1 (H^T (r - r_k) - R_k) leaves the contact problem u = W r + b with the Delassus
// operator W = H A^-1 H^T (symmetrised) and b = w - H A^-1 (R_k + H^T r_k), solved by a primal-dual
// active set (statuses open / stick / slide, the slip direction frozen and updated; Murty's least-index
// rule when it cycles), the block Gauss-Seidel with the exact local Coulomb solver as its fallback (alone it
// stalls on many contacts along one inextensible strand). At a fixed point dq = 0, so the law holds with the
// true gaps and slips whatever W's approximations. A rod held by its contacts (a rope round a drum) is
// unstable without them: where the forces r_k do not yet carry the load A is indefinite, and the step
// then solves the augmented equilibrium (an augmented Lagrangian on the contacts active at r_k: G their
// normal rows, g their gaps)  (A + rho G^T G) dq = -R_k - rho G^T g + H^T (r - r_k),  whose extra term
// rho G^T u_N vanishes on every contact that stays closed (the step is Newton's) and at a fixed point; rho
// the smallest of k_max / ell^2 x 10^j (j = 0 .. 6) that makes the matrix positive definite, else the same
// with G also holding the tangential rows of the contacts that stick (force strictly inside the cone; g their
// slips, which stay 0), else a Levenberg shift sigma diag(K) on the first (10^-6 x 10^j): a shorter step until
// the forces carry the load. Candidates: the Gauss points within
// `contact_distance` of an obstacle at q_k (others carry no force); a candidate whose gap opens takes off.
// Converged when the equilibrium residual |R|_inf <= tolerance * scale (scale = max(|K|_inf |q|_inf,
// |K|_inf / L, |F_ext(q0)|_inf, |J^T f|_inf)) after a step |dq|_inf L <= tolerance (1 + |q|_inf L).
// The floor: the Gauss-Seidel's tolerance (1e-12 of the force scale) and a compliance of 1e-12 of W's
// largest diagonal added to every block (a point locked to first order along a straight stretch from the
// clamp has a singular block) leave equilibrium residuals of ~1e-10; the default tolerance is 1e-9.
// Reported: the contact law's natural-map residual at the last solve and the largest penetration.
// The increment is bundle_frictional_statics.hpp's with one strand (one code path for both).
//
// Obstacles are convex and the rod stays outside: a half-space (plane), a ball, an infinite cylinder,
// a right-angled edge (a table's: the quarter-space behind two perpendicular faces, its edge rounded),
// each with its own friction coefficient. `radius` is the distance at which the rod's centreline
// touches (the obstacle's radius plus the rod's).
// Bad input (InputError naming it): as validate(model); point forces or self-contact in the model
// ("point_forces", "self_contact": the contact forces are this solver's); an obstacle with a direction
// that is not a unit vector to 1e-10, a radius not > 0 (ball, cylinder), mu < 0 or not finite
// ("obstacles"); a previous state whose q or points do not fit the model ("previous": 3N finite values,
// one finite point per Gauss point, contacts naming existing points and obstacles); options out of range. No convergence in max_iterations, a singular
// tangent stiffness or a non-finite step: SolverError with the iterations and the residual.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/contact/cone_complementarity.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

// The edge: the points within `radius` of the quarter-space {(x - point).direction <= 0, (x - point).side
// <= 0}, i.e. a solid whose faces have the outward normals `direction` (a table's top) and `side` (its
// front), meeting at an edge rounded with the radius `radius` about the line through `point` along
// direction x side. Its gap is the distance to that quarter-space minus the radius: an exact signed
// distance outside (|grad| = 1, the normal continuous over the rounding).
struct RigidObstacle {
  enum class Shape { Plane, Ball, Cylinder, Edge };
  Shape shape = Shape::Plane;
  Vec3 point = Vec3::Zero();       // plane: a point of it; ball: the centre; cylinder: a point of the axis;
                                   //   edge: a point of the rounding's axis
  Vec3 direction = Vec3::UnitZ();  // plane: the unit normal toward the rod; cylinder: the unit axis; edge: the
                                   //   unit outward normal of its first face
  double radius = 0.0;             // ball, cylinder, edge: > 0, to the rod's centreline
  double mu = 0.0;                 // Coulomb friction coefficient, >= 0
  Vec3 side = Vec3::UnitX();       // edge: the unit outward normal of its second face, orthogonal to direction
};

// The gap of x (> 0 outside), the outward unit normal at the closest surface point and its gradient
// dn/dx (0 for a plane; (I - n n^T) / d for a ball, (P - n n^T) / d for a cylinder or an edge's
// rounding, d the distance to the centre or axis and P the projection off the axis; 0 over an edge's faces).
struct ObstacleProximity {
  double gap = 0.0;
  Vec3 normal = Vec3::UnitZ();
  Mat3 normal_gradient = Mat3::Zero();
};
ObstacleProximity obstacle_proximity(const RigidObstacle& obstacle, const Vec3& x);

// InputError "obstacles" naming the obstacle: a point that is not finite, a direction that is not a unit
// vector to 1e-10 (plane, cylinder, edge), an edge's side that is not one or not orthogonal to its
// direction to 1e-10, a radius not > 0 (ball, cylinder, edge), mu < 0 or not finite.
void validate_obstacles(const std::vector<RigidObstacle>& obstacles);

struct FrictionalStaticOptions {
  double contact_distance = 0.0;    // candidate contacts: gap <= this; 0: one element length
  std::size_t max_iterations = 200;
  double tolerance = 1e-9;          // relative equilibrium residual and step, in (0, 1)
  contact::ConeSettings cone = {1e-12, 100000};
};

struct FrictionalContact {
  std::size_t point = 0;     // Gauss point (Kinematics::points() order)
  std::size_t obstacle = 0;  // index into the obstacles
  double gap = 0.0;          // at the solution
  Mat3 frame;                // columns (n, t1, t2)
  Vec3 local_force;          // r = (r_N, r_T1, r_T2)
  Vec3 force;                // world: frame * r
  Vec3 slip;                 // (gap, t1 . dx, t2 . dx) of the increment at the solution
};

// An equilibrium (or the start of a load path): q, the Gauss points' positions there (the next
// increment's x_prev) and the contact forces (its warm start).
struct FrictionalStaticResult {
  VecX q;
  std::vector<Vec3> points;                 // Gauss points' world positions at q
  Vec3 root_position = Vec3::Zero();        // the root's placement at q (the model's): with q it places any
  Mat3 root_frame = Mat3::Identity();       //   material point (a contact foot between strands slides along it)
  std::vector<FrictionalContact> contacts;  // the candidates at the solution (a zero force: open)
  std::size_t iterations = 0;               // Newton iterations
  double residual = 0.0;                    // |R|_inf of the equilibrium, relative to its scale
  double contact_residual = 0.0;            // natural-map residual of the last contact solve
  double penetration = 0.0;                 // max(0, -gap) over the Gauss points
};

// The start of a load path: the rod at q, no contact force (InputError "q" as kinematics.hpp).
FrictionalStaticResult frictional_start(const RodModel& model, const VecX& q);

// One increment from `previous` (an equilibrium of the path, or its start) to the equilibrium of
// `model`, starting from previous.q with previous.contacts' forces.
FrictionalStaticResult solve_frictional_increment(const RodModel& model, const std::vector<RigidObstacle>& obstacles,
                                                  const FrictionalStaticResult& previous,
                                                  const FrictionalStaticOptions& options = {});

}  // namespace rodvv::solvers::superhelix
