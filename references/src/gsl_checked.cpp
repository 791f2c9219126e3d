#include "gsl_checked.hpp"

#include <gsl/gsl_errno.h>

#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"

namespace rodvv::references::detail {

void gsl_handler_off() {
  // The one process-wide effect of this library: a function-local static runs exactly once.
  static const bool switched_off = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)switched_off;
}

void check_gsl(int status, std::string_view function) {
  if (status == GSL_SUCCESS) return;
  throw SolverError(std::string(function),
                    std::string(function) + " returned status " + std::to_string(status) + " (" +
                        gsl_strerror(status) + ")",
                    0, std::numeric_limits<double>::quiet_NaN());
}

}  // namespace rodvv::references::detail
