#pragma once
// Number formatting shared by the renderers. Full precision lives in results.json; tables show
// compact forms. A non-finite value or an absent optional prints as "n/a" (never "nan"/"inf").
#include <optional>
#include <string>

namespace rodvv::reports {

inline constexpr const char* kNotAvailable = "n/a";

std::string format_shortest(double value);                   // shortest round-trip, "0.1", "64"
std::string format_scientific(double value, int significant);  // "1.23e-05"
std::string format_general(double value, int significant);     // %g: "6.28319", "1.5e-07"
std::string format_fixed(double value, int decimals);          // "2.01"

std::string format_scientific(const std::optional<double>& value, int significant);
std::string format_general(const std::optional<double>& value, int significant);
std::string format_fixed(const std::optional<double>& value, int decimals);

// The display conventions of the report tables.
std::string format_error(const std::optional<double>& value);    // 3 significant, scientific
std::string format_value(const std::optional<double>& value);    // 6 significant, %g
std::string format_order(const std::optional<double>& value);    // 2 decimals
std::string format_seconds(double seconds);                       // "0.0123 s"

}  // namespace rodvv::reports
