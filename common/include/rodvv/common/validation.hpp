#pragma once
// Input validation at the boundary of every reference, solver and case (ARCHITECTURE.md, convention 4).
// Each check throws rodvv::InputError whose message reads
//   invalid parameter 'omega' = -1: must be a finite number > 0
// so that a user sees which parameter was wrong, what it was, and what is allowed.
#include <cstddef>
#include <string_view>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv {

void require_finite(std::string_view name, double value);
void require_positive(std::string_view name, double value);      // finite and > 0
void require_non_negative(std::string_view name, double value);  // finite and >= 0
void require_open_interval(std::string_view name, double value, double lo, double hi);    // lo < v < hi
void require_closed_interval(std::string_view name, double value, double lo, double hi);  // lo <= v <= hi
void require_greater(std::string_view name, double value, double bound);                  // v > bound
void require_at_least(std::string_view name, std::size_t value, std::size_t minimum);
// Each component finite; the error names it as name[i].
void require_finite_vector(std::string_view name, const Vec3& value);

// Formats a double with the shortest round-tripping precision used in all error messages.
std::string format_value(double value);

}  // namespace rodvv
