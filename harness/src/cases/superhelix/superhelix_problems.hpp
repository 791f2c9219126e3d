#pragma once
// The Super-Helix cases kept one problem per file (this folder); the older ones live in
// ../superhelix_cases.cpp, which registers these too.
#include "rodvv/harness/registry.hpp"

namespace rodvv::harness::superhelix_cases {

// The method description every Super-Helix case carries.
extern const char* const kMethod;

void add_bathe_bolourchi(Registry& registry);    // 45-degree bend, out-of-plane tip load
void add_lateral_torsional(Registry& registry);  // lateral-torsional buckling of a cantilever
void add_spinning_clamp_oracle(Registry& registry);  // the step against an independent Lagrangian oracle
void add_clothoid_energy_decay(Registry& registry);  // the super-clothoid's dynamics: energy loss, dense = O(N)

}  // namespace rodvv::harness::superhelix_cases
