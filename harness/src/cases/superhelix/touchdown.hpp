#pragma once
// superhelix/touchdown (touchdown.cpp): its small-deflection reference and its level, apart so that a test
// can run the level against a perturbed reference (the gates' teeth).
#include "rodvv/harness/case.hpp"
#include "rodvv/harness/parameters.hpp"

namespace rodvv::harness::superhelix_cases {

// A heavy cantilever (EI, weight w per length, length L) clamped horizontally at height delta over a rigid
// floor, small deflections: lifted over l = (72 EI delta / w)^(1/4), y(xi) = w l xi^3 / (18 EI) -
// w xi^4 / (24 EI) with xi = l - x, the clamp's moment w l^2 / 6 and the floor's reaction w (L - 2 l / 3).
struct TouchdownReference {
  double L = 0.0, EI = 0.0, w = 0.0, delta = 0.0;
  double lifted() const;
  double height(double x) const;  // 0 on the floor (x >= l)
  double clamp_moment() const;
  double floor_reaction() const;
};

// One level of the case (N = level elements) measured against `reference`.
LevelOutput touchdown_level(const Parameters& p, double level, const TouchdownReference& reference);

}  // namespace rodvv::harness::superhelix_cases
