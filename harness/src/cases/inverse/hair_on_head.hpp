#pragma once
// The windows of the cases whose hair lies on a head (round-trip-sphere, bundle), measured on
// round-trip-sphere 2026-11-26 (every other parameter at its default): the world positions carry
// eps |R|, so lever arms lose |R| / L in relative precision (R / L = 160 passes, 400 fails the
// forward residual, 33 eps); the weight rhoS g L^3 / EI passes at 7.8e7 (g = 1e8), the forward
// Newton fails at 7.8e9. From the parameters R, L, rhoS, g and EI.
#include "rodvv/harness/case.hpp"

namespace rodvv::harness::inverse_cases {

void require_hair_on_head_windows(Case& c);

}  // namespace rodvv::harness::inverse_cases
