#pragma once
// A semi-implicit Euler step of the Super-Helix or super-clothoid dynamics that produced a non-finite
// state has diverged (a step beyond the scheme's stability limit, or a state that blew up): that is a
// numerical failure of the step (rodvv::SolverError naming the method, the time, the step size and
// the quantity), never bad input - the next step's validation of its input would otherwise report it
// as an invalid parameter 'state.q' (issue 14, class 4).
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"

namespace rodvv::solvers::superhelix::detail {

inline void require_finite_step(const std::string& method, const DynamicState& from, const DynamicState& next,
                                double h) {
  const bool q_finite = next.q.allFinite(), qdot_finite = next.qdot.allFinite();
  if (q_finite && qdot_finite) {
    check_time_budget(method, 0, std::numeric_limits<double>::quiet_NaN());  // every step: no run hangs
    return;
  }
  const std::string what = !qdot_finite ? "the generalized velocities qdot" : "the generalized coordinates q";
  throw SolverError(method,
                    "the step from t = " + format_value(from.time) + " with h = " + format_value(h) + " made " +
                        what + " non-finite (the state diverged: h beyond the stability limit, or a blow-up)",
                    0, std::numeric_limits<double>::quiet_NaN());
}

}  // namespace rodvv::solvers::superhelix::detail
