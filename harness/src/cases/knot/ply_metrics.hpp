#pragma once
// What the plectoneme cases of both rods share (PHYSICS.md §5.2): the ply's laws for a free end loop at
// a measured R and theta (references/knot_and_ply.hpp; a left-handed ply, M_t > 0), the theta at which
// the M_t law gives a measured M_t, and the metrics both report from the measurements each rod makes of
// its own contacts and solution struct.
#include <string>
#include <vector>

#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/harness/case.hpp"
#include "rodvv/harness/gate.hpp"
#include "rodvv/references/knot_and_ply.hpp"

namespace rodvv::harness::knot_cases {

// The laws of a ply of bending stiffness B, radius R and helix angle theta, free end loop.
references::PlectonemeSolution ply_law(double B, double R, double theta);
// The theta in (0, pi/4) at which the law's M_t of a left-handed ply equals `moment` (bisection: it grows
// from 0 to infinity on it; a moment <= 0, of the wrong hand, gives theta -> 0).
double theta_of_moment(double B, double R, double moment);

// What a rod measured: in the middle of the ply (its outer quarters dropped) the strands' distance R and
// helix angle theta, the contact force per strand length p and the strand tension n.t; on the root's
// tail the tension n.t and the twisting moment m.t; max_s |H(s) - H_tail| / T_ext through the rod.
struct PlyMeasurement {
  double R = 0.0, theta = 0.0, contact_force = 0.0, strand_tension = 0.0;
  double tail_tension = 0.0, twisting_moment = 0.0;
  double H_deviation = 0.0;
};

// H_deviation, tension_law, tension_from_moment, moment_law, contact_force_law, strand_tension_law and the
// diagnostics helix_angle (deg), helix_angle_from_moment, ply_radius (R / h), tail_tension, twisting_moment.
void add_ply_metrics(LevelOutput& output, const PlyMeasurement& ply, double B, double h, double T_ext);
std::vector<MetricSpec> ply_metric_specs();

// The first-order envelope of a law's errors e_i measured at the default levels N_i: C = 2 max_i |e_i| N_i
// (h = 1/N), so that the bound at the finest level is twice the largest error the levels would give there
// at first order (the errors fall, but not monotonically: the ply's contact set changes).
GateSpec law_envelope(const std::string& metric, const std::vector<double>& elements, const std::vector<double>& errors);

// A law's error within a tenth of the quantity at every level (the resolution rodvv asks beside every
// order, gate.hpp kResolvedFraction): the gate of the plectoneme cases at any parameters.
GateSpec resolved_law(const std::string& metric);

// The station nearest to s (the tails' middle, where H_tail, the tension and M_t are read).
std::size_t station_nearest(const SpatialRodSolution& solution, double s);

}  // namespace rodvv::harness::knot_cases
