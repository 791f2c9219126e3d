#pragma once
// The knot family: knots and plies tied in rods with self-contact (PHYSICS.md §5), one problem per
// file in this folder.
#include "rodvv/harness/registry.hpp"

namespace rodvv::harness::knot_cases {

void add_trefoil_nodal(Registry& registry);     // open trefoil pulled by a dead load, nodal 3-D rod
void add_plectoneme_nodal(Registry& registry);  // plectoneme with a free end loop, both ends clamped, nodal 3-D rod

}  // namespace rodvv::harness::knot_cases
