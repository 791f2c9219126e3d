// libFuzzer target: the values a user types on the command line for a case: `--set NAME=VALUE`
// (apply_assignment, then the case's cross-parameter check, as `rodvv run` does before any level)
// and `--levels` (validate_levels). The first two bytes choose one of the registered cases; each
// following line is an assignment, or, after '@', levels as raw doubles (8 bytes each, so that
// NaN, infinities, subnormals and negative zero reach validate_levels as CLI11 could hand them over).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "fuzz_contract.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const auto& cases = rodvv::harness::default_registry().cases();
  const rodvv::harness::Case& c = cases[(std::size_t(data[0]) << 8 | data[1]) % cases.size()];
  std::string_view rest(reinterpret_cast<const char*>(data + 2), size - 2);
  rodvv::fuzz::expect_read_or_input_error("fuzz_cli_values", [&] {
    if (!rest.empty() && rest.front() == '@') {
      std::vector<double> levels((rest.size() - 1) / sizeof(double));
      if (!levels.empty()) std::memcpy(levels.data(), rest.data() + 1, levels.size() * sizeof(double));
      rodvv::harness::validate_levels(c, levels);
      return;
    }
    rodvv::harness::Parameters parameters = c.info.parameters;
    while (!rest.empty()) {
      const auto end = rest.find('\n');
      rodvv::harness::apply_assignment(parameters, rest.substr(0, end));
      rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    }
    if (c.check_parameters) c.check_parameters(parameters);
  });
  return 0;
}
