#pragma once
// The open trefoil on the Super-Helix, tied and relaxed (shared by knot/trefoil-superhelix, the sweep over
// N, and knot/trefoil-looseness-superhelix, the sweep over the rod's thickness).
//
// Tying: the braid closure of trefoil_tying.hpp at the nodal case's proportions (strands 1.25 h off the
// braid axis over |x| <= 10 h, closing arcs of radius 0.6 lambda, tails 3 h apart, lambda = sqrt(B/T)),
// but with tails 2 lambda long instead of 6 lambda: a Super-Helix has equal elements, and the shorter
// rod puts them where the knot is (ell = 1.7 h at N = 50, looseness 0.1). The rod is laid on the curve
// element by element (superhelix_on_curve.hpp) and relaxed at the full load by the statics with
// self-contact (superhelix/statics.hpp: Newton on the potential, Levenberg shift, at most 1.5 h of motion
// per step). The root is clamped, the tip free under the dead pull T e_x.
#include <cstddef>
#include <vector>

#include "rodvv/harness/case.hpp"
#include "rodvv/harness/parameters.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/newton.hpp"
#include "trefoil_metrics.hpp"

namespace rodvv::harness::knot_cases {

inline constexpr const char* kSuperHelixContactMethod =
    "Super-Helix (Bertails et al. 2006) with a C^2 line-contact barrier (k/3)(2h - d)^3 per unit length between "
    "Gauss points and their feet on the helical arcs (chord sort-and-sweep broad phase); statics by Newton on the "
    "potential with its exact Hessian, Levenberg shift and at most 1.5 h of motion per step";

// The knot tied in N elements and relaxed with the barrier: the model (barrier self-contact), its
// equilibrium, and the laying's largest miss of the curve / h. SolverError from the statics.
struct TiedSuperHelixTrefoil {
  solvers::superhelix::RodModel model;
  solvers::superhelix::StaticResult relaxed;
  double laying_miss = 0.0;
};
TiedSuperHelixTrefoil tie_superhelix_trefoil(const TrefoilKnot& knot, std::size_t elements);
// The ends' span along the pull e_x (the end shortening's L - span).
double span_along_pull(const solvers::superhelix::Kinematics& kinematics, const solvers::superhelix::RodModel& model);

// Ties the knot (its barrier k h^3 / T, the line barrier's stiffness per unit length) in N elements, relaxes it, and measures it: the trefoil metrics (trefoil_metrics.hpp), the
// contact-force series and the diagnostics below. SolverError when the knot comes undone.
LevelOutput relax_superhelix_trefoil(const TrefoilKnot& knot, std::size_t elements);
// barrier = k h^3 / T in [50, 5000] (default 500), measured at both ends with the default levels of both cases.
Parameter superhelix_barrier_parameter();
// The windows of the Super-Helix trefoils' parameters (each case with its levels: the N sweep, the barrier
// limit, the hard contact): looseness in [0.08, 0.12] and C/B in [0.3, 100], measured at their ends.
void require_superhelix_trefoil_window(Case& c);
// contact_points, deepest_overlap, laying_miss, iterations, equilibrium_residual.
std::vector<MetricSpec> superhelix_trefoil_diagnostic_specs();

}  // namespace rodvv::harness::knot_cases
