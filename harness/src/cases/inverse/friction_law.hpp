#pragma once
// Coulomb's law at the contacts of a forward frictional equilibrium (frictional_statics.hpp), as the
// forward friction cases measure it: which loaded contacts slide (|r_T| = mu r_N with a slip), whether
// each sliding force opposes its slip, and whether any force leaves its cone; and the Noether quantity's
// balance along it (H' = -f.t); and the gate of errors made where contacts sit at Gauss points.
#include <cstddef>
#include <string>
#include <vector>

#include "rodvv/harness/gate.hpp"
#include "rodvv/solvers/superhelix/frictional_statics.hpp"

namespace rodvv::harness::inverse_cases {

struct FrictionLaw {
  std::size_t loaded = 0;      // contacts with r_N > 1e-9 of the largest
  std::size_t sliding = 0;     // loaded, |r_T| >= (1 - 1e-9) mu r_N and a slip > 0
  double cone_violation = 0.0;  // max (|r_T| - mu r_N)_+ / max r_N
  double slip_alignment = 0.0;  // max over sliding contacts of 1 + r_T.u_T / (|r_T| |u_T|): 0 when opposed
};

FrictionLaw friction_law(const std::vector<solvers::superhelix::FrictionalContact>& contacts, double mu);

// With friction H is no longer constant, but its change is predicted (seed slides 002: H' = -f.t, f the
// contact force per length): across a point force f at s_g, H(s_g+) - H(s_g-) = -f.t. Measured on the
// solution struct (superhelix/solution.hpp) built with the equilibrium's contact forces as dead point loads,
// so that its n(s) carries them, H the flattened form (invariants/noether3d.hpp), over its stations:
//   balance    max |H(s) + sum_{s_g < s} f_g.t_g - H(s_0)| / scale (a force at a station counts half there);
//   deviation  max |H(s) - H(s_0)| / scale, the same without the jumps: frictionless forces are normal to the
//              obstacle, and to the rod where it touches, so H is constant (a force off the rod's tangent, as
//              at a point contact between Gauss points, shows here and not in the balance).
struct NoetherAlongContacts {
  double balance = 0.0, deviation = 0.0;
};
NoetherAlongContacts noether_along_contacts(const solvers::superhelix::RodModel& model,
                                            const solvers::superhelix::FrictionalStaticResult& state, double scale);

// The gate of an error whose contacts sit at Gauss points: where a contact region starts or ends within an
// element its force is off the true point by O(h), so the error is first order with a constant that jumps as
// the ends move within elements. No order is fitted; the error is held under `constant` h (h = 1 / N) at every
// level, the constant twice the largest e_i N_i measured at the default levels (a measured bound).
GateSpec contact_envelope_gate(const std::string& metric, double constant);

}  // namespace rodvv::harness::inverse_cases
