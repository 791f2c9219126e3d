#include "rodvv/harness/parameters.hpp"

#include <charconv>
#include <cmath>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::harness {

Parameter make_parameter(std::string name, double value, double min, double max, bool min_open,
                         bool max_open, std::string unit, std::string description) {
  return Parameter{std::move(name), value, min, max, min_open, max_open, std::move(unit),
                   std::move(description)};
}

namespace {

std::string known_names(const Parameters& parameters) {
  std::string names;
  for (const auto& parameter : parameters) names += (names.empty() ? "" : ", ") + parameter.name;
  return names.empty() ? "(none)" : names;
}

std::size_t index_of(const Parameters& parameters, std::string_view name) {
  for (std::size_t i = 0; i < parameters.size(); ++i)
    if (parameters[i].name == name) return i;
  throw InputError(std::string(name), "unknown parameter '" + std::string(name) +
                                          "'; this case has: " + known_names(parameters));
}

}  // namespace

double parameter_value(const Parameters& parameters, std::string_view name) {
  return parameters[index_of(parameters, name)].value;
}

std::string describe_range(const Parameter& parameter) {
  return std::string(parameter.min_open ? "(" : "[") + format_value(parameter.min) + ", " +
         format_value(parameter.max) + (parameter.max_open ? ")" : "]");
}

std::string describe_allowed(const Parameter& parameter) {
  switch (parameter.kind) {
    case ParameterKind::Integer: return "a whole number in " + describe_range(parameter);
    case ParameterKind::Boolean: return "0 (off) or 1 (on)";
    case ParameterKind::Real: break;
  }
  return "a finite number in " + describe_range(parameter);
}

Parameter integer_parameter(std::string name, double value, double min, double max, std::string description) {
  Parameter p = make_parameter(std::move(name), value, min, max, false, false, "", std::move(description));
  p.kind = ParameterKind::Integer;
  return p;
}

Parameter switch_parameter(std::string name, bool value, std::string description) {
  Parameter p = make_parameter(std::move(name), value ? 1.0 : 0.0, 0.0, 1.0, false, false, "", std::move(description));
  p.kind = ParameterKind::Boolean;
  return p;
}

void set_parameter(Parameters& parameters, std::string_view name, double value) {
  Parameter& parameter = parameters[index_of(parameters, name)];
  const bool above_min = parameter.min_open ? value > parameter.min : value >= parameter.min;
  const bool below_max = parameter.max_open ? value < parameter.max : value <= parameter.max;
  const bool whole = value == std::floor(value);
  const bool of_kind = parameter.kind == ParameterKind::Real || (parameter.kind == ParameterKind::Integer && whole) ||
                       (parameter.kind == ParameterKind::Boolean && (value == 0.0 || value == 1.0));
  if (!std::isfinite(value) || !above_min || !below_max || !of_kind)
    throw InputError(parameter.name, "invalid parameter '" + parameter.name + "' = " + format_value(value) +
                                         ": must be " + describe_allowed(parameter));
  parameter.value = value;
}

void apply_assignment(Parameters& parameters, std::string_view assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string_view::npos || equals == 0)
    throw InputError("--set", "malformed --set '" + std::string(assignment) +
                                  "': expected NAME=VALUE, e.g. theta0_deg=45");
  const std::string_view name = assignment.substr(0, equals);
  const Parameter& parameter = parameters[index_of(parameters, name)];  // unknown names first, with the list
  std::string_view text = assignment.substr(equals + 1);
  // std::from_chars takes no '+' sign; a user writing +45 means 45.
  const std::string_view digits = text.size() > 1 && text[0] == '+' && text[1] != '-' ? text.substr(1) : text;
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range && end == digits.data() + digits.size())
    throw InputError(std::string(name), "invalid value in --set '" + std::string(assignment) + "': '" +
                                            std::string(text) + "' is out of the range of a double; '" +
                                            parameter.name + "' must be " + describe_allowed(parameter));
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
    throw InputError(std::string(name), "malformed value in --set '" + std::string(assignment) + "': '" +
                                            std::string(text) + "' is not a number; '" + parameter.name +
                                            "' must be " + describe_allowed(parameter));
  set_parameter(parameters, name, value);
}

}  // namespace rodvv::harness
