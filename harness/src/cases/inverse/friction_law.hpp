#pragma once
// Coulomb's law at the contacts of a forward frictional equilibrium (frictional_statics.hpp), as the
// forward friction cases measure it: which loaded contacts slide (|r_T| = mu r_N with a slip), whether
// each sliding force opposes its slip, and whether any force leaves its cone.
#include <cstddef>
#include <vector>

#include "rodvv/solvers/superhelix/frictional_statics.hpp"

namespace rodvv::harness::inverse_cases {

struct FrictionLaw {
  std::size_t loaded = 0;      // contacts with r_N > 1e-9 of the largest
  std::size_t sliding = 0;     // loaded, |r_T| >= (1 - 1e-9) mu r_N and a slip > 0
  double cone_violation = 0.0;  // max (|r_T| - mu r_N)_+ / max r_N
  double slip_alignment = 0.0;  // max over sliding contacts of 1 + r_T.u_T / (|r_T| |u_T|): 0 when opposed
};

FrictionLaw friction_law(const std::vector<solvers::superhelix::FrictionalContact>& contacts, double mu);

}  // namespace rodvv::harness::inverse_cases
