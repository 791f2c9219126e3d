#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

const char* to_string(MetricKind kind) {
  switch (kind) {
    case MetricKind::Error: return "error";
    case MetricKind::Invariant: return "invariant";
    case MetricKind::Diagnostic: return "diagnostic";
  }
  return "unknown";
}

const char* to_string(GateKind kind) {
  switch (kind) {
    case GateKind::Order: return "order";
    case GateKind::UpperBound: return "upper-bound";
    case GateKind::LowerBound: return "lower-bound";
    case GateKind::Regression: return "regression";
  }
  return "unknown";
}

const char* to_string(ResolutionScale scale) {
  switch (scale) {
    case ResolutionScale::StepSize: return "step-size";
    case ResolutionScale::Count: return "count";
  }
  return "unknown";
}

}  // namespace rodvv::harness
