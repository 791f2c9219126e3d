#include "rodvv/common/errors.hpp"

#include <sstream>

namespace rodvv {

InputError::InputError(std::string parameter, const std::string& message)
    : std::invalid_argument(message), parameter_(std::move(parameter)) {}

namespace {
std::string solver_message(const std::string& method, const std::string& message,
                           std::size_t iterations, double residual) {
  std::ostringstream out;
  out.precision(6);
  out << method << ": " << message << " (after " << iterations << " iterations, residual "
      << residual << ")";
  return out.str();
}
}  // namespace

SolverError::SolverError(const std::string& method, const std::string& message,
                         std::size_t iterations, double residual)
    : std::runtime_error(solver_message(method, message, iterations, residual)),
      method_(method),
      message_(message),
      iterations_(iterations),
      residual_(residual) {}

}  // namespace rodvv
