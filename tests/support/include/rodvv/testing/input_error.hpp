#pragma once
// What a bad-input test asks of a call: the parameter its InputError names.
#include <string>

#include "rodvv/common/errors.hpp"

namespace rodvv::testing {

// The parameter named by the InputError f throws, or "<no InputError>" if it throws none.
template <class F>
std::string input_error_parameter_of(F&& f) {
  try {
    f();
  } catch (const rodvv::InputError& e) {
    return e.parameter();
  }
  return "<no InputError>";
}

}  // namespace rodvv::testing
