#pragma once
// The contract every fuzz target checks: whatever the bytes, a reader either accepts them or throws
// rodvv::InputError (exit 2 in the CLI). Any other exception is an internal error (exit 3 in the
// CLI) and aborts, so that libFuzzer (and the replay runner) reports the input as a crash; memory
// and undefined-behaviour errors are caught by the sanitizers the targets are built with.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "rodvv/common/errors.hpp"

namespace rodvv::fuzz {

template <class Body>
void expect_read_or_input_error(const char* target, Body&& body) {
  try {
    body();
  } catch (const InputError& error) {
    // A refusal must say something: an empty message would reach the user as "rodvv: ".
    if (std::string(error.what()).empty()) {
      std::fprintf(stderr, "%s: InputError with an empty message\n", target);
      std::abort();
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: not an InputError: %s\n", target, error.what());
    std::abort();
  }
}

}  // namespace rodvv::fuzz
