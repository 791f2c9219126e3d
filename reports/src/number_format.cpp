#include "rodvv/reports/number_format.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace rodvv::reports {

std::string format_shortest(double value) {
  if (!std::isfinite(value)) return kNotAvailable;
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string format_scientific(double value, int significant) {
  if (!std::isfinite(value)) return kNotAvailable;
  return fmt::format("{:.{}e}", value, significant > 1 ? significant - 1 : 0);
}

std::string format_general(double value, int significant) {
  if (!std::isfinite(value)) return kNotAvailable;
  return fmt::format("{:.{}g}", value, significant > 0 ? significant : 1);
}

std::string format_fixed(double value, int decimals) {
  if (!std::isfinite(value)) return kNotAvailable;
  return fmt::format("{:.{}f}", value, decimals > 0 ? decimals : 0);
}

std::string format_scientific(const std::optional<double>& value, int significant) {
  return value ? format_scientific(*value, significant) : kNotAvailable;
}

std::string format_general(const std::optional<double>& value, int significant) {
  return value ? format_general(*value, significant) : kNotAvailable;
}

std::string format_fixed(const std::optional<double>& value, int decimals) {
  return value ? format_fixed(*value, decimals) : kNotAvailable;
}

std::string format_error(const std::optional<double>& value) { return format_scientific(value, 3); }
std::string format_value(const std::optional<double>& value) { return format_general(value, 6); }
std::string format_order(const std::optional<double>& value) { return format_fixed(value, 2); }

std::string format_seconds(double seconds) {
  if (!std::isfinite(seconds)) return kNotAvailable;
  return format_general(seconds, 3) + " s";
}

}  // namespace rodvv::reports
