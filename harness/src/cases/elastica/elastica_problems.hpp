#pragma once
// The planar elastica cases kept one problem per file (this folder); the older ones live in
// ../elastica_cases.cpp, which registers these too.
#include "rodvv/harness/registry.hpp"

namespace rodvv::harness::elastica_cases {

void add_manufactured(Registry& registry);  // manufactured planar equilibrium, polygon and arcs

}  // namespace rodvv::harness::elastica_cases
