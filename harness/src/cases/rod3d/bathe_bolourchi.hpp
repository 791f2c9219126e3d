#pragma once
// The Bathe-Bolourchi 45-degree bend solved on the nodal rod, for rod3d/bathe-bolourchi and as the
// independent oracle of its Super-Helix counterpart (superhelix/bathe-bolourchi).
#include <cstddef>
#include <vector>

#include "rodvv/harness/registry.hpp"

namespace rodvv::harness::rod3d_cases {

// The tip displacement's frame-free parts: along the load, and its magnitude in the arc's plane.
struct BatheBolourchiTip {
  double along_load = 0.0, in_plane = 0.0;
};

// A 45-degree arc of radius R, EI1 = EI2 = GJ = EI, inextensible, clamped (tilted plane), dead tip
// force P normal to its plane, on N edges.
BatheBolourchiTip nodal_bathe_bolourchi_tip(double R, double EI, double P, std::size_t elements);

// What both rods report (rod3d/ and superhelix/bathe-bolourchi): the parameters R, EI, P; the
// self-convergence |u(N) - u(2N)| of both tip parts and the tip at 2N against Kynema's converged
// geometrically exact beam (PRIOR_ART.md §4.2: (-23.6459716009047, 13.7208006040058,
// 53.5776450626987), compared through its frame-free parts), with their metric specs.
Parameters bathe_bolourchi_parameters();
void add_bathe_bolourchi_metrics(LevelOutput& output, const BatheBolourchiTip& tip, const BatheBolourchiTip& finer);
std::vector<MetricSpec> bathe_bolourchi_metric_specs();

}  // namespace rodvv::harness::rod3d_cases
