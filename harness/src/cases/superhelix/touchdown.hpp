#pragma once
// superhelix/touchdown (touchdown.cpp): one level against a given reference, apart so that a test can run the
// level against a perturbed reference (the gates' teeth).
#include "rodvv/harness/case.hpp"
#include "rodvv/harness/parameters.hpp"
#include "rodvv/references/heavy_touchdown.hpp"

namespace rodvv::harness::superhelix_cases {

// One level of the case (N = level elements) measured against `reference` (references/heavy_touchdown.hpp).
LevelOutput touchdown_level(const Parameters& p, double level, const references::HeavyTouchdown& reference);

}  // namespace rodvv::harness::superhelix_cases
