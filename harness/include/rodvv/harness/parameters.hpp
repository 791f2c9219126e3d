#pragma once
// Case parameters by name: lookup, and `--set NAME=VALUE` overrides validated against the
// parameter's allowed range (InputError naming the parameter, the value and the range).
#include <string>
#include <string_view>
#include <vector>

#include "rodvv/harness/case_info.hpp"

namespace rodvv::harness {

using Parameters = std::vector<Parameter>;

Parameter make_parameter(std::string name, double value, double min, double max, bool min_open,
                         bool max_open, std::string unit, std::string description);

// Throws InputError naming the known parameters when `name` is unknown.
double parameter_value(const Parameters& parameters, std::string_view name);

// Validates `value` against the parameter's range and stores it.
void set_parameter(Parameters& parameters, std::string_view name, double value);

// Parses "NAME=VALUE" (VALUE a finite decimal number) and applies it.
void apply_assignment(Parameters& parameters, std::string_view assignment);

// "(0, 180)", "[1, inf)": the allowed range in interval notation.
std::string describe_range(const Parameter& parameter);
// What --set accepts: "a finite number in (0, 180)", "a whole number in [2, 64]", "0 (off) or 1 (on)".
std::string describe_allowed(const Parameter& parameter);

// A whole-number parameter in [min, max] (a count), and an on/off switch (0 or 1).
Parameter integer_parameter(std::string name, double value, double min, double max, std::string description);
Parameter switch_parameter(std::string name, bool value, std::string description);

}  // namespace rodvv::harness
