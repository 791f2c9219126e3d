#include "rodvv/common/validation.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"

namespace rodvv {

std::string format_value(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

namespace {
[[noreturn]] void fail(std::string_view name, const std::string& value, const std::string& range) {
  throw InputError(std::string(name),
                   "invalid parameter '" + std::string(name) + "' = " + value + ": must be " + range);
}
[[noreturn]] void fail(std::string_view name, double value, const std::string& range) {
  fail(name, format_value(value), range);
}
}  // namespace

void require_finite_vector(std::string_view name, const Vec3& value) {
  for (int i = 0; i < 3; ++i) require_finite(std::string(name) + "[" + std::to_string(i) + "]", value[i]);
}

void require_finite(std::string_view name, double value) {
  if (!std::isfinite(value)) fail(name, value, "a finite number");
}

void require_positive(std::string_view name, double value) {
  if (!std::isfinite(value) || !(value > 0.0)) fail(name, value, "a finite number > 0");
}

void require_non_negative(std::string_view name, double value) {
  if (!std::isfinite(value) || !(value >= 0.0)) fail(name, value, "a finite number >= 0");
}

void require_open_interval(std::string_view name, double value, double lo, double hi) {
  if (!std::isfinite(value) || !(value > lo && value < hi))
    fail(name, value, "a finite number in the open interval (" + format_value(lo) + ", " +
                          format_value(hi) + ")");
}

void require_closed_interval(std::string_view name, double value, double lo, double hi) {
  if (!std::isfinite(value) || !(value >= lo && value <= hi))
    fail(name, value, "a finite number in the closed interval [" + format_value(lo) + ", " +
                          format_value(hi) + "]");
}

void require_greater(std::string_view name, double value, double bound) {
  if (!std::isfinite(value) || !(value > bound))
    fail(name, value, "a finite number > " + format_value(bound));
}

void require_at_least(std::string_view name, std::size_t value, std::size_t minimum) {
  if (value < minimum) fail(name, std::to_string(value), "an integer >= " + std::to_string(minimum));
}

}  // namespace rodvv
