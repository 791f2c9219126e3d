#pragma once
// A case whose "solver" has a known error model e = C h^p (+ optional failure), for testing the
// sweep runner and the gates without any real solver.
#include <cmath>
#include <stdexcept>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/case.hpp"

namespace rodvv::testing {

inline harness::Case synthetic_case(double true_order, double c = 1.0) {
  harness::Case result;
  auto& info = result.info;
  info.name = "synthetic/power-law";
  info.family = "synthetic";
  info.title = "e = C h^p";
  info.parameters = {harness::make_parameter("c", c, 0.0, 1e9, true, false, "", "error constant")};
  info.resolution = {"dt", "step", harness::ResolutionScale::StepSize, {0.1, 0.05, 0.025, 0.0125}, {}};
  info.metrics = {{"error", harness::MetricKind::Error, "", "C h^p", false, true_order},
                  {"value", harness::MetricKind::Error, "", "1 + C h^p", true, true_order}};
  result.run_level = [true_order](const harness::Parameters& parameters, double h) {
    const double error = harness::parameter_value(parameters, "c") * std::pow(h, true_order);
    harness::LevelOutput output;
    output.metrics["error"] = {error, 0.0, error};
    output.metrics["value"] = {1.0 + error, 1.0, error};
    return output;
  };
  return result;
}

}  // namespace rodvv::testing
