#pragma once
// Private helpers of rodvv_references: checked calls into GSL.
// GSL's default error handler calls abort() on a domain error (PHYSICS.md §2.5, practical notes). We
// switch it off once per process and turn every non-success status into rodvv::SolverError, so that
// a library status never terminates the caller.
#include <string_view>

namespace rodvv::references::detail {

// Switches GSL's abort handler off; idempotent and thread-safe (function-local static).
void gsl_handler_off();

// Throws rodvv::SolverError naming `function` and gsl_strerror(status) when status != GSL_SUCCESS.
void check_gsl(int status, std::string_view function);

}  // namespace rodvv::references::detail
