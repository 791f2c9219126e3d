#include "scales.hpp"

#include <cmath>

#include <fmt/format.h>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::harness::pendulum_cases {

namespace {
constexpr double kDefaultLength = 1.3;
constexpr double kDefaultGravity = 2.7 * 2.7 * kDefaultLength;  // omega = 2.7
}  // namespace

Parameters frequency_parameters(bool unit_scale) {
  Parameter g = make_parameter("g", kDefaultGravity, 0.0, 1e12, true, false, "length/time^2", "gravity");
  Parameter l = make_parameter("length", kDefaultLength, 0.0, 1e6, true, false, "length",
                               "pendulum length (omega = sqrt(g/l))");
  g.unit_scale = l.unit_scale = unit_scale;
  return {g, l};
}

double natural_frequency(const Parameters& parameters) {
  return std::sqrt(parameter_value(parameters, "g") / parameter_value(parameters, "length"));
}

cases::Window frequency_group_window(std::string name, int power, double low, double high, std::string why) {
  const std::string group = power == 1 ? "omega " + name : power == -1 ? name + " / omega"
                                                                        : fmt::format("{} omega^{}", name, power);
  const std::string range = std::isinf(high) ? fmt::format(">= {:g}", low) : fmt::format("in [{:g}, {:g}]", low, high);
  return {fmt::format("{} {}, omega = sqrt(g/l) ({})", group, range, why), [=](const Parameters& p) {
            const double omega = natural_frequency(p), value = parameter_value(p, name);
            const double grouped = value * std::pow(omega, power);
            if (!cases::inside(grouped, low, high))
              throw InputError(name, fmt::format("invalid parameter '{}' = {}: {} = {} (omega = sqrt(g/l) = {}) must be "
                                                 "{} ({})",
                                                 name, format_value(value), group, format_value(grouped),
                                                 format_value(omega), range, why));
          }};
}

}  // namespace rodvv::harness::pendulum_cases
