#pragma once
// The gate table that `rodvv run` and `rodvv sweep` print on stdout.
#include <string>
#include <vector>

#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::apps {

std::string render_gate_table(const std::vector<harness::SweepResult>& results);
// Levels x metrics table of one sweep, with the fitted orders (for `rodvv sweep`).
std::string render_level_table(const harness::SweepResult& result);

}  // namespace rodvv::apps
