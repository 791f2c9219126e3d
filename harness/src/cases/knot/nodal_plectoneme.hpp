#pragma once
// The nodal rod's plectoneme, laid, relaxed and measured (PHYSICS.md §5.2): what knot/plectoneme-nodal
// (a convergence study at one helix angle) and knot/plectoneme-angles-nodal (the ply's laws over the
// helix angle) share. The rod (bending B, twisting C, radius h, barrier k = barrier T_ext / h^2) is laid
// on `layout` (plectoneme_tying.hpp) with the twist rate M_t(theta_0, h) / C that holds a left-handed ply,
// its tip clamped but sliding along its tail under the dead pull T_ext = the tension law at theta_0 and
// R = h, and relaxed by the pseudo-transient contact statics. Measured in the middle of the ply (the
// contact pairs between the strands, the quarter nearest the loop and the quarter nearest the junction
// dropped): per segment of the root's strand, its closest pair gives R = d / 2 and theta = 1/2 acos(-t1.t2);
// on the root's tail (its middle) the tension and M_t; H(s) through the rod.
#include <cstddef>
#include <optional>
#include <vector>

#include "../case_builder.hpp"
#include "plectoneme_tying.hpp"
#include "ply_metrics.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::harness::knot_cases {

struct NodalPly {
  double B = 0.0, C = 0.0, h = 0.0;
  double theta0 = 0.0;   // the laid helix angle (rad); T_ext is the tension law's at it and R = h
  double barrier = 0.0;  // k h^2 / T_ext
};

// B, C, radius and barrier from the parameters of both cases; theta0 is the caller's.
NodalPly nodal_ply_of(const Parameters& p, double theta0);
// The parameters B (default 1.3), C (default C), radius (any: the ply is posed in units of h, what shapes it
// is C/B, a window of each case) and barrier in [barrier_low, barrier_high] (measured by each case), default
// 500.
std::vector<Parameter> nodal_ply_parameters(double C, double barrier_low, double barrier_high);

// Lays, relaxes and measures: add_ply_metrics, the 3-D Noether metrics, the contact forces' series and the
// diagnostics contact_pairs, iterations, equilibrium_residual. SolverError (the method, iterations,
// residual) when the relaxation fails or ends off the ply: no self-contact, fewer than 3 strand segments in
// contact in its middle, or a helix angle there beyond 45 degrees.
LevelOutput relax_nodal_plectoneme(const NodalPly& ply, const PlyLayout& layout, std::size_t edges);

// Measures a relaxed ply (`result` of the statics on `model`, a rod of bending B and radius h pulled by
// T_ext) as relax_nodal_plectoneme does, the tails' tension, M_t and H_tail read at the station nearest
// to arclength `tail_station` on the root's tail.
LevelOutput measure_nodal_ply(const solvers::rod3d::RodModel& model, const solvers::rod3d::StaticResult& result,
                              double B, double h, double T_ext, double tail_station);

// The metric specs of relax_nodal_plectoneme's output, H_deviation with the given theoretical order.
std::vector<MetricSpec> nodal_plectoneme_metric_specs(std::optional<double> H_order);

}  // namespace rodvv::harness::knot_cases
