#pragma once
// The goldens file of the regression gates (harness/golden.hpp): JSON, one entry per case, a value
// per line so that a `rodvv bless` shows in a diff as the values that moved.
//   {"format": "rodvv goldens", "version": 1,
//    "cases": {"<case>": [{"level": 0.1, "failed": false,
//                          "metrics": {"<metric>": {"computed": x, "reference": r, "error": e,
//                                                   "scale": s}}}]}}
// Absent optionals are left out; non-finite numbers are written as "nan", "inf", "-inf".
#include <filesystem>

#include "rodvv/harness/golden.hpp"

namespace rodvv::reports {

// InputError (parameter "goldens") naming the file and the field on anything malformed.
harness::Goldens read_goldens(const std::filesystem::path& path);
void write_goldens(const std::filesystem::path& path, const harness::Goldens& goldens);

}  // namespace rodvv::reports
