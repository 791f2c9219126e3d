// knot/*: knots tied in rods with self-contact. One file per problem in this folder; this one lists them.
#include "knot_cases.hpp"

namespace rodvv::harness {

void register_knot_cases(Registry& registry) {
  knot_cases::add_trefoil_nodal(registry);
  knot_cases::add_trefoil_superhelix(registry);
  knot_cases::add_trefoil_looseness_superhelix(registry);
  knot_cases::add_trefoil_barrier_limit(registry);
  knot_cases::add_trefoil_hard_nodal(registry);
  knot_cases::add_trefoil_hard_superhelix(registry);
  knot_cases::add_plectoneme_nodal(registry);
  knot_cases::add_plectoneme_angles_nodal(registry);
  knot_cases::add_plectoneme_superhelix(registry);
  knot_cases::add_plectoneme_twisted_nodal(registry);
}

}  // namespace rodvv::harness
