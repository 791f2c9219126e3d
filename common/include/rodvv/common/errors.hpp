#pragma once
// The two error kinds of rodvv (ARCHITECTURE.md, convention 4).
//  - InputError: a value supplied by the user or a caller is outside its allowed range. The message
//    names the parameter, the value and the range. The CLI maps it to exit code 2.
//  - SolverError: a numerical method failed (no convergence, root not bracketed, a library status
//    other than success). The message carries the iteration count and the residual.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace rodvv {

class InputError : public std::invalid_argument {
 public:
  InputError(std::string parameter, const std::string& message);
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

class SolverError : public std::runtime_error {
 public:
  SolverError(const std::string& method, const std::string& message, std::size_t iterations,
              double residual);
  const std::string& method() const noexcept { return method_; }
  // The failure alone, without the method, iterations and residual that what() adds.
  const std::string& message() const noexcept { return message_; }
  std::size_t iterations() const noexcept { return iterations_; }
  double residual() const noexcept { return residual_; }

 private:
  std::string method_;
  std::string message_;
  std::size_t iterations_;
  double residual_;
};

}  // namespace rodvv
