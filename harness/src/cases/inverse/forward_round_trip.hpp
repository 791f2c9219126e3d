#pragma once
// The round trip of the inverse cases: the forward statics of the recovered rest model, started from
// the target q perturbed by 1 % of |q|_inf (entry i moved by 0.01 |q|_inf sin(1.3 i + 0.2)), must
// come back to q. Newton (exact Jacobian, line search) stops at its round-off floor; the recovered q0
// holds q to round-off in F; both map to q through J^-1. Reported in those units:
//   round_trip_error     = |q_found - q|_inf / (eps |J^-1|_inf scale),
//   scale = max(|K q|_inf, |F_weight|_inf, |F_contacts|_inf) (each load on its own: they may cancel),
//   equilibrium_residual = |r(q)|_inf / (eps scale)  (the forward residual at q),
// and |q_found - q|_inf / |q|_inf. From a perturbation, not from the rest shape under load stepping:
// a heavy rod's continuation from its rest shape may reach another equilibrium (measured on
// round-trip-3d at g = 1e12), which says nothing about whether q0 holds q.
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/harness/case.hpp"
#include "rodvv/harness/gate.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::harness::inverse_cases {

struct RoundTrip {
  double error = 0.0;                 // round_trip_error
  double relative_error = 0.0;        // round_trip_error_relative
  double equilibrium_residual = 0.0;  // equilibrium_residual
};
RoundTrip forward_round_trip(const solvers::superhelix::RodModel& rest, const VecX& q);
void add_round_trip_metrics(LevelOutput& out, const RoundTrip& round_trip);
void add_round_trip_metrics(LevelOutput& out, const solvers::superhelix::RodModel& rest, const VecX& q);

// The specs of those three metrics and their two gates (64 and 16: a multiple of eps, for the O(N)
// sums in F and the LU of J; a subtraction, a division and a product per entry), shared by every
// inverse case.
void add_round_trip_specs(std::vector<MetricSpec>& metrics, std::vector<GateSpec>& gates);
// The regression tolerances of the round-trip metrics, which measure round-off (Case::golden_absolute).
void hold_round_trip_round_off(Case& c);

}  // namespace rodvv::harness::inverse_cases
