#pragma once
// The knot family: knots and plies tied in rods with self-contact (PHYSICS.md §5), one problem per
// file in this folder.
#include "rodvv/harness/registry.hpp"

namespace rodvv::harness::knot_cases {

// The method every knot case runs (the nodal rod's contact statics), as the report names it.
inline constexpr const char* kContactStaticsMethod =
    "discrete elastic rod (Bergou et al. 2008) with a C^2 self-contact barrier (k/3)(2h - d)^3 between "
    "non-adjacent segments (sort-and-sweep broad phase); statics by Newton with exact derivatives, sparse LU, "
    "pseudo-transient continuation (Kelley & Keyes 1998)";

// The nodal rod's hard contact (d >= 2h by complementarity, no barrier).
inline constexpr const char* kHardContactStaticsMethod =
    "discrete elastic rod (Bergou et al. 2008) with hard frictionless self-contact d >= 2h between non-adjacent "
    "segments: Newton-LCP (the linearised contacts' LCP solved by Lemke's method at every step, exact derivatives, "
    "sparse LU, pseudo-transient continuation), started from the barrier's equilibrium";

void add_trefoil_nodal(Registry& registry);     // open trefoil pulled by a dead load, nodal 3-D rod
void add_trefoil_superhelix(Registry& registry);  // the same on the Super-Helix
void add_trefoil_looseness_superhelix(Registry& registry);  // the Super-Helix trefoil toward the loose limit
void add_trefoil_barrier_limit(Registry& registry);  // both rods' trefoils as the barrier stiffens
void add_trefoil_hard_nodal(Registry& registry);  // the nodal rod's trefoil with hard contact
void add_trefoil_hard_superhelix(Registry& registry);  // the Super-Helix's trefoil with hard contact
void add_plectoneme_nodal(Registry& registry);  // plectoneme with a free end loop, both ends clamped, nodal 3-D rod
void add_plectoneme_angles_nodal(Registry& registry);  // the nodal ply's laws over the helix angle, 10 .. 25 deg
void add_plectoneme_superhelix(Registry& registry);  // the same ply on the Super-Helix, tip in a sliding clamp
void add_plectoneme_twisted_nodal(Registry& registry);  // a ply formed by twisting a straight rod, nodal 3-D rod

}  // namespace rodvv::harness::knot_cases
