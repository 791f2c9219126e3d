#pragma once
// The open trefoil in the nodal 3-D rod, tied and relaxed (shared by knot/trefoil-nodal, the sweep over N,
// and knot/trefoil-barrier-limit-nodal, the sweep over the barrier's stiffness).
//
// Tying (trefoil_tying.hpp): the closure of the braid sigma_1^3 with its lower arc cut and drawn out into
// tails, in units of the knot's own scale lambda = sqrt(B/T) (the loose-knot loop: apex radius lambda/2,
// PHYSICS.md §5.1) and of the radius h: strands 1.25 h off the braid axis over |x| <= 10 h, closing arcs
// of radius 0.6 lambda, tails 6 lambda long passing 3 h apart. Relaxed to equilibrium at the full load by
// the statics with pseudo-transient continuation (rod3d/statics.hpp): the knot slides and turns about the
// pull axis (an exact zero mode of an isotropic rod), which a plain Newton iteration cannot follow. The
// root is clamped, the tip free under the dead pull T e_x; the barrier is k = barrier T / h^2 per segment
// pair (an overlap of about h / sqrt(barrier) at a contact force T). A level finer than 100 edges ties and
// relaxes the knot in 100 edges first, then refines the equilibrium (rod3d/refine.hpp), doubling the edges
// up to its N, and relaxes it again at each: the slide and turn of the knot into place take ~450
// iterations at any N, and each refinement leaves 15 to 30 (measured at the defaults: 454 iterations at
// N = 100, then 28 at 200 and 17 at 400; the same equilibria as tied directly at N, to the solver's
// tolerance; BM_TrefoilKnot in bench/bench_rod3d.cpp).
#include <cstddef>
#include <vector>

#include "rodvv/harness/case.hpp"
#include "trefoil_metrics.hpp"

namespace rodvv::harness::knot_cases {

// Ties the knot in N edges, relaxes it, and measures it: the trefoil metrics (trefoil_metrics.hpp), the
// contact-force series and the diagnostics below. SolverError when the knot comes undone.
LevelOutput relax_nodal_trefoil(const TrefoilKnot& knot, std::size_t edges);
// The same knot with hard contact (d >= 2h, solvers/rod3d/statics.hpp: Newton-LCP): relaxed with the
// barrier as above (the long slide and turn of the knot into place, where the barrier's smooth energy
// suits the pseudo-transient iteration), then hardened - the hard statics started from the barrier's
// equilibrium (15 to 51 iterations at N = 50 .. 400, statics.cpp; from the tied curve directly, 400 to 2900). The
// metrics gain overlap_over_tolerance (the deepest 2h - d over the statics' gap tolerance, tolerance x L)
// and the diagnostic hard_iterations; iterations counts both stages.
LevelOutput relax_nodal_trefoil_hard(const TrefoilKnot& knot, std::size_t edges);
// The nodal trefoil cases' windows: the looseness h sqrt(T/B) in [0.07, 0.15] and C/B in [0.3, 100] (measured on
// knot/trefoil-nodal, nodal_trefoil.cpp).
void require_nodal_trefoil_window(Case& c);

// contact_pairs, deepest_overlap, iterations, equilibrium_residual.
std::vector<MetricSpec> nodal_trefoil_diagnostic_specs();

}  // namespace rodvv::harness::knot_cases
