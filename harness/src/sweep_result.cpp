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
    case ResolutionScale::Parameter: return "parameter";
  }
  return "unknown";
}

const MetricSpec* find_metric_spec(const CaseInfo& info, const std::string& name) {
  for (const auto& spec : info.metrics)
    if (spec.name == name) return &spec;
  return nullptr;
}

bool at_default_parameters(const CaseInfo& info, const std::vector<Parameter>& parameters, bool unit_scales_free) {
  if (parameters.size() != info.parameters.size()) return false;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const Parameter& given = parameters[i];
    const Parameter& defaults = info.parameters[i];
    if (given.name != defaults.name) return false;
    if (given.value != defaults.value && !(unit_scales_free && defaults.unit_scale)) return false;
  }
  return true;
}

}  // namespace rodvv::harness
