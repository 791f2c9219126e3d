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

void add_trefoil_nodal(Registry& registry);     // open trefoil pulled by a dead load, nodal 3-D rod
void add_trefoil_superhelix(Registry& registry);  // the same on the Super-Helix
void add_trefoil_looseness_superhelix(Registry& registry);  // the Super-Helix trefoil toward the loose limit
void add_trefoil_barrier_limit(Registry& registry);  // both rods' trefoils as the barrier stiffens
void add_plectoneme_nodal(Registry& registry);
void add_plectoneme_superhelix(Registry& registry);  // the same ply on the Super-Helix, tip in a sliding clamp  // plectoneme with a free end loop, both ends clamped, nodal 3-D rod

}  // namespace rodvv::harness::knot_cases
