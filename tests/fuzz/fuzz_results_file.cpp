// libFuzzer target: a results file (`rodvv report --from DIR`, `rodvv run --json F`), through
// report_from_json_text, the reader behind read_report_file; an accepted file must also merge and
// serialise again (what `report --from` does next).
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "fuzz_contract.hpp"
#include "rodvv/reports/json_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  rodvv::fuzz::expect_read_or_input_error("fuzz_results_file", [&] {
    std::vector<rodvv::reports::ValidationReport> reports;
    reports.push_back(rodvv::reports::report_from_json_text(text, "fuzz.json"));
    const auto merged = rodvv::reports::merge_reports(std::move(reports));
    (void)rodvv::reports::to_json(merged).dump();
  });
  return 0;
}
