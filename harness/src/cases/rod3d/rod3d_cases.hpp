#pragma once
// The rod3d family: the nodal 3-D rod (solvers/rod3d, a discrete elastic rod), one problem per file.
// Each add_* registers one case (or the cases of one problem) with the shared case builder.
#include "rodvv/harness/registry.hpp"

namespace rodvv::harness::rod3d_cases {

// The method description every rod3d case carries.
extern const char* const kMethod;

void add_helix_axial_wrench(Registry& registry);  // uniform helix held by an axial wrench
void add_mattiasson(Registry& registry);          // Mattiasson cantilever in a tilted 3-D frame
void add_heavy_cantilever(Registry& registry);    // cantilever under its own weight in a tilted 3-D frame
void add_roll_up(Registry& registry);             // end-moment roll-up in a tilted 3-D frame
void add_modes(Registry& registry);               // bending and torsional frequencies of a cantilever
void add_energy_in_time(Registry& registry);      // energy of implicit Euler and midpoint on a swinging rod
void add_skew_vibration(Registry& registry);      // first-mode release skew to the principal planes vs Euler-Bernoulli
void add_helical_buckling(Registry& registry);    // localized helical buckling (PyElastica's case)
void add_bathe_bolourchi(Registry& registry);     // 45-degree bend, out-of-plane tip load
void add_lateral_torsional(Registry& registry);   // lateral-torsional buckling of a cantilever
void add_greenhill(Registry& registry);           // Greenhill twisted column, clamped and pinned
void add_michell_ring(Registry& registry);        // Michell twisted-ring instability (closed rod)
void add_manufactured(Registry& registry);        // manufactured 3-D equilibrium: distributed force and couple

}  // namespace rodvv::harness::rod3d_cases
